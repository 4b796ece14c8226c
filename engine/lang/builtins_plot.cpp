// symrep/lang/builtins_plot.cpp -- plot, trajectory and hodograph: pictures drawn by
// gnuplot (output/plot.h) from closed forms evaluated by the compiled evaluator.
//
//   plot(e, values, t = [t0, t1], "file.png" [, n [, "title"]])        e(t), e scalar or list
//   trajectory(r, values, t = [t0, t1], "file.svg" [, n [, "title"]])  the curve r(t)
//   hodograph(r, values, t = [t0, t1], "file.png" [, n [, "title"]])   the curve r'(t)
// trajectory and hodograph take the options view = "auto" | "top" | "xy" | "xz" | "yz" |
// "plane" | "3d", azimuth = a, elevation = e (degrees, for the 3-D view), anywhere among
// the arguments; the view "auto" is chosen from the data (output/plot.h).
#include <cmath>
#include <sstream>

#include "symrep/scalar/scalar.h"
#include "symrep/lang/builtins.h"
#include "symrep/lang/interpreter.h"
#include "symrep/output/printer.h"
#include "symrep/lang/values.h"
#include "symrep/numeric/evaluator.h"
#include "symrep/output/plot.h"
#include "symrep/vector/vector.h"

namespace symrep::lang {

using output::print_ex;

using GiNaC::ex;
using args_t = std::vector<value>;

namespace {

const char* const section = "Plots";

struct time_range {
    ex t;  ///< the symbol
    double t0 = 0, t1 = 0;
};

time_range time_arg(const args_t& a, std::size_t i, const builtin& b, const data_values& d) {
    const std::string where = b.name + ": argument " + std::to_string(i + 1);
    if (!a[i].is_ex()) throw type_error(where + " must be t = [t0, t1] (usage: " + b.signature + ")");
    const ex& r = a[i].as_ex();
    if (!GiNaC::is_a<GiNaC::relational>(r) || !GiNaC::is_a<GiNaC::symbol>(r.lhs()) || is_vector_symbol(r.lhs()))
        throw type_error(where + " must be t = [t0, t1] with a scalar name t (usage: " + b.signature + ")");
    const ex range = r.rhs();
    if (!(GiNaC::is_a<GiNaC::lst>(range) || GiNaC::is_a<GiNaC::matrix>(range)) || range.nops() != 2)
        throw type_error(where + " must give the range of " + print_ex(r.lhs()) + " as [t0, t1], not " +
                         message_text(range));
    time_range tr;
    tr.t = r.lhs();
    // the ends may use the values (t = [0, 2*pi/w0])
    tr.t0 = to_double(put_values(range.op(0), d), b, "the start " + message_text(range.op(0)));
    tr.t1 = to_double(put_values(range.op(1), d), b, "the end " + message_text(range.op(1)));
    if (!std::isfinite(tr.t0) || !std::isfinite(tr.t1))
        throw type_error(b.name + ": the range of " + print_ex(tr.t) + " must be finite");
    if (!(tr.t0 < tr.t1))
        throw type_error(b.name + ": the range [" + message_text(range.op(0)) + ", " + message_text(range.op(1)) +
                         "] of " + print_ex(tr.t) + " is empty or reversed: t0 must be less than t1");
    return tr;
}

std::string file_arg(const args_t& a, std::size_t i, const builtin& b, context& c) {
    if (!a[i].is_string())
        throw type_error(b.name + ": argument " + std::to_string(i + 1) + " must be the file name as a string, e.g. " +
                         "\"orbit.png\" (usage: " + b.signature + ")");
    const std::string& f = a[i].as_string();
    if (f.empty()) throw type_error(b.name + ": the file name is empty");
    if (auto* s = dynamic_cast<session*>(&c)) return s->resolve_path(f);
    return f;
}

/// Samples the scalar closed forms `fs` (t free) at n points of [t0, t1].
std::vector<std::vector<double>> sample(const std::vector<ex>& fs, const time_range& tr, std::size_t n,
                                        const builtin& b, std::vector<double>& ts) {
    num::compiled_function f;
    try {
        f = num::compile(fs, {tr.t});
    } catch (const symrep::error& e) {
        throw type_error(b.name + ": " + e.what() + "; give every symbol but " + print_ex(tr.t) +
                         " a value in the values list");
    }
    ts.resize(n);
    for (std::size_t i = 0; i < n; ++i) ts[i] = tr.t0 + (tr.t1 - tr.t0) * double(i) / double(n - 1);
    std::vector<double> out(n * fs.size());
    f.eval_many(ts.data(), out.data(), n);
    std::vector<std::vector<double>> cols(fs.size(), std::vector<double>(n));
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < fs.size(); ++k) cols[k][i] = out[i * fs.size() + k];
    return cols;
}

/// The closed form of e with the values put in and t left free.
ex with_values(const ex& e, data_values d, const time_range& tr, const builtin& b) {
    d.scalars.erase(tr.t);
    try {
        return put_values_limit(e, d);
    } catch (const symrep::error& x) {
        throw type_error(b.name + ": " + x.what() + " (give every vector a value [x, y, z] in the values list)");
    }
}

std::string short_text(const ex& e, std::size_t max = 70) {
    std::string s = print_ex(e);
    if (s.size() > max) s = s.substr(0, max - 3) + "...";
    return s;
}

std::string range_text(const time_range& tr) {
    std::ostringstream os;
    os << print_ex(tr.t) << " from " << tr.t0 << " to " << tr.t1;
    return os.str();
}

long points_arg(const args_t& a, std::size_t i, const builtin& b, long dflt) {
    return a.size() > i ? arg_int(a, i, b, 2, 1000000) : dflt;
}

std::string title_arg(const args_t& a, std::size_t i, const builtin& b, std::string dflt) {
    return a.size() > i ? arg_string(a, i, b) : dflt;
}

/// trajectory and hodograph: a vector expression drawn as a space curve.
value space_curve(const builtin& b, const args_t& a, context& c, bool derivative) {
    const ex& r = arg_ex(a, 0, b);
    if (!r.is_zero() && !is_vector(r))
        throw type_error(b.name + ": argument 1 must be a vector function of t, not the scalar " + message_text(r) +
                         " (use plot for scalars)");
    const data_values d = read_values(a[1], b, 1);
    const time_range tr = time_arg(a, 2, b, d);
    const std::string file = file_arg(a, 3, b, c);
    const long n = points_arg(a, 4, b, 2000);
    const ex e = derivative ? r.diff(GiNaC::ex_to<GiNaC::symbol>(tr.t)) : r;  // vector constants are constant
    std::vector<ex> fs = components(with_values(e.is_zero() ? vector_literal(0, 0, 0) : e, d, tr, b));
    if (fs.size() != 3) throw type_error(b.name + ": argument 1 must be a vector with three components");
    output::plot_spec spec;
    spec.three_d = true;
    if (const value* v = c.named_option("view")) {
        if (!v->is_string())
            throw type_error(b.name + ": view must be a string: \"auto\", \"top\", \"xy\", \"xz\", \"yz\", "
                             "\"plane\" or \"3d\", not " + v->a_kind());
        spec.view = v->as_string();
        output::choose_view(spec, b.name);  // an unknown name fails before the sampling
    }
    for (const char* name : {"azimuth", "elevation"}) {
        const value* v = c.named_option(name);
        if (!v) continue;
        if (!v->is_ex()) throw type_error(b.name + ": " + name + " must be a number of degrees, not " + v->a_kind());
        const double deg = to_double(put_values(v->as_ex(), d), b, std::string("the ") + name);
        if (!std::isfinite(deg) || std::abs(deg) > 360)
            throw type_error(b.name + ": " + name + " must be a finite number of degrees in [-360, 360]");
        if (std::string(name) == "azimuth") spec.azimuth = deg;
        else if (deg < -90 || deg > 90) throw type_error(b.name + ": elevation must be in [-90, 90] degrees");
        else spec.elevation = deg;
        if (spec.view != "3d")
            throw type_error(b.name + ": " + name + " sets the 3-D view: give view = \"3d\" with it");
    }
    std::vector<double> ts;
    spec.columns = sample(fs, tr, std::size_t(n), b, ts);
    const std::string t = print_ex(tr.t);
    if (derivative) {
        spec.xlabel = "dx/d" + t, spec.ylabel = "dy/d" + t, spec.zlabel = "dz/d" + t;
        spec.title = title_arg(a, 5, b, "hodograph (velocity), " + range_text(tr));
    } else {
        spec.xlabel = "x", spec.ylabel = "y", spec.zlabel = "z";
        spec.title = title_arg(a, 5, b, "trajectory, " + range_text(tr));
    }
    output::write_plot(spec, file, b.name);
    c.wrote_file(file);
    return value();
}

value builtin_plot(const builtin& b, const args_t& a, context& c) {
    std::vector<ex> es;
    output::plot_spec spec;
    if (a[0].is_list()) {
        // an entry that is a list of [x, y] pairs is a set of points (a table)
        for (const value& v : a[0].as_list()) {
            if (!v.is_list()) {
                if (!v.is_ex()) throw type_error(b.name + ": a curve must be an expression or a list of [x, y] points");
                es.push_back(v.as_ex());
                continue;
            }
            output::plot_spec::point_set ps;
            ps.name = "points";
            for (const value& pt : v.as_list()) {
                const auto number = [&](const value& x) {
                    if (!x.is_ex()) throw type_error(b.name + ": a point must be a pair [x, y] of real numbers");
                    return to_double(x.as_ex(), b, "a point's coordinate");
                };
                if (!pt.is_list() || pt.as_list().size() != 2)
                    throw type_error(b.name + ": a point must be a pair [x, y] of real numbers");
                ps.x.push_back(number(pt.as_list()[0]));
                ps.y.push_back(number(pt.as_list()[1]));
            }
            if (ps.x.empty()) throw type_error(b.name + ": an empty list of points");
            if (spec.points.size() > 0) ps.name += " " + std::to_string(spec.points.size() + 1);
            spec.points.push_back(std::move(ps));
        }
    } else {
        es.push_back(arg_ex(a, 0, b));
    }
    if (es.empty() && spec.points.empty()) throw type_error(b.name + ": nothing to plot (the list is empty)");
    const data_values d = read_values(a[1], b, 1);
    const time_range tr = time_arg(a, 2, b, d);
    const std::string file = file_arg(a, 3, b, c);
    const long n = points_arg(a, 4, b, 1000);
    std::vector<ex> fs;
    for (ex e : es) {
        std::string name;  // name = e labels the curve
        if (GiNaC::is_a<GiNaC::relational>(e) && GiNaC::is_a<GiNaC::symbol>(e.lhs()) &&
            !is_vector_symbol(e.lhs())) {
            name = print_ex(e.lhs());
            e = e.rhs();
        }
        const std::vector<ex> cs = components(with_values(e, d, tr, b));
        if (cs.size() == 3 && is_vector(e)) {
            static const char* xyz[] = {"x", "y", "z"};
            for (std::size_t k = 0; k < 3; ++k) {
                fs.push_back(cs[k]);
                spec.names.push_back(std::string(xyz[k]) + " of " + (name.empty() ? short_text(e, 40) : name));
            }
        } else if (cs.size() == 1) {
            fs.push_back(cs[0]);
            spec.names.push_back(name.empty() ? short_text(e, 60) : name);
        } else {
            throw type_error(b.name + ": cannot plot " + message_text(e) +
                             ": a scalar, a list of scalars or a vector is needed");
        }
    }
    spec.columns = sample(fs, tr, std::size_t(n), b, spec.t);
    spec.xlabel = print_ex(tr.t);
    spec.ylabel = fs.size() == 1 && spec.points.empty() ? spec.names[0] : std::string("value");
    if (fs.size() == 1 && spec.points.empty()) spec.names.clear();
    spec.title = title_arg(a, 5, b, es.size() == 1 ? short_text(es[0]) : std::string("plot"));
    output::write_plot(spec, file, b.name);
    c.wrote_file(file);
    return value();
}

value builtin_trajectory(const builtin& b, const args_t& a, context& c) {
    return space_curve(b, a, c, false);
}

value builtin_hodograph(const builtin& b, const args_t& a, context& c) {
    return space_curve(b, a, c, true);
}

}  // namespace

