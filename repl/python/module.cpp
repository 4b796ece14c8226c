// repl/python/module.cpp -- symrep._symrep, the compiled part of the Python module `symrep`
// (docs/python.md). A thin layer over the language session (lang/interpreter.h), its value
// arithmetic and builtins (lang::binary_op, lang::negate, lang::values_equal, the registry's
// bodies), and the compiled evaluators (numeric/evaluator.h, numeric/stable_evaluator.h):
//
//   Session   runs statements: eval() returns the last value or raises symrep.Error with the
//             line and column; run() returns the events of a cell in order (text printed,
//             results, pictures written, the error) for front-ends such as the Jupyter kernel;
//             call() runs a builtin on values; completions() and help() are the interactive
//             prompt's (lang/help.h).
//   Value     a value of the language (expression, element, list, ...) with its text, LaTeX
//             and kind; Python's operators are the language's operators on the values, every
//             builtin is a method (v.inverse()); to_python(), float(), bool(), len(), [k]
//             and iteration convert where exact.
//   Compiled  a closed form compiled once, evaluated over NumPy arrays with the GIL released.
//
// The package's Python side (symrep/__init__.py) defines symrep.Error; symrep/_sympy.py
// reads a value into SymPy (Value.to_sympy).
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
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
#include "lang/statement_clock.h"
#include "lang/values.h"
#include "syntax/lexer.h"
#include "symrep/version.h"
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

// The user's statements: errors carry their line and column.
py_value eval(const state_ptr& st, const std::string& code) {
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
    if (!message.empty()) raise_error(message, file, line, column, source);
    return {std::move(v), st};
}

// An operation of the engine on values (an operator, a builtin's body), run as a statement
// runs (lang/statement_clock.h: Ctrl-C and the time limit stop it); its errors are
// symrep.Error without a place (the operation is the module's, not a line of the user's),
// with the message a statement gives (lang::message_of: symrep's verbatim, GiNaC's translated).
template <class F>
py_value engine_call(const state_ptr& st, F&& f) {
    lang::value v;
    std::string message;
    {
        interruptible guard;  // the GIL held, as in eval()
        std::chrono::steady_clock::time_point start;
        const lang::statement_clock clock(st->s.options().time_limit, start);
        try {
            v = f();
        } catch (const std::exception& e) {
            message = lang::message_of(e);
        } catch (...) {
            message = "unknown internal error";
        }
    }
    if (!message.empty()) raise_error(message, "", 0, 0, "");
    return {std::move(v), st};
}

// A Python argument as a language value: Value, bool, int, float, Fraction-like (numerator /
// denominator), str (a string value), list or tuple (a list).
GiNaC::numeric integer_from_python(const py::handle& x, bool& ok) {
    // str() of a Python int (or an integer type such as numpy's): an optional '-' and digits
    const std::string text = py::str(x).cast<std::string>();
    const std::size_t first = !text.empty() && text[0] == '-' ? 1 : 0;
    ok = text.size() > first && text.find_first_not_of("0123456789", first) == std::string::npos;
    return ok ? GiNaC::numeric(text.c_str()) : GiNaC::numeric(0);
}

lang::value from_python(const py::handle& x) {
    if (py::isinstance<py_value>(x)) return x.cast<const py_value&>().v;
    if (py::isinstance<py::bool_>(x)) return lang::value(x.cast<bool>());
    bool ok = false;
    if (py::isinstance<py::int_>(x)) return lang::value(GiNaC::ex(integer_from_python(x, ok)));
    if (py::isinstance<py::float_>(x)) {
        const double d = x.cast<double>();
        if (!std::isfinite(d)) throw symrep::type_error("not a finite number: " + py::repr(x).cast<std::string>());
        return lang::value(GiNaC::ex(GiNaC::numeric(d)));
    }
    if (py::hasattr(x, "numerator") && py::hasattr(x, "denominator") && !py::isinstance<py::str>(x)) {
        bool ok_d = false;
        const GiNaC::numeric n = integer_from_python(x.attr("numerator"), ok),
                             d = integer_from_python(x.attr("denominator"), ok_d);
        if (ok && ok_d) {
            if (d.is_zero()) throw symrep::domain_error("division by zero");
            return lang::value(GiNaC::ex(n / d));
        }
    }
    if (py::isinstance<py::str>(x)) return lang::value(x.cast<std::string>());
    if (py::isinstance<py::list>(x) || py::isinstance<py::tuple>(x)) {
        lang::list l;
        for (const py::handle& y : x) l.push_back(from_python(y));
        return lang::value(std::move(l));
    }
    throw symrep::type_error("cannot pass a Python " + py::str(x.get_type().attr("__name__")).cast<std::string>() +
                             " to symrep (numbers, strings, lists and symrep values only)");
}

