// symrep/output/plot.cpp -- gnuplot driver (see plot.h).
#include "symrep/output/plot.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include <Eigen/Dense>

#include "symrep/core/error.h"

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

namespace {

std::string number_text(double x, int digits = 6) {
    std::ostringstream os;
    os << std::setprecision(digits) << (x == 0 ? 0.0 : x);  // no "-0"
    return os.str();
}

/// An axis as drawn: the data are written as (value - offset) / 10^exp, the ticks run from
/// lo to hi by step (lo and hi multiples of step), the label says the offset and scale.
struct axis {
    std::string name;          ///< what the axis shows ("x", "dz/dt", "t", ...)
    double min = INFINITY, max = -INFINITY;  ///< the finite values
    double offset = 0;
    int exp = 0;
    double lo = 0, hi = 1;                    ///< the range drawn
    double step = 1, tick_lo = 0, tick_hi = 1;  ///< the ticks: tick_lo, tick_lo + step, ..., tick_hi
    std::string note;          ///< e.g. "not to scale with x"

    void see(double x) {
        if (std::isfinite(x)) min = std::min(min, x), max = std::max(max, x);
    }
    double span() const { return max > min ? max - min : 0; }
    double map(double x) const { return (x - offset) / std::pow(10.0, exp); }
    std::string label() const {
        std::string l = name;
        if (offset != 0) l += (offset > 0 ? " - " : " + ") + number_text(std::abs(offset));
        if (exp != 0) l += " (x 1e" + std::to_string(exp) + ")";
        if (!note.empty()) l += " (" + note + ")";
        return l;
    }
};

/// The offset (when the values crowd around one far from 0) and the power of ten
/// (a multiple of 3, when the values are tiny or huge) of an axis.
void choose_scale(axis& a) {
    if (!(a.min <= a.max)) a.min = 0, a.max = 1;  // no finite value (a curve in another column)
    const double m = std::max(std::abs(a.min), std::abs(a.max)), s = a.span();
    a.offset = 0;
    if (s > 0 && s < 1e-2 * m) {  // 1.00000 .. 1.00003: offset 1
        const double p = std::pow(10.0, std::ceil(std::log10(s)));
        a.offset = std::round((a.min + a.max) / 2 / p) * p;
    }
    const double r = std::max(std::abs(a.min - a.offset), std::abs(a.max - a.offset));
    a.exp = 0;
    if (r > 0 && (r < 1e-2 || r >= 1e4)) a.exp = int(std::floor(std::log10(r) / 3)) * 3;
}

/// The tick step for a span (of mapped values): 1, 2, 2.5 or 5 times a power of ten, at
/// least span / 5.5, so that the range (the span and 6% margins) holds at most six ticks.
double nice_step(double span) {
    if (!(span > 0)) return 1;
    const double raw = span / 5, mag = std::pow(10.0, std::floor(std::log10(raw))), f = raw / mag;
    return (f <= 1.1 ? 1 : f <= 2.2 ? 2 : f <= 2.75 ? 2.5 : f <= 5.5 ? 5 : 10) * mag;
}

/// The range (the values and a margin of 3% each side) and the ticks inside it.
void set_ticks(axis& a, double step) {
    double lo = a.map(a.min), hi = a.map(a.max);
    if (!(hi > lo)) {  // a constant: a unit interval around it
        const double h = lo == 0 ? 1 : std::pow(10.0, std::floor(std::log10(std::abs(lo))));
        lo -= h, hi += h;
        step = nice_step(hi - lo);
    }
    const double pad = 0.03 * (hi - lo);
    a.lo = lo - pad, a.hi = hi + pad;
    a.step = step;
    a.tick_lo = std::ceil(a.lo / step - 1e-9) * step;
    a.tick_hi = std::floor(a.hi / step + 1e-9) * step;
}

/// Each axis on its own scale and ticks.
void own_scales(std::vector<axis*> axes) {
    for (axis* a : axes) {
        choose_scale(*a);
        set_ticks(*a, nice_step(a->map(a->max) - a->map(a->min)));
    }
}

/// The axes drawn at one scale: one power of ten and one step for all.
void common_scale(std::vector<axis*> axes) {
    int exp = INT32_MIN;
    double span = 0;
    for (axis* a : axes) {
        choose_scale(*a);
        exp = std::max(exp, a->exp);
    }
    for (axis* a : axes) a->exp = exp, span = std::max(span, a->map(a->max) - a->map(a->min));
    for (axis* a : axes) set_ticks(*a, nice_step(span));
}

/// True when the extents (all > 0) are within equal_scale_ratio of each other.
bool comparable(std::initializer_list<double> extents) {
    double lo = INFINITY, hi = 0;
    for (double e : extents) lo = std::min(lo, e), hi = std::max(hi, e);
    return lo > 0 && hi <= equal_scale_ratio * lo;
}

void axis_lines(std::ostream& g, const char* which, const axis& a) {
    g << "set " << which << "label " << quote(a.label()) << " noenhanced\n";
    g << "set " << which << "range [" << number_text(a.lo, 12) << ":" << number_text(a.hi, 12) << "]\n";
    g << "set " << which << "tics " << number_text(a.tick_lo, 12) << ", " << number_text(a.step, 12) << ", "
      << number_text(a.tick_hi, 12) << "\n";
    g << "set format " << which << " '%g'\n";
}

/// A unit vector to 3 digits, components below 5e-4 (rounding noise) printed as 0.
std::string vector_text(const double* v) {
    const auto c = [](double x) { return number_text(std::abs(x) < 5e-4 ? 0.0 : x, 3); };
    return "[" + c(v[0]) + ", " + c(v[1]) + ", " + c(v[2]) + "]";
}

/// The unit vector with its largest component positive (a direction, printed the same each time).
void orient(double* v) {
    int k = 0;
    for (int i = 1; i < 3; ++i)
        if (std::abs(v[i]) > std::abs(v[k]) + 1e-9) k = i;
    if (v[k] < 0)
        for (int i = 0; i < 3; ++i) v[i] = -v[i];
}

}  // namespace