void register_plot_builtins(registry& r) {
    add_builtins(r, section, {
        {"plot", "plot(e, values, t = [t0, t1], \"file.png\" [, n [, \"title\"]])",
         "Draws e as a function of t on [t0, t1] (n samples, default 1000) into a PNG or SVG file (the "
         "extension chooses; gnuplot draws it, and must be installed: Debian package gnuplot-nox, or "
         "the program named by SYMREP_GNUPLOT). e is a scalar expression, a list of them (one curve "
         "each, with a legend) or a vector (its x, y, z components); name = e labels a curve. values as in eval: name = value, "
         "vectors as [x, y, z]; the ends t0, t1 may use them. At most six ticks per axis; tiny or huge "
         "values are drawn scaled, the axis label saying so (\"value (x 1e-3)\"). A relative file name is relative to the "
         "running script; a file that already holds the same picture is left alone. Returns nothing.",
         "", "plot([sin(t), cos(w*t)], [w = 2], t = [0, 2*pi], \"/tmp/symrep_plot_example.svg\")",
         4, 6, builtin_plot},
        {"trajectory", "trajectory(r, values, t = [t0, t1], \"file.svg\" [, n [, \"title\"]] [, view = \"auto\"])",
         "Draws the space curve of the vector function r(t), t in [t0, t1] (n samples, default 2000), "
         "into a PNG or SVG file as plot does, the start marked. The view is chosen from the data: a "
         "nearly planar curve (its extent across its plane at most 5% of its largest extent) is drawn "
         "in 2-D, in a coordinate plane when it is that flat along a coordinate axis (\"seen from above "
         "(x-y)\"), else projected on the plane of the motion (axes u, v named by their directions); "
         "any other curve in 3-D. The legend says which. Options, anywhere among the arguments: "
         "view = \"auto\" (default), \"top\" (= \"xy\"), \"xy\", \"xz\", \"yz\", \"plane\" or \"3d\"; "
         "with \"3d\", azimuth = a and elevation = e in degrees (default 30, 30). Axes share one scale "
         "when their extents are within 1:4, else a label says \"not to scale\"; tiny or huge values "
         "are drawn scaled, the label saying so (\"z (x 1e-3)\").",
         "", "vector w, r0\ntrajectory(rotation_operator(w, t, r0), [w = [0, 0, 1], r0 = [1, 0, 1]], "
         "t = [0, 6], \"/tmp/symrep_trajectory_example.svg\", view = \"3d\", azimuth = 40)", 4, 6,
         builtin_trajectory, {"view", "azimuth", "elevation"}},
        {"hodograph", "hodograph(r, values, t = [t0, t1], \"file.png\" [, n [, \"title\"]] [, view = \"auto\"])",
         "Draws the hodograph of the motion r(t): the curve of its velocity dr/dt (diff(r, t), vector "
         "constants being constant), as trajectory draws a curve, with the same options (view, "
         "azimuth, elevation).",
         "", "vector w, r0\nhodograph(rotation_operator(w, t, r0), [w = [0, 0, 1], r0 = [1, 0, 1]], "
         "t = [0, 6], \"/tmp/symrep_hodograph_example.svg\")", 4, 6, builtin_hodograph,
         {"view", "azimuth", "elevation"}},
    });
}

}  // namespace symrep::lang