// name(args...): the builtin's body on the values, after the checks the language makes of a
// call (lang/evaluate.cpp, session::call): the name (lang/help.h's message, with the names
// near it), the number of arguments (the same message as session::call's: the engine has no
// call on values of its own yet).
py_value call(const state_ptr& st, const std::string& name, const std::vector<lang::value>& args) {
    return engine_call(st, [&]() -> lang::value {
        const lang::builtin* b = st->s.builtins().find(name);
        if (!b) throw symrep::type_error(lang::unknown_builtin_message(st->s.builtins(), name));
        // ode reads its equation as written (x'' names a derivative), not as a value
        if (b->name == "ode")
            throw symrep::type_error(
                "ode: the equation and the initial conditions are read as written (x'' names a derivative), "
                "so a problem is made in a statement: s.eval(\"P := ode(...)\")");
        if (args.size() < b->min_args || args.size() > b->max_args) {
            std::string expected;
            if (b->min_args == b->max_args) expected = std::to_string(b->min_args);
            else if (b->max_args == SIZE_MAX) expected = "at least " + std::to_string(b->min_args);
            else expected = std::to_string(b->min_args) + " to " + std::to_string(b->max_args);
            throw symrep::type_error(b->name + ": expects " + expected + " argument" + (expected == "1" ? "" : "s") +
                                     ", got " + std::to_string(args.size()) + " (usage: " + b->signature + ")");
        }
        return b->fn(args, st->s);
    });
}

