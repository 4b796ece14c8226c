// symrep/output/plot.cpp -- gnuplot driver (see plot.h).
#include "output/plot.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "core/error.h"

extern char** environ;

namespace symrep::output {

namespace fs = std::filesystem;

namespace {

/// A gnuplot single-quoted string: no escapes inside except '' for a quote.
std::string quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) {
        if (c == '\'') out += "''";
        else if (c == '\n' || c == '\r') out += ' ';
        else out += c;
    }
    return out + "'";
}

std::string slurp(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::ostringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

/// A temporary directory removed when this goes out of scope.
struct temp_dir {
    fs::path path;
    explicit temp_dir(const std::string& who) {
        const char* base = std::getenv("TMPDIR");
        std::string templ = std::string(base && *base ? base : "/tmp") + "/symrep_plot_XXXXXX";
        if (!mkdtemp(templ.data()))
            throw error(who + ": cannot create a temporary directory in " + templ + ": " + std::strerror(errno));
        path = templ;
    }
    ~temp_dir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

void write_number(std::ostream& os, double x) {
    if (std::isfinite(x)) os << x;
    else os << "NaN";
}

}  // namespace

std::string gnuplot_program() {
    const char* p = std::getenv("SYMREP_GNUPLOT");
    return p && *p ? std::string(p) : std::string("gnuplot");
}

void write_plot(const plot_spec& spec, const std::string& path, const std::string& who) {
    // the terminal from the extension
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext != ".png" && ext != ".svg")
        throw error(who + ": the file name '" + path + "' must end in .png or .svg (the extension chooses the format)");
    if (fs::path(path).filename().string() == ext || path.find('\0') != std::string::npos)
        throw error(who + ": '" + path + "' is not a file name");
    const std::size_t n = spec.three_d ? (spec.columns.empty() ? 0 : spec.columns[0].size()) : spec.t.size();
    if (spec.three_d && spec.columns.size() != 3) throw error(who + ": internal: a 3-D curve needs 3 columns");
    for (const auto& c : spec.columns)
        if (c.size() != n) throw error(who + ": internal: columns of different lengths");
    bool any_finite = false;
    double zmin = INFINITY, zmax = -INFINITY, xyspan = 0;
    for (std::size_t i = 0; i < n; ++i) {
        bool row = true;
        for (const auto& c : spec.columns) row = row && std::isfinite(c[i]);
        if (!spec.three_d) {
            for (const auto& c : spec.columns) any_finite = any_finite || std::isfinite(c[i]);
        } else if (row) {
            any_finite = true;
            zmin = std::min(zmin, spec.columns[2][i]);
            zmax = std::max(zmax, spec.columns[2][i]);
            xyspan = std::max({xyspan, std::abs(spec.columns[0][i]), std::abs(spec.columns[1][i])});
        }
    }
    for (const auto& ps : spec.points) {
        if (ps.x.size() != ps.y.size()) throw error(who + ": internal: a point set with different lengths");
        for (std::size_t i = 0; i < ps.x.size(); ++i)
            any_finite = any_finite || (std::isfinite(ps.x[i]) && std::isfinite(ps.y[i]));
    }
    if (!any_finite) throw error(who + ": no sample is a finite number (nothing to draw)");

    temp_dir tmp(who);
    const fs::path data = tmp.path / "data.dat", script = tmp.path / "plot.gp", out = tmp.path / ("out" + ext),
                   log = tmp.path / "gnuplot.log";
    {
        std::ofstream d(data);
        d << std::setprecision(12);
        for (std::size_t i = 0; i < n; ++i) {
            if (!spec.three_d) write_number(d, spec.t[i]), d << ' ';
            for (std::size_t k = 0; k < spec.columns.size(); ++k) {
                if (k) d << ' ';
                write_number(d, spec.columns[k][i]);
            }
            d << '\n';
        }
        if (!d) throw error(who + ": cannot write the temporary data file " + data.string());
        for (std::size_t k = 0; k < spec.points.size(); ++k) {
            std::ofstream pd(tmp.path / ("points" + std::to_string(k) + ".dat"));
            pd << std::setprecision(12);
            for (std::size_t i = 0; i < spec.points[k].x.size(); ++i) {
                write_number(pd, spec.points[k].x[i]);
                pd << ' ';
                write_number(pd, spec.points[k].y[i]);
                pd << '\n';
            }
            if (!pd) throw error(who + ": cannot write the temporary data file of the points");
        }
    }
    {
        std::ofstream g(script);
        g << "set encoding utf8\n";
        if (ext == ".png")
            g << "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n"
                 "  set terminal pngcairo size 900,700 enhanced font 'Sans,11' background rgb 'white'\n"
                 "} else {\n  set terminal png size 900,700 background rgb 'white'\n}\n";
        else
            g << "set terminal svg size 900,700 font 'Sans,11' background rgb 'white'\n";
        g << "set output " << quote(out.string()) << "\n";
        g << "set title " << quote(spec.title) << " noenhanced\n";
        g << "set xlabel " << quote(spec.xlabel) << " noenhanced\n";
        g << "set ylabel " << quote(spec.ylabel) << " noenhanced\n";
        g << "set grid\n";
        const std::string df = quote(data.string());
        if (!spec.three_d) {
            if (spec.columns.size() + spec.points.size() > 1) g << "set key below\n";
            else g << "unset key\n";
            g << "plot ";
            for (std::size_t k = 0; k < spec.points.size(); ++k) {  // the marks first, the curves over them
                if (k) g << ", \\\n     ";
                g << quote((tmp.path / ("points" + std::to_string(k) + ".dat")).string())
                  << " using 1:2 with points pointtype 7 pointsize 0.5 title " << quote(spec.points[k].name)
                  << " noenhanced";
            }
            for (std::size_t k = 0; k < spec.columns.size(); ++k) {
                if (k || !spec.points.empty()) g << ", \\\n     ";
                g << df << " using 1:" << k + 2 << " with lines linewidth 1.5";
                if (k < spec.names.size()) g << " title " << quote(spec.names[k]) << " noenhanced";
                else g << " notitle";
            }
            g << "\n";
        } else {
            const bool flat = zmax - zmin <= 1e-9 * std::max(xyspan, 1e-300);
            if (flat) {
                // a curve in a plane z = const: drawn in that plane, x and y at equal scales
                std::ostringstream zc;
                zc << std::setprecision(6) << zmin;
                g << "set size ratio -1\nset key below\n";
                g << "plot " << df << " using 1:2 with lines linewidth 1.2 title "
                  << quote("curve (in the plane " + spec.zlabel + " = " + zc.str() + ")") << " noenhanced, \\\n     "
                  << df << " every ::0::0 using 1:2 with points pointtype 7 pointsize 1.3 title 'start'\n";
            } else {
                g << "set zlabel " << quote(spec.zlabel) << " noenhanced\n";
                g << "set key below\n";
                g << "set view 60, 30\nset view equal xyz\nset xyplane relative 0\n";
                g << "splot " << df << " using 1:2:3 with lines linewidth 1.2 title 'curve', \\\n      " << df
                  << " every ::0::0 using 1:2:3 with points pointtype 7 pointsize 1.3 title 'start'\n";
            }
        }
        g << "unset output\n";
        if (!g) throw error(who + ": cannot write the temporary gnuplot script " + script.string());
    }

    // run gnuplot: no shell, stdin from /dev/null, its output into the log
    const std::string prog = gnuplot_program();
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    posix_spawn_file_actions_adddup2(&fa, 1, 2);
    std::string a0 = prog, a1 = script.string();
    char* argv[] = {a0.data(), a1.data(), nullptr};
    pid_t pid = 0;
    const int rc = posix_spawnp(&pid, prog.c_str(), &fa, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    if (rc != 0)
        throw error(who + ": gnuplot is needed to draw plots, but '" + prog + "' cannot be run (" +
                    std::strerror(rc) + "): install it (Debian/Ubuntu: apt-get install gnuplot-nox) or set " +
                    "SYMREP_GNUPLOT to the gnuplot program");
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    std::string msg = slurp(log);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !fs::exists(out) || fs::file_size(out) == 0) {
        if (msg.size() > 600) msg = "..." + msg.substr(msg.size() - 600);
        throw error(who + ": gnuplot ('" + prog + "') failed to draw the picture" +
                    (msg.empty() ? std::string() : ": " + msg));
    }

    // copy to the destination unless it already holds exactly this picture
    const std::string picture = slurp(out);
    std::error_code ec;
    if (fs::exists(path, ec) && slurp(path) == picture) return;
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    if (f) f.write(picture.data(), std::streamsize(picture.size()));
    if (!f) throw error(who + ": cannot write the picture to '" + path + "': " + std::strerror(errno));
}

}  // namespace symrep::output
