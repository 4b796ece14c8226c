// repl/python/module.cpp -- symrep._symrep, the compiled part of the Python module `symrep`
// (docs/python.md). A thin layer over the language session (lang/interpreter.h) and the
// compiled evaluators (numeric/evaluator.h, numeric/stable_evaluator.h):
//
//   Session   runs statements: eval() returns the last value or raises symrep.Error with the
//             line and column; run() returns the events of a cell in order (text printed,
//             results, pictures written, the error) for front-ends such as the Jupyter kernel;
//             completions() and help() are the interactive prompt's (lang/help.h).
//   Value     a value of the language (expression, element, list, ...) with its text, LaTeX
//             and kind; Python operators and builtin calls go through the session.
//   Compiled  a closed form compiled once, evaluated over NumPy arrays with the GIL released.
//
// The package's Python side (symrep/__init__.py) defines symrep.Error and the conversions
// to Python numbers and SymPy.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <csignal>
#include <cmath>
#include <memory>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/interrupt.h"
#include "lang/help.h"
#include "lang/interpreter.h"
#include "lang/print_value.h"
#include "lang/values.h"
#include "syntax/lexer.h"
#include "numeric/evaluator.h"
#include "numeric/stable_evaluator.h"
#include "vector/vector.h"

namespace py = pybind11;
using namespace symrep;