// a op b by the language's arithmetic (lang::binary_op), Python's operands in either order
py_value binary(const py_value& a, const py::object& b, const std::string& op, bool reflected) {
    const lang::value other = from_python(b);
    return engine_call(a.state, [&] {
        return reflected ? lang::binary_op(op, other, a.v) : lang::binary_op(op, a.v, other);
    });
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
            // the relations name = value, as the language makes them (vectors as [x, y, z]); the
            // name read as the language reads it (a symbol, or the value of a variable)
            const py::dict dv = values.cast<py::dict>();
            lang::list relations;
            for (const auto& [k, v] : dv) {
                const lang::value rhs = from_python(v);
                try {
                    relations.push_back(lang::binary_op("=", st->s.evaluate(k.cast<std::string>()), rhs));
                } catch (const symrep::error&) {
                    throw;
                } catch (const std::exception& e) {
                    throw symrep::error(lang::message_of(e));
                }
            }
            const lang::value vl(std::move(relations));
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

// --- Value's Python protocol (conversions, truth, lists, builtins as methods) -------

py::object python_int(const GiNaC::numeric& n) {
    std::ostringstream o;
    o << n;
    return py::module_::import("builtins").attr("int")(o.str());
}

py::object python_fraction(const GiNaC::numeric& q) {
    return py::module_::import("fractions").attr("Fraction")(python_int(q.numer()), python_int(q.denom()));
}

// the number as Python's exact or float number, or None when the value is no number
py::object python_number(const lang::value& v) {
    if (!v.is_ex() || !GiNaC::is_a<GiNaC::numeric>(v.as_ex())) return py::none();
    const GiNaC::numeric x = GiNaC::ex_to<GiNaC::numeric>(v.as_ex());
    if (x.is_integer()) return python_int(x);
    if (x.is_rational()) return python_fraction(x);
    if (x.is_real()) return py::float_(x.to_double());
    const GiNaC::numeric re = x.real(), im = x.imag();
    py::object complex = py::module_::import("builtins").attr("complex");
    if (re.is_rational() && im.is_rational()) return complex(python_fraction(re), python_fraction(im));
    return complex(re.to_double(), im.to_double());
}

py::object to_python(const py_value& v) {
    if (v.v.is_bool()) return py::bool_(v.v.as_bool());
    if (v.v.is_none()) return py::none();
    if (v.v.is_string()) return py::str(v.v.as_string());
    if (v.v.is_list()) {
        py::list l;
        for (const lang::value& x : v.v.as_list()) l.append(to_python(py_value{x, v.state}));
        return l;
    }
    py::object n = python_number(v.v);
    if (!n.is_none()) return n;
    throw py::type_error(v.v.kind() + " has no exact Python number form: " + lang::print_value(v.v, false) +
                         " (use .text, .latex or to_sympy())");
}

// float(v) for a real number, exact or not (evalf at the session's Digits)
double to_float(const py_value& v) {
    const bool number = v.v.is_ex() && GiNaC::is_a<GiNaC::numeric>(v.v.as_ex());
    const lang::value x = number ? v.v : call(v.state, "evalf", {v.v}).v;
    if (x.is_ex() && GiNaC::is_a<GiNaC::numeric>(x.as_ex()) && GiNaC::ex_to<GiNaC::numeric>(x.as_ex()).is_real()) {
        const GiNaC::numeric r = GiNaC::ex_to<GiNaC::numeric>(x.as_ex());
        // a rational correctly rounded, as Python's float(Fraction) does
        return r.is_rational() ? python_fraction(r).cast<double>() : r.to_double();
    }
    throw py::type_error("not a real number: " + lang::print_value(v.v, false));
}

bool to_bool(const py_value& v) {
    // only a boolean has a truth value: `if s.eval("check(P, r)"):` must not be true for false
    if (!v.v.is_bool())
        throw py::type_error("the truth value of a symrep " + v.v.kind() +
                             " is not defined (only booleans have one): " + lang::print_value(v.v, false));
    return v.v.as_bool();
}

// the entries of a list value as Values (Python's list semantics for len, [k], slices, iter)
py::list items(const py_value& v) {
    if (!v.v.is_list()) throw py::type_error("a symrep " + v.v.kind() + " is not a list");
    py::list l;
    for (const lang::value& x : v.v.as_list()) l.append(py_value{x, v.state});
    return l;
}

// v.name: the builtin name(v, ...) as a bound method, its help as the docstring
py::object builtin_method(const py_value& v, const std::string& name) {
    if (name.rfind("_", 0) == 0) throw py::attribute_error(name);
    if (!v.state->s.builtins().find(name))
        throw py::attribute_error("'" + name + "' is neither an attribute of a symrep value nor a builtin");
    const std::string help = lang::help_text(v.state->s.builtins(), name);
    py::options options;
    options.disable_function_signatures();
    return py::cpp_function(
        [v, name](const py::args& args) {
            std::vector<lang::value> a{v.v};
            for (const py::handle& x : args) a.push_back(from_python(x));
            return call(v.state, name, a);
        },
        py::name(name.c_str()), py::doc(help.empty() ? nullptr : help.c_str()));
}

std::vector<std::string> builtin_names(const state_ptr& st) {
    std::vector<std::string> names;
    for (const auto* b : st->s.builtins().all()) names.push_back(b->name);
    return names;
}

}  // namespace