view_choice choose_view(const plot_spec& spec, const std::string& who) {
    static const char* const plane_names[3] = {"yz", "xz", "xy"};  // by the axis across the plane
    const std::string& v = spec.view;
    const std::string want = v == "top" ? "xy" : v;
    if (want != "auto" && want != "xy" && want != "xz" && want != "yz" && want != "plane" && want != "3d")
        throw error(who + ": unknown view '" + v + "': give \"auto\", \"top\", \"xy\", \"xz\", \"yz\", \"plane\" or \"3d\"");
    const std::size_t n = spec.columns.size() == 3 ? spec.columns[0].size() : 0;
    // the finite points, their coordinate extents, centroid and covariance
    Eigen::Vector3d mean = Eigen::Vector3d::Zero(), lo = Eigen::Vector3d::Constant(INFINITY),
                    hi = Eigen::Vector3d::Constant(-INFINITY);
    std::vector<Eigen::Vector3d> pts;
    for (std::size_t i = 0; i < n; ++i) {
        const Eigen::Vector3d p(spec.columns[0][i], spec.columns[1][i], spec.columns[2][i]);
        if (!p.allFinite()) continue;
        pts.push_back(p);
        mean += p, lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    }
    view_choice c;
    const std::string L[3] = {spec.xlabel, spec.ylabel, spec.zlabel};
    const auto coordinate = [&](int across) {  // the coordinate plane across axis `across`
        const int a = across == 0 ? 1 : 0, b = across == 2 ? 1 : 2;
        c.kind = plane_names[across];
        for (int i = 0; i < 3; ++i) c.u[i] = i == a, c.v[i] = i == b;
        const bool single = L[a].size() == 1 && L[b].size() == 1;
        const std::string pair = single ? L[a] + "-" + L[b] : L[a] + ", " + L[b];
        c.caption = (across == 2 ? "seen from above (" : "seen along " + L[across] + " (") + pair + ")";
        if (!pts.empty()) {
            if (lo[across] == hi[across]) c.caption += ", in the plane " + L[across] + " = " + number_text(lo[across]);
            else c.caption += ", " + L[across] + " from " + number_text(lo[across], 3) + " to " + number_text(hi[across], 3);
        }
        return c;
    };
    if (want == "xy") return coordinate(2);
    if (want == "xz") return coordinate(1);
    if (want == "yz") return coordinate(0);
    c.kind = "3d";
    c.caption = "in 3-D";
    if (pts.empty()) return c;
    mean /= double(pts.size());
    const Eigen::Vector3d ext = hi - lo;
    // the coordinate axis along which the curve is flattest
    int across = 0;
    for (int k = 1; k < 3; ++k)
        if (ext[k] < ext[across]) across = k;
    const double largest = ext.maxCoeff();
    if (want == "auto" && (largest == 0 || ext[across] <= planar_fraction * largest)) return coordinate(across);
    // the principal directions: eigenvectors of the covariance, eigenvalues ascending
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const auto& p : pts) cov += (p - mean) * (p - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
    double pext[3];
    for (int k = 0; k < 3; ++k) {
        double a = INFINITY, b = -INFINITY;
        for (const auto& p : pts) {
            const double x = p.dot(es.eigenvectors().col(k));
            a = std::min(a, x), b = std::max(b, x);
        }
        pext[k] = b - a;
    }
    const double plargest = std::max({pext[0], pext[1], pext[2]});
    if (want == "plane" || (want == "auto" && pext[0] <= planar_fraction * plargest)) {
        c.kind = "plane";
        for (int i = 0; i < 3; ++i) c.u[i] = es.eigenvectors()(i, 2), c.v[i] = es.eigenvectors()(i, 1);
        orient(c.u), orient(c.v);
        double nrm[3];
        for (int i = 0; i < 3; ++i) nrm[i] = es.eigenvectors()(i, 0);
        orient(nrm);
        c.caption = "projected on the plane of the motion (normal " + vector_text(nrm) + ")";
    }
    return c;
}