namespace {

// One session and the streams it writes to, shared by the values made in it.
struct session_state {
    std::ostringstream out, err;
    lang::session s{out, err};
    long next_temporary = 0;
};
using state_ptr = std::shared_ptr<session_state>;

struct py_value {
    lang::value v;
    state_ptr state;
};

[[noreturn]] void raise_error(const std::string& message, const std::string& file, int line, int column,
                              const std::string& source_line) {
    py::object error = py::module_::import("symrep").attr("Error");
    py::object e = line > 0 ? error(message, file, line, column, source_line)
                            : error(message, py::none(), py::none(), py::none(), py::none());
    PyErr_SetObject(error.ptr(), e.ptr());
    throw py::error_already_set();
}

// SIGINT while the engine runs (the notebook's stop button, Ctrl-C) sets the engine's
// interruption flag; the statement fails with "interrupted" and Python gets symrep.Error.
// The previous handler (Python's) is restored afterwards.
class interruptible {
public:
    interruptible() {
        symrep::interrupt_flag() = false;
        struct sigaction sa {};
        sa.sa_handler = [](int) { symrep::interrupt_flag() = true; };
        sigemptyset(&sa.sa_mask);
        sigaction(SIGINT, &sa, &old_);
    }
    ~interruptible() {
        sigaction(SIGINT, &old_, nullptr);
        symrep::interrupt_flag() = false;
    }

private:
    struct sigaction old_ {};
};

// `located`: the code is the user's (errors carry its line and column); off for the statements
// this module writes itself (operators, calls), whose places mean nothing to the user.
py_value eval(const state_ptr& st, const std::string& code, bool located = true) {
    lang::value v;
    std::string message, file, source;
    int line = 0, column = 0;
    {
        // the GIL stays held: GiNaC is not thread safe (docs/library.md), so no other Python
        // thread may enter the engine meanwhile; SIGINT reaches the engine's flag regardless
        interruptible guard;
        try {
            v = st->s.evaluate(code);
        } catch (const lang::script_error& e) {
            message = e.what(), file = "<python>", line = e.where.line, column = e.where.column;
            source = lang::source_line(code, line);
        } catch (const std::bad_alloc& e) {
            message = allocation_failure_message(e, "out of memory");
        } catch (const std::exception& e) {
            message = e.what();
        }
    }
    if (!message.empty()) {
        if (!located) line = 0;
        raise_error(message, file, line, column, source);
    }
    return {std::move(v), st};
}

// Names for values in the session, removed again when the statement over them has run:
// operations and calls are statements over such names.
class temporaries {
public:
    explicit temporaries(state_ptr st) : st_(std::move(st)) {}
    temporaries(const temporaries&) = delete;
    temporaries& operator=(const temporaries&) = delete;
    ~temporaries() {
        for (const std::string& n : names_) st_->s.erase(n);
    }
    std::string operator()(const lang::value& v) {
        names_.push_back("__py" + std::to_string(st_->next_temporary++));
        st_->s.set(names_.back(), v);
        return names_.back();
    }

private:
    state_ptr st_;
    std::vector<std::string> names_;
};

// A Python argument as a language value: Value, bool, int, float, Fraction-like (numerator /
// denominator), str (a string value), list or tuple (a list).
lang::value from_python(const state_ptr& st, const py::handle& x);

lang::value number_from_text(const state_ptr& st, const std::string& text) { return st->s.evaluate(text); }

lang::value from_python(const state_ptr& st, const py::handle& x) {
    if (py::isinstance<py_value>(x)) return x.cast<const py_value&>().v;
    if (py::isinstance<py::bool_>(x)) return lang::value(x.cast<bool>());
    if (py::isinstance<py::int_>(x)) return number_from_text(st, py::str(x).cast<std::string>());
    if (py::isinstance<py::float_>(x)) {
        const double d = x.cast<double>();
        if (!std::isfinite(d)) throw symrep::type_error("not a finite number: " + py::repr(x).cast<std::string>());
        return lang::value(GiNaC::ex(GiNaC::numeric(d)));
    }
    if (py::hasattr(x, "numerator") && py::hasattr(x, "denominator") && !py::isinstance<py::str>(x))
        return number_from_text(st, "(" + py::str(x.attr("numerator")).cast<std::string>() + ")/(" +
                                        py::str(x.attr("denominator")).cast<std::string>() + ")");
    if (py::isinstance<py::str>(x)) return lang::value(x.cast<std::string>());
    if (py::isinstance<py::list>(x) || py::isinstance<py::tuple>(x)) {
        lang::list l;
        for (const py::handle& y : x) l.push_back(from_python(st, y));
        return lang::value(std::move(l));
    }
    throw symrep::type_error("cannot pass a Python " + py::str(x.get_type().attr("__name__")).cast<std::string>() +
                             " to symrep (numbers, strings, lists and symrep values only)");
}

// name(args...) evaluated in the session
py_value call(const state_ptr& st, const std::string& name, const std::vector<lang::value>& args) {
    temporaries tmp(st);
    std::string code = name + "(";
    for (std::size_t i = 0; i < args.size(); ++i) code += (i ? ", " : "") + tmp(args[i]);
    return eval(st, code + ")", false);
}

py_value binary(const py_value& a, const py::object& b, const std::string& op, bool reflected) {
    const lang::value other = from_python(a.state, b);
    temporaries tmp(a.state);
    const std::string x = tmp(a.v), y = tmp(other);
    return eval(a.state, reflected ? "(" + y + ") " + op + " (" + x + ")" : "(" + x + ") " + op + " (" + y + ")",
                false);
}

// --- the compiled fast path ---------------------------------------------------

struct compiled {
    num::compiled_function f;
    std::shared_ptr<num::stable_function> stable;
    std::vector<std::string> inputs;    // one per input column
    std::vector<std::size_t> widths;    // per input name given: 1 (scalar) or 3 (vector)
    std::vector<std::string> names;     // the input names as given
    std::size_t n_outputs = 0;
    std::string text;
};

// A value for name: the closed form (or another value) must have the symbol.
void check_value_name(const GiNaC::ex& name, const std::vector<GiNaC::ex>& forms, const lang::data_values& d) {
    for (const GiNaC::ex& f : forms)
        if (f.has(name)) return;
    for (const auto& [k, x] : d.scalars)
        if (!k.is_equal(name) && x.has(name)) return;
    for (const auto& [k, x] : d.vectors)
        if (!k.is_equal(name) && x.has(name)) return;
    std::set<std::string> names;
    for (const GiNaC::ex& f : forms)
        for (auto it = f.preorder_begin(); it != f.preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::symbol>(*it)) names.insert(GiNaC::ex_to<GiNaC::symbol>(*it).get_name());
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    throw symrep::type_error("compile: a value is given for '" + num::symbol_name(name) +
                             "', which the closed form does not have (its symbols: " +
                             (list.empty() ? std::string("none") : list) + ")");
}

compiled compile(const state_ptr& st, const py_value& e, const std::vector<std::string>& inputs,
                 const py::object& values, bool stable) {
    // an expression (a scalar, a vector: its components) or a list of them (flattened)
    std::vector<GiNaC::ex> forms;
    std::function<bool(const lang::value&)> collect = [&](const lang::value& x) {
        if (x.is_ex()) return forms.push_back(x.as_ex()), true;
        if (!x.is_list()) return false;
        for (const lang::value& y : x.as_list())
            if (!collect(y)) return false;
        return true;
    };
    if (!collect(e.v))
        raise_error("compile: the closed form must be an expression or a list of them, not " + e.v.a_kind(), "", 0,
                    0, "");
    compiled c;
    std::string message;
    try {
        lang::data_values d;
        if (!values.is_none()) {
            // name = value pairs read by the language (vectors as [x, y, z])
            const py::dict dv = values.cast<py::dict>();
            temporaries tmp(st);
            std::string list = "[";
            bool first = true;
            for (const auto& [k, v] : dv) {
                list += (first ? "" : ", ") + k.cast<std::string>() + " = " + tmp(from_python(st, v));
                first = false;
            }
            const lang::value vl = st->s.evaluate(list + "]");
            lang::builtin b;
            b.name = "compile";
            // floats taken as the exact doubles they are: GiNaC would otherwise fold w . w,
            // |w|^2 - w_y^2 ... in double precision as the values go in (a cancellation the
            // compiled program, the stable one too, would then take for exact)
            d = lang::exact_values(lang::read_values(vl, b, 1));
        }
        std::vector<GiNaC::ex> in;
        for (const std::string& name : inputs) {
            const GiNaC::ex sym = st->s.symbol(name);
            c.names.push_back(name);
            if (is_vector_symbol(sym)) {
                GiNaC::ex comps[3];
                for (int k = 0; k < 3; ++k) {
                    comps[k] = st->s.symbol(name + "_" + "xyz"[k]);
                    in.push_back(comps[k]);
                    c.inputs.push_back(name + "_" + "xyz"[k]);
                }
                d.vectors[sym] = vector_literal(comps[0], comps[1], comps[2]);
                c.widths.push_back(3);
            } else {
                in.push_back(sym);
                c.inputs.push_back(name);
                c.widths.push_back(1);
            }
        }
        // a value for a name that the closed form does not have is a typo, not a no-op
        for (const auto& [k, x] : d.scalars) check_value_name(k, forms, d);
        for (const auto& [k, x] : d.vectors) check_value_name(k, forms, d);
        std::vector<GiNaC::ex> outs;
        for (const GiNaC::ex& form : forms) {
            GiNaC::ex put;
            try {
                // where the values make the closed form singular (w = 0 in sin(|w| t)/|w|): the limit
                put = lang::put_values_limit(form, d);
            } catch (const symrep::error&) {
                throw;
            } catch (const std::exception&) {
                throw symrep::domain_error(
                    "compile: the closed form is singular at these values (a division by zero) and its limit "
                    "there could not be taken; solve the problem for these values, solve(P, values), and "
                    "compile that solution");
            }
            for (const GiNaC::ex& x : lang::components(put)) outs.push_back(x);
        }
        c.f = num::compile(outs, in);
        // always: the plain path checks its points with the stable evaluator's double tier
        (void)stable;
        c.stable = std::make_shared<num::stable_function>(outs, in);
        c.n_outputs = outs.size();
        c.text = lang::print_value(e.v);
    } catch (const std::exception& ex) {
        message = ex.what();
    }
    if (!message.empty()) raise_error(message.rfind("compile: ", 0) == 0 ? message : "compile: " + message, "", 0, 0, "");
    return c;
}

// f(**arrays): every input a scalar or an array of n values (vectors: n x 3 or 3); the result
// n x n_outputs (n_outputs == 1: a vector of n values).
// How f(...) evaluates: checked (the default), the stable evaluator, or the bare double program.
enum class evaluation { checked, stable, unchecked };

// The accuracy the checked path proves for every output (relative to its value); docs/python.md.
constexpr double plain_rel_tol = 1e-6;

py::array_t<double> evaluate(const compiled& c, const py::kwargs& kw, evaluation mode) {
    const std::size_t k = c.inputs.size();
    std::vector<py::array_t<double, py::array::c_style | py::array::forcecast>> cols;
    std::size_t n = 1;
    for (std::size_t i = 0; i < c.names.size(); ++i) {
        if (!kw.contains(c.names[i].c_str()))
            throw symrep::type_error("missing input '" + c.names[i] + "'");
        auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(kw[c.names[i].c_str()]);
        if (!a) throw symrep::type_error("input '" + c.names[i] + "' is not numeric");
        const std::size_t w = c.widths[i];
        std::size_t len = 1;
        if (w == 1 && a.ndim() == 1) len = std::size_t(a.shape(0));
        else if (w == 3 && a.ndim() == 2 && a.shape(1) == 3) len = std::size_t(a.shape(0));
        else if (!(w == 1 && a.ndim() == 0) && !(w == 3 && a.ndim() == 1 && a.shape(0) == 3))
            throw symrep::type_error("input '" + c.names[i] + "' must be " +
                                     (w == 1 ? "a number or a 1-D array" : "3 numbers or an n x 3 array"));
        if (len != 1) {
            if (n != 1 && len != n)
                throw symrep::type_error("inputs of different lengths (" + std::to_string(n) + " and " +
                                         std::to_string(len) + ")");
            n = len;
        }
        cols.push_back(a);
    }
    for (const auto& key : kw) {
        const std::string name = key.first.cast<std::string>();
        if (std::find(c.names.begin(), c.names.end(), name) == c.names.end())
            throw symrep::type_error("'" + name + "' is not an input of this function (inputs: " +
                                     [&] {
                                         std::string s;
                                         for (const auto& x : c.names) s += (s.empty() ? "" : ", ") + x;
                                         return s;
                                     }() + ")");
    }
    // row-major inputs, n x k (a scalar broadcast)
    std::vector<double> in(n * k);
    std::size_t col = 0;
    for (std::size_t i = 0; i < c.names.size(); ++i) {
        const auto& a = cols[i];
        const double* p = a.data();
        const bool array = (c.widths[i] == 1 && a.ndim() == 1) || (c.widths[i] == 3 && a.ndim() == 2);
        for (std::size_t r = 0; r < n; ++r)
            for (std::size_t j = 0; j < c.widths[i]; ++j) in[r * k + col + j] = p[(array ? r * c.widths[i] : 0) + j];
        col += c.widths[i];
    }
    const std::size_t m = c.n_outputs;
    py::array_t<double> out = m == 1 ? py::array_t<double>(std::vector<py::ssize_t>{py::ssize_t(n)})
                                     : py::array_t<double>(std::vector<py::ssize_t>{py::ssize_t(n), py::ssize_t(m)});
    double* o = out.mutable_data();
    if (mode == evaluation::stable) {
        // its exact tier uses GiNaC: the GIL stays held
        for (std::size_t r = 0; r < n; ++r) c.stable->eval(in.data() + r * k, o + r * m);
    } else if (mode == evaluation::unchecked) {
        // doubles only, an immutable program (thread safe): other Python threads run meanwhile
        py::gil_scoped_release nogil;
        c.f.eval_many(in.data(), o, n);
    } else {
        // checked: the double program with its running error bound (the stable evaluator's
        // first tier, reentrant: the GIL released); a point where an output's bound exceeds
        // plain_rel_tol of its value is evaluated again by the stable evaluator (GIL held)
        std::vector<std::size_t> again;
        {
            py::gil_scoped_release nogil;
            again = c.stable->eval_many_binary64(in.data(), o, n, plain_rel_tol);
        }
        for (std::size_t r : again) c.stable->eval(in.data() + r * k, o + r * m);
    }
    return out;
}

}  // namespace