PYBIND11_MODULE(_symrep, m) {
    m.doc() = "symrep: exact solutions of dynamical systems by the algebraic methods (the compiled part)";
    m.attr("version") = SYMREP_VERSION;
    m.def("caret_text", &lang::caret_text, py::arg("line"), py::arg("column"),
          "The source line and a caret under the column, as symrep --caret prints them.");
    m.def("needs_more_input", &lang::needs_more_input, py::arg("text"),
          "True while the text has an open bracket or string: the statement goes on (syntax/lexer.h).");

    // the three classes first, their methods after: every signature then names the classes
    // (symrep.Value, not the C++ type behind it)
    py::class_<session_state, state_ptr> session_class(m, "Session",
                                                       "A symrep language session (variables, symbols, results).");
    py::class_<py_value> value_class(
        m, "Value",
        "A value of the symrep language (expression, element, list, ...): .text, .latex, .kind, Python's "
        "operators, and every builtin as a method (v.inverse(), v.charpoly(X)); to_python() and to_sympy() "
        "convert where exact.");
    py::class_<compiled> compiled_class(m, "Compiled",
                                        "A closed form compiled to a flat double program (numeric/evaluator.h).");

    session_class
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
                st->s.set(name, from_python(x));
            },
            py::arg("name"), py::arg("value"), "Assigns a variable (a Value, number, string or list).")
        .def("variables", [](const state_ptr& st) { return st->s.variable_names(); }, "The names of the variables.")
        .def(
            "call",
            [](const state_ptr& st, const std::string& name, const py::args& args) {
                std::vector<lang::value> a;
                for (const py::handle& x : args) a.push_back(from_python(x));
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
        .def("builtin_names", &builtin_names, "The names of the builtins (each is also a method of Value).")
        .def(
            "compile",
            [](const state_ptr& st, const py::object& expression, const py::object& inputs, const py::object& values,
               bool stable) {
                // the closed form: a Value, or statements whose last value is one; the inputs: names
                const py_value e = py::isinstance<py::str>(expression) ? eval(st, expression.cast<std::string>())
                                                                       : expression.cast<py_value>();
                std::vector<std::string> names;
                if (py::isinstance<py::str>(inputs)) names.push_back(inputs.cast<std::string>());
                else
                    for (const py::handle& x : inputs) names.push_back(x.cast<std::string>());
                return compile(st, e, names, values, stable);
            },
            py::arg("expression"), py::arg("inputs"), py::arg("values") = py::none(), py::arg("stable") = false,
            "Compiles a closed form (a Value, or statements whose last value is one) in the named "
            "inputs (a name or a list of names: scalars; a vector input is three columns), the other "
            "symbols given by `values` (name -> number, [x, y, z] or Value); see Compiled.__call__.");

    value_class
        .def_property_readonly("text", [](const py_value& v) { return lang::print_value(v.v, false); })
        .def_property_readonly("latex", [](const py_value& v) { return lang::latex_value(v.v); })
        .def_property_readonly("kind", [](const py_value& v) { return v.v.kind(); })
        .def_property_readonly("session", [](const py_value& v) { return v.state; }, "The session the value lives in.")
        .def("__str__", [](const py_value& v) { return lang::print_value(v.v, false); })
        .def("__repr__", [](const py_value& v) { return "symrep.Value(" + lang::print_value(v.v, true) + ")"; })
        .def("_repr_latex_", [](const py_value& v) { return "$" + lang::latex_value(v.v) + "$"; })
        .def("to_python", &to_python,
             "The value as a Python object where that is exact: bool, int, fractions.Fraction, float (a "
             "floating-point value), complex, str, None, lists of these. A symbolic expression, an element or "
             "a problem raises TypeError (use .text, .latex, to_sympy()).")
        .def(
            "to_sympy",
            [](const py::object& self) { return py::module_::import("symrep._sympy").attr("to_sympy")(self); },
            "The value as a SymPy object, read from its printed form and checked exact: the engine compares "
            "the SymPy result printed back with the value (==) and refuses when they differ or cannot be "
            "compared. Lists give lists; vector expressions (x, ., |v|) and elements have no SymPy form here "
            "(TypeError).")
        .def("__bool__", &to_bool, "Only a boolean has a truth value (TypeError otherwise).")
        .def("__float__", &to_float, "float(v) for a real number, exact or not (evalf at the session's Digits).")
        .def("__len__", [](const py_value& v) { return py::len(items(v)); })
        .def("__getitem__",
             [](const py_value& v, const py::object& k) -> py::object {
                 const py::list l = items(v);
                 return l[k];  // Python's indexing: negative indices, slices, IndexError
             })
        .def("__iter__", [](const py_value& v) { return py::iter(items(v)); })
        .def("__getattr__", &builtin_method, py::arg("name"),
             "v.name(args...) is the builtin name(v, args...): v.inverse(), v.charpoly(X).")
        .def("__dir__",
             [](const py::object& self) {
                 // the attributes and every builtin: what an interactive prompt completes
                 py::list names = py::module_::import("builtins").attr("object").attr("__dir__")(self);
                 for (const std::string& n : builtin_names(self.cast<const py_value&>().state)) names.append(n);
                 return names;
             })
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
        .def("__neg__", [](const py_value& a) { return engine_call(a.state, [&] { return lang::negate(a.v); }); })
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
                other = from_python(b);
            } catch (const symrep::type_error&) {
                return py::bool_(false);  // a dict, an object: no value of the language equals it
            }
            const py_value r = engine_call(a.state, [&] { return lang::value(lang::values_equal(a.v, other)); });
            return py::bool_(r.v.as_bool());
        })
        .def("__hash__", [](const py_value& v) { return py::hash(py::str(lang::print_value(v.v, true))); })
        .def(
            "call",
            [](const py_value& v, const std::string& name, const py::args& args) {
                std::vector<lang::value> a{v.v};
                for (const py::handle& x : args) a.push_back(from_python(x));
                return call(v.state, name, a);
            },
            py::arg("name"), "name(self, args...): v.call('inverse') is inverse(v).");

    compiled_class
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