std::string gnuplot_script(const plot_spec& spec, const std::string& format, const std::string& dir,
                           const std::string& who) {
    const fs::path tmp(dir);
    const fs::path data = tmp / "data.dat", out = tmp / ("out." + format);
    const std::size_t n = spec.three_d ? (spec.columns.empty() ? 0 : spec.columns[0].size()) : spec.t.size();
    std::ostringstream g;
    g << "set encoding utf8\n";
    if (format == "png")
        g << "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n"
             "  set terminal pngcairo size 900,700 enhanced font 'Sans,11' background rgb 'white'\n"
             "} else {\n  set terminal png size 900,700 background rgb 'white'\n}\n";
    else
        g << "set terminal svg size 900,700 font 'Sans,11' background rgb 'white'\n";
    g << "set output " << quote(out.string()) << "\n";
    g << "set title " << quote(spec.title) << " noenhanced\n";
    g << "set grid\n";
    const std::string df = quote(data.string());
    std::ofstream d(data);
    d << std::setprecision(12);
    if (!spec.three_d) {
        axis ax, ay;
        ax.name = spec.xlabel, ay.name = spec.ylabel;
        for (std::size_t i = 0; i < n; ++i) {
            bool any = false;
            for (const auto& c : spec.columns) any = any || std::isfinite(c[i]);
            if (any) ax.see(spec.t[i]);
            for (const auto& c : spec.columns) ay.see(c[i]);
        }
        for (const auto& ps : spec.points)
            for (std::size_t i = 0; i < ps.x.size(); ++i)
                if (std::isfinite(ps.x[i]) && std::isfinite(ps.y[i])) ax.see(ps.x[i]), ay.see(ps.y[i]);
        own_scales({&ax, &ay});
        for (std::size_t i = 0; i < n; ++i) {
            write_number(d, ax.map(spec.t[i]));
            for (const auto& c : spec.columns) d << ' ', write_number(d, ay.map(c[i]));
            d << '\n';
        }
        for (std::size_t k = 0; k < spec.points.size(); ++k) {
            std::ofstream pd(tmp / ("points" + std::to_string(k) + ".dat"));
            pd << std::setprecision(12);
            for (std::size_t i = 0; i < spec.points[k].x.size(); ++i) {
                write_number(pd, ax.map(spec.points[k].x[i]));
                pd << ' ';
                write_number(pd, ay.map(spec.points[k].y[i]));
                pd << '\n';
            }
            if (!pd) throw error(who + ": cannot write the temporary data file of the points");
        }
        axis_lines(g, "x", ax);
        axis_lines(g, "y", ay);
        if (spec.columns.size() + spec.points.size() > 1) g << "set key below\n";
        else g << "unset key\n";
        g << "plot ";
        for (std::size_t k = 0; k < spec.points.size(); ++k) {  // the marks first, the curves over them
            if (k) g << ", \\\n     ";
            g << quote((tmp / ("points" + std::to_string(k) + ".dat")).string())
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
        const view_choice vc = choose_view(spec, who);
        const auto& X = spec.columns;
        if (vc.kind != "3d") {
            axis au, av;
            if (vc.kind == "plane") au.name = "u (along " + vector_text(vc.u) + ")", av.name = "v (along " + vector_text(vc.v) + ")";
            else {
                const std::string L[3] = {spec.xlabel, spec.ylabel, spec.zlabel};
                for (int i = 0; i < 3; ++i) {
                    if (vc.u[i] == 1) au.name = L[i];
                    if (vc.v[i] == 1) av.name = L[i];
                }
            }
            std::vector<std::pair<double, double>> uv(n);
            for (std::size_t i = 0; i < n; ++i) {
                double a = 0, b = 0;
                for (int k = 0; k < 3; ++k) {
                    if (vc.u[k] != 0) a += vc.u[k] * X[k][i];
                    if (vc.v[k] != 0) b += vc.v[k] * X[k][i];
                }
                uv[i] = {a, b};
                if (std::isfinite(a) && std::isfinite(b)) au.see(a), av.see(b);
            }
            if (comparable({au.span(), av.span()})) {
                common_scale({&au, &av});
                g << "set size ratio -1\n";
            } else {
                own_scales({&au, &av});
                if (au.span() > 0 && av.span() > 0) av.note = "not to scale with " + au.name.substr(0, au.name.find(' '));
            }
            for (const auto& [a, b] : uv) write_number(d, au.map(a)), d << ' ', write_number(d, av.map(b)), d << '\n';
            axis_lines(g, "x", au);
            axis_lines(g, "y", av);
            g << "set key below reverse Left\n";
            g << "plot " << df << " using 1:2 with lines linewidth 1.2 title " << quote("curve " + vc.caption)
              << " noenhanced, \\\n     " << df
              << " every ::0::0 using 1:2 with points pointtype 7 pointsize 1.3 title 'start'\n";
        } else {
            axis a[3];
            a[0].name = spec.xlabel, a[1].name = spec.ylabel, a[2].name = spec.zlabel;
            for (std::size_t i = 0; i < n; ++i)
                if (std::isfinite(X[0][i]) && std::isfinite(X[1][i]) && std::isfinite(X[2][i]))
                    for (int k = 0; k < 3; ++k) a[k].see(X[k][i]);
            const std::string equal = comparable({a[0].span(), a[1].span(), a[2].span()}) ? "xyz"
                                      : comparable({a[0].span(), a[1].span()})            ? "xy"
                                                                                          : "";
            // in 3-D the scales are said in the legend (a long z label would leave the canvas)
            std::string scales;
            if (equal == "xyz") common_scale({&a[0], &a[1], &a[2]});
            else if (equal == "xy") {
                common_scale({&a[0], &a[1]});
                own_scales({&a[2]});
                scales = "; " + a[2].name + " not to scale with " + a[0].name + ", " + a[1].name;
            } else {
                own_scales({&a[0], &a[1], &a[2]});
                scales = "; axes not to scale with each other";
            }
            for (std::size_t i = 0; i < n; ++i) {
                for (int k = 0; k < 3; ++k) {
                    if (k) d << ' ';
                    write_number(d, a[k].map(X[k][i]));
                }
                d << '\n';
            }
            axis_lines(g, "x", a[0]);
            axis_lines(g, "y", a[1]);
            axis_lines(g, "z", a[2]);
            g << "set key below reverse Left\n";
            g << "set view " << number_text(90 - spec.elevation) << ", "
              << number_text(std::fmod(std::fmod(spec.azimuth, 360.0) + 360.0, 360.0)) << "\n";
            if (!equal.empty()) g << "set view equal " << equal << "\n";
            g << "set xyplane relative 0\n";
            g << "splot " << df << " using 1:2:3 with lines linewidth 1.2 title "
              << quote("curve in 3-D (azimuth " + number_text(spec.azimuth) + ", elevation " +
                       number_text(spec.elevation) + ")" + scales)
              << " noenhanced"
              << ", \\\n      " << df << " every ::0::0 using 1:2:3 with points pointtype 7 pointsize 1.3 title 'start'\n";
        }
    }
    if (!d) throw error(who + ": cannot write the temporary data file " + data.string());
    g << "unset output\n";
    return g.str();
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
    for (std::size_t i = 0; i < n; ++i) {
        bool row = true;
        for (const auto& c : spec.columns) row = row && std::isfinite(c[i]);
        if (!spec.three_d) {
            for (const auto& c : spec.columns) any_finite = any_finite || std::isfinite(c[i]);
        } else if (row) {
            any_finite = true;
        }
    }
    for (const auto& ps : spec.points) {
        if (ps.x.size() != ps.y.size()) throw error(who + ": internal: a point set with different lengths");
        for (std::size_t i = 0; i < ps.x.size(); ++i)
            any_finite = any_finite || (std::isfinite(ps.x[i]) && std::isfinite(ps.y[i]));
    }
    if (!any_finite) throw error(who + ": no sample is a finite number (nothing to draw)");

    temp_dir tmp(who);
    const fs::path script = tmp.path / "plot.gp", out = tmp.path / ("out" + ext), log = tmp.path / "gnuplot.log";
    {
        const std::string text = gnuplot_script(spec, ext.substr(1), tmp.path.string(), who);
        std::ofstream g(script);
        g << text;
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