PYBIND11_MODULE(_symrep, m) {
    m.doc() = "symrep: exact solutions of dynamical systems by the algebraic methods (the compiled part)";
    m.attr("version") = SYMREP_VERSION;
    m.def("caret_text", &lang::caret_text, py::arg("line"), py::arg("column"),
          "The source line and a caret under the column, as symrep --caret prints them.");
    m.def("needs_more_input", &lang::needs_more_input, py::arg("text"),
          "True while the text has an open bracket or string: the statement goes on (syntax/lexer.h).");

    py::class_<session_state, state_ptr>(m, "Session", "A symrep language session (variables, symbols, results).")
        .def(py::init([] { return std::make_shared<session_state>(); }))
        .def("eval", [](const state_ptr& st, const std::string& code) { return eval(st, code); }, py::arg("code"),
             "Runs the statements of `code` and returns the value of the last one (None for a "
             "declaration); raises symrep.Error with the line and column at the first failure.")
        .def(
            "run",
            [](const state_ptr& st, const std::string& code, const std::string& name) {
                // the events of a cell in order: ("text", str), ("result", Value), ("file", path),
                // ("error", (message, file, line, column, source line)); stops at the first error
                std::vector<std::tuple<std::string, std::string, lang::value,
                                       lang::session::reported_error>> events;
                auto flush = [&] {
                    std::string t = st->out.str();
                    if (!t.empty()) events.push_back({"text", t, {}, {}});
                    st->out.str("");
                };
                auto& s = st->s;
                s.observe([&](const lang::value& v) { flush(), events.push_back({"result", "", v, {}}); },
                          [&](const lang::session::reported_error& e) { flush(), events.push_back({"error", "", {}, e}); },
                          [&](const std::string& path) { flush(), events.push_back({"file", path, {}, {}}); });
                const lang::output_options saved = s.options();
                s.options().stop_on_error = true;
                s.options().print_results = false;
                s.options().caret = false;
                {
                    interruptible guard;  // the GIL held, as in eval()
                    s.run_string(code, name);
                }
                flush();
                s.options() = saved;
                s.resume();
                s.observe({}, {}, {});
                st->err.str("");
                py::list out;
                for (auto& [kind, text, v, e] : events) {
                    if (kind == "text" || kind == "file") out.append(py::make_tuple(kind, text));
                    else if (kind == "result") out.append(py::make_tuple(kind, py_value{v, st}));
                    else
                        out.append(py::make_tuple(kind, py::make_tuple(e.message, e.where.file, e.where.line,
                                                                       e.where.column, e.source_line)));
                }
                return out;
            },
            py::arg("code"), py::arg("name") = "<cell>",
            "Runs a cell statement by statement, as the interactive prompt does, up to its first "
            "error; returns its events in order: ('text', printed text), ('result', Value), "
            "('file', path of a picture written), ('error', (message, file, line, column, source line)).")
        .def(
            "get",
            [](const state_ptr& st, const std::string& name) -> py::object {
                const lang::value* v = st->s.get(name);
                if (!v) return py::none();
                return py::cast(py_value{*v, st});
            },
            py::arg("name"), "The value of a variable, or None.")
        .def(
            "set",
            [](const state_ptr& st, const std::string& name, const py::object& x) {
                st->s.set(name, from_python(st, x));
            },
            py::arg("name"), py::arg("value"), "Assigns a variable (a Value, number, string or list).")
        .def("variables", [](const state_ptr& st) { return st->s.variable_names(); })
        .def(
            "call",
            [](const state_ptr& st, const std::string& name, const py::args& args) {
                std::vector<lang::value> a;
                for (const py::handle& x : args) a.push_back(from_python(st, x));
                return call(st, name, a);
            },
            py::arg("name"), "Calls a builtin with Python arguments: s.call('inverse', w).")
        .def(
            "completions",
            [](const state_ptr& st, const std::string& prefix, bool commands) {
                return lang::completions(st->s, prefix, commands);
            },
            py::arg("prefix"), py::arg("commands") = false, "The names a word may complete to (lang/help.h).")
        .def(
            "help",
            [](const state_ptr& st, const std::string& name) -> py::object {
                const std::string t = lang::help_text(st->s.builtins(), name);
                if (t.empty()) return py::none();
                return py::str(t);
            },
            py::arg("name"), "The help on a builtin (as ?name at the prompt), or None.")
        .def("unknown_builtin_message",
             [](const state_ptr& st, const std::string& name) {
                 return lang::unknown_builtin_message(st->s.builtins(), name);
             })
        .def("builtin_names",
             [](const state_ptr& st) {
                 std::vector<std::string> names;
                 for (const auto* b : st->s.builtins().all()) names.push_back(b->name);
                 return names;
             })
        .def(
            "compile",
            [](const state_ptr& st, const py_value& e, const std::vector<std::string>& inputs, const py::object& values,
               bool stable) { return compile(st, e, inputs, values, stable); },
            py::arg("expression"), py::arg("inputs"), py::arg("values") = py::none(), py::arg("stable") = false,
            "Compiles a closed form in the named inputs (scalars; a vector input is three "
            "columns), the other symbols given by `values` (name -> number, [x, y, z] or Value).");

    py::class_<py_value>(m, "Value", "A value of the symrep language.")
        .def_property_readonly("text", [](const py_value& v) { return lang::print_value(v.v, false); })
        .def_property_readonly("latex", [](const py_value& v) { return lang::latex_value(v.v); })
        .def_property_readonly("kind", [](const py_value& v) { return v.v.kind(); })
        .def_property_readonly("session", [](const py_value& v) { return v.state; }, "The session the value lives in.")
        .def("__str__", [](const py_value& v) { return lang::print_value(v.v, false); })
        .def("__repr__", [](const py_value& v) { return "symrep.Value(" + lang::print_value(v.v, true) + ")"; })
        .def("_repr_latex_", [](const py_value& v) { return "$" + lang::latex_value(v.v) + "$"; })
        .def("_number",
             [](const py_value& v) -> py::object {
                 // exact rationals as (numerator, denominator) strings, floats and complex as such
                 if (!v.v.is_ex() || !GiNaC::is_a<GiNaC::numeric>(v.v.as_ex())) return py::none();
                 const GiNaC::numeric x = GiNaC::ex_to<GiNaC::numeric>(v.v.as_ex());
                 auto str = [](const GiNaC::numeric& n) {
                     std::ostringstream o;
                     o << n;
                     return o.str();
                 };
                 if (x.is_rational())
                     return py::make_tuple("rational", str(x.numer()), str(x.denom()));
                 if (x.is_real()) return py::make_tuple("real", x.to_double());
                 const GiNaC::numeric re = x.real(), im = x.imag();
                 if (re.is_rational() && im.is_rational())
                     return py::make_tuple("gaussian", str(re.numer()), str(re.denom()), str(im.numer()),
                                           str(im.denom()));
                 return py::make_tuple("complex", re.to_double(), im.to_double());
             })
        .def("_items",
             [](const py_value& v) -> py::object {
                 if (!v.v.is_list()) return py::none();
                 py::list l;
                 for (const lang::value& x : v.v.as_list()) l.append(py_value{x, v.state});
                 return l;
             })
        .def("_bool", [](const py_value& v) -> py::object {
            if (!v.v.is_bool()) return py::none();
            return py::bool_(v.v.as_bool());
        })
        .def("_string", [](const py_value& v) -> py::object {
            if (!v.v.is_string()) return py::none();
            return py::str(v.v.as_string());
        })
        .def("_is_none", [](const py_value& v) { return v.v.is_none(); })
        .def("__add__", [](const py_value& a, const py::object& b) { return binary(a, b, "+", false); })
        .def("__radd__", [](const py_value& a, const py::object& b) { return binary(a, b, "+", true); })
        .def("__sub__", [](const py_value& a, const py::object& b) { return binary(a, b, "-", false); })
        .def("__rsub__", [](const py_value& a, const py::object& b) { return binary(a, b, "-", true); })
        .def("__mul__", [](const py_value& a, const py::object& b) { return binary(a, b, "*", false); })
        .def("__rmul__", [](const py_value& a, const py::object& b) { return binary(a, b, "*", true); })
        .def("__truediv__", [](const py_value& a, const py::object& b) { return binary(a, b, "/", false); })
        .def("__rtruediv__", [](const py_value& a, const py::object& b) { return binary(a, b, "/", true); })
        .def("__pow__", [](const py_value& a, const py::object& b) { return binary(a, b, "^", false); })
        .def("__rpow__", [](const py_value& a, const py::object& b) { return binary(a, b, "^", true); })
        .def("__neg__",
             [](const py_value& a) {
                 temporaries tmp(a.state);
                 return eval(a.state, "-(" + tmp(a.v) + ")", false);
             })
        .def("cross", [](const py_value& a, const py::object& b) { return binary(a, b, "x", false); },
             "The cross product a x b (vectors).")
        .def("dot", [](const py_value& a, const py::object& b) { return binary(a, b, ".", false); },
             "The dot product a . b (vectors).")
        .def("__eq__", [](const py_value& a, const py::object& b) -> py::object {
            // exact equality as the language decides it (==); an undecided comparison raises;
            // None and objects that are no values of the language are not equal
            if (b.is_none()) return py::bool_(false);
            lang::value other;
            try {
                other = from_python(a.state, b);
            } catch (const symrep::type_error&) {
                return py::bool_(false);  // a dict, an object: no value of the language equals it
            }
            temporaries tmp(a.state);
            const std::string x = tmp(a.v), y = tmp(other);
            const py_value r = eval(a.state, "(" + x + ") == (" + y + ")", false);
            if (!r.v.is_bool()) throw symrep::type_error("== gave " + r.v.a_kind() + ", not a boolean");
            return py::bool_(r.v.as_bool());
        })
        .def("__hash__", [](const py_value& v) { return py::hash(py::str(lang::print_value(v.v, true))); })
        .def(
            "call",
            [](const py_value& v, const std::string& name, const py::args& args) {
                std::vector<lang::value> a{v.v};
                for (const py::handle& x : args) a.push_back(from_python(v.state, x));
                return call(v.state, name, a);
            },
            py::arg("name"), "name(self, args...): v.call('inverse') is inverse(v).");

    py::class_<compiled>(m, "Compiled", "A closed form compiled to a flat double program (numeric/evaluator.h).")
        .def_property_readonly("inputs", [](const compiled& c) { return c.names; })
        .def_property_readonly("columns", [](const compiled& c) { return c.inputs; })
        .def_property_readonly("n_outputs", [](const compiled& c) { return c.n_outputs; })
        .def_property_readonly("n_instructions", [](const compiled& c) { return c.f.n_instructions(); })
        .def_property_readonly("expression", [](const compiled& c) { return c.text; })
        .def("listing", [](const compiled& c) { return c.f.listing(); })
        .def(
            "__call__", [](const compiled& c, const py::kwargs& kw) { return evaluate(c, kw, evaluation::checked); },
            "f(t=array, ...): the values at every point, n x n_outputs (n for one output), each output "
            "proved correct to 1e-6 relative by the double program's running error bound; points where "
            "the bound does not prove it are evaluated by the stable evaluator.")
        .def(
            "stable", [](const compiled& c, const py::kwargs& kw) { return evaluate(c, kw, evaluation::stable); },
            "The stable evaluator (numeric/stable_evaluator.h: error bounds, binary128 and exact "
            "tiers where double cancels), point by point: every output to 1e-14 relative.")
        .def(
            "unchecked",
            [](const compiled& c, const py::kwargs& kw) { return evaluate(c, kw, evaluation::unchecked); },
            "The bare double program (eval_many), fastest, with no accuracy check: where the closed "
            "form cancels, its values can be wrong in every digit.");

    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const symrep::error& e) {
            py::object error = py::module_::import("symrep").attr("Error");
            py::object x = error(e.what(), py::none(), py::none(), py::none(), py::none());
            PyErr_SetObject(error.ptr(), x.ptr());
        }
    });
}
