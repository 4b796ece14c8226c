// repl/python/module.cpp -- symrep._symrep, the compiled part of the Python module `symrep`
// (docs/python.md). A thin layer over the language session (lang/interpreter.h), its value
// arithmetic and builtins (lang::binary_op, lang::negate, lang::values_equal, the registry's
// bodies), and the compiled evaluators (numeric/evaluator.h, numeric/stable_evaluator.h):
//
//   Session   runs statements: eval() returns the last value or raises symrep.Error (a subclass
//             per typed exception of the engine, error_class) with the line and column; run()
//             returns the events of a cell in order (text printed, results, pictures written,
//             the error) for front-ends such as the Jupyter kernel; call() runs a builtin on
//             values; completions() and help() are the interactive prompt's (lang/help.h).
//   Value     a value of the language (expression, element, list, ...) with its text, LaTeX
//             and kind; Python's operators are the language's operators on the values, every
//             builtin is a method (v.inverse(), made by symrep/_methods.py with the builtin's
//             help and signature); to_python(), float(), int(), abs(), bool(), len(), [k] and
//             iteration convert where exact; _tree() is the expression tree symrep/_sympy.py
//             walks; values pickle by their canonical text (symrep/_methods.py).
//   Compiled  a closed form compiled once, evaluated over NumPy arrays with the GIL released.
//
// Python arguments become values exactly (from_python: numbers, strings, lists, NumPy arrays);
// any other Python type raises Python's TypeError (an operator returns NotImplemented).
// The package's Python side (symrep/__init__.py) defines symrep.Error and its subclasses.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <csignal>
#include <cctype>
#include <cmath>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/interrupt.h"
#include "dual/dual.h"
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

// The class of symrep's Python exceptions (symrep/__init__.py) for an exception of the
// engine (core/error.h): syntax_error -> ParseError, zero_divisor_error -> ZeroDivisorError,
// domain_error -> DomainError (UndecidedError where the engine says it cannot decide, the
// message every undecided zero test, sign or convergence gives), type_error ->
// LanguageTypeError, ...; the interruption and the time limit by their messages
// (core/interrupt.h); GiNaC's division by zero and poles by their types.
std::string error_class(const std::exception_ptr& p, const std::string& message) {
    const auto interrupted_or = [&](const char* other) -> std::string {
        if (message == "interrupted") return "Interrupted";
        if (message.rfind("time limit", 0) == 0) return "TimeLimitError";
        return other;
    };
    if (!p) return interrupted_or("Error");
    try {
        std::rethrow_exception(p);
    } catch (const symrep::syntax_error&) {
        return "ParseError";
    } catch (const symrep::zero_divisor_error&) {
        return "ZeroDivisorError";
    } catch (const symrep::algebra_error&) {
        return "AlgebraError";
    } catch (const symrep::domain_error&) {
        if (message.find("division by zero") != std::string::npos) return "DivisionByZeroError";
        return message.find("cannot decide") != std::string::npos ? "UndecidedError" : "DomainError";
    } catch (const symrep::type_error&) {
        return "LanguageTypeError";
    } catch (const symrep::size_error&) {
        return "SizeError";
    } catch (const symrep::closed_form_error&) {
        return "ClosedFormError";
    } catch (const symrep::internal_error&) {
        return "InternalError";
    } catch (const lang::script_error& e) {
        return error_class(e.original, message);
    } catch (const std::bad_alloc&) {  // Ctrl-C or the time limit inside a library call, or no memory
        return interrupted_or("SizeError");
    } catch (const symrep::error&) {
        return interrupted_or("Error");
    } catch (const std::exception&) {
        // GiNaC's: 1/0 (numeric::div, power::eval), a pole (tan(pi/2)), log(0)
        if (message == "division by zero") return "DivisionByZeroError";
        try {
            std::rethrow_exception(p);
        } catch (const std::domain_error&) {
            return "DomainError";
        } catch (...) {
        }
        return interrupted_or("Error");
    } catch (...) {
        return "Error";
    }
}

// The exception symrep.<cls>(message, file, line, column, source line); no place when line is 0.
py::object error_object(const std::string& cls, const std::string& message, const std::string& file, int line,
                        int column, const std::string& source_line, const std::exception_ptr& p = nullptr) {
    // the bytes the program prints (lang::reported_message: long numbers shortened, controls escaped)
    const std::string shown = lang::reported_message(message);
    py::object error = py::module_::import("symrep").attr(cls.c_str());
    py::object e = line > 0 ? error(shown, file, line, column, source_line)
                            : error(shown, py::none(), py::none(), py::none(), py::none());
    if (p) try {
            std::rethrow_exception(p);
        } catch (const symrep::zero_divisor_error& z) {
            e.attr("ranks") = py::cast(z.ranks);  // the vanishing idempotent components (III.1.55)
        } catch (...) {
        }
    return e;
}

// Raises error_object(...).
[[noreturn]] void raise_error(const std::string& cls, const std::string& message, const std::string& file, int line,
                              int column, const std::string& source_line, const std::exception_ptr& p = nullptr) {
    py::object e = error_object(cls, message, file, line, column, source_line, p);
    PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(e.ptr())), e.ptr());
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
    std::exception_ptr what;
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
            what = e.original;
        } catch (const std::bad_alloc& e) {
            message = allocation_failure_message(e, "out of memory");
            what = std::current_exception();
        } catch (const std::exception& e) {
            message = e.what();
            what = std::current_exception();
        }
    }
    if (!message.empty()) raise_error(error_class(what, message), message, file, line, column, source, what);
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
    std::exception_ptr what;
    {
        interruptible guard;  // the GIL held, as in eval()
        std::chrono::steady_clock::time_point start;
        const lang::statement_clock clock(st->s.options().time_limit, start);
        try {
            v = f();
        } catch (const py::error_already_set&) {
            throw;  // a Python error (a wrong Python type among the arguments) stays Python's
        } catch (const py::builtin_exception&) {
            throw;
        } catch (const std::exception& e) {
            message = lang::message_of(e);
            what = std::current_exception();
        } catch (...) {
            message = "unknown internal error";
        }
    }
    if (!message.empty()) raise_error(error_class(what, message), message, "", 0, 0, "", what);
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

// NumPy's arrays and scalars (anything with dtype and tolist()) read as the Python lists and
// numbers tolist() gives: an array is a list value (nested for n-D), a float64 the double it is
bool numpy_like(const py::handle& x) {
    return py::hasattr(x, "dtype") && py::hasattr(x, "tolist") && py::hasattr(x, "ndim");
}

lang::value from_python(const py::handle& x) {
    if (py::isinstance<py_value>(x)) return x.cast<const py_value&>().v;
    if (py::isinstance<py::bool_>(x)) return lang::value(x.cast<bool>());
    bool ok = false;
    if (py::isinstance<py::int_>(x)) return lang::value(GiNaC::ex(integer_from_python(x, ok)));
    if (py::isinstance<py::float_>(x)) {
        const double d = x.cast<double>();
        if (!std::isfinite(d)) throw py::value_error("not a finite number: " + py::repr(x).cast<std::string>());
        return lang::value(GiNaC::ex(GiNaC::numeric(d)));
    }
    if (numpy_like(x)) {
        const py::object kind = x.attr("dtype").attr("kind");
        const std::string k = py::str(kind).cast<std::string>();
        if (k.size() != 1 || std::string("biuf").find(k[0]) == std::string::npos)
            throw py::type_error("cannot pass a NumPy array of dtype " + py::str(x.attr("dtype")).cast<std::string>() +
                                 " to symrep (booleans, integers and floats only)");
        return from_python(x.attr("tolist")());
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
    // a wrong Python type is Python's TypeError, as for any Python function
    throw py::type_error("cannot pass a Python " + py::str(x.get_type().attr("__name__")).cast<std::string>() +
                         " to symrep (numbers, strings, lists, NumPy arrays and symrep values only)");
}

// from_python, or nullopt for an object that is no value of the language (an operator then
// returns NotImplemented: Python tries the other operand, then raises its TypeError)
std::optional<lang::value> try_from_python(const py::handle& x) {
    try {
        return from_python(x);
    } catch (const py::type_error&) {
        return std::nullopt;
    }
}

// name(args...): the builtin's body on the values, after the checks the language makes of a
// call (lang/evaluate.cpp, session::call): the name (lang/help.h's message, with the names
// near it), the number of arguments (the same message as session::call's: the engine has no
// call on values of its own yet).
// name(args..., option = value...): the options (view = "3d") as the language passes them to a
// builtin that declares them (lang::builtin::options, context::named_options)
py_value call(const state_ptr& st, const std::string& name, const std::vector<lang::value>& args,
              const std::vector<std::pair<std::string, lang::value>>& options = {}) {
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
        for (const auto& o : options)
            if (std::find(b->options.begin(), b->options.end(), o.first) == b->options.end()) {
                std::string known;
                for (const std::string& k : b->options) known += (known.empty() ? "" : ", ") + k;
                throw symrep::type_error(b->name + ": no option " + o.first +
                                         (known.empty() ? " (it takes none)" : " (its options: " + known + ")"));
            }
        struct options_scope {  // as lang::session::call_builtin: the options of this call only
            lang::context& c;
            std::vector<std::pair<std::string, lang::value>> saved;
            ~options_scope() { c.named_options = std::move(saved); }
        } scope{st->s, std::move(st->s.named_options)};
        st->s.named_options = options;
        return lang::reduce_dual(b->fn(args, st->s));  // as session::call: dual values reduced mod eps^2
    });
}

// the keyword arguments of s.call / v.call as named options
std::vector<std::pair<std::string, lang::value>> options_of(const py::kwargs& kwargs) {
    std::vector<std::pair<std::string, lang::value>> o;
    for (const auto& [k, x] : kwargs) o.emplace_back(py::str(k).cast<std::string>(), from_python(x));
    return o;
}

// a op b by the language's arithmetic (lang::binary_op), Python's operands in either order;
// NotImplemented for an operand that is no value of the language
py::object binary(const py_value& a, const py::object& b, const std::string& op, bool reflected) {
    const std::optional<lang::value> other = try_from_python(b);
    if (!other) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
    return py::cast(engine_call(a.state, [&] {
        return reflected ? lang::binary_op(op, *other, a.v) : lang::binary_op(op, a.v, *other);
    }));
}

// a.cross(b), a.dot(b): as binary, a TypeError for an operand that is no value of the language
py_value binary_method(const py_value& a, const py::object& b, const std::string& op) {
    const std::optional<lang::value> other = try_from_python(b);
    if (!other) from_python(b);  // raises the TypeError naming the type
    return engine_call(a.state, [&] { return lang::binary_op(op, a.v, *other); });
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

// A value or an input for `name`: the closed form (or another value) must have the symbol; a
// name it does not have is a typo, not a no-op (the error names it and the form's symbols).
void check_value_name(const GiNaC::ex& name, const std::vector<GiNaC::ex>& forms, const lang::data_values& d,
                      bool input = false) {
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
    throw symrep::type_error("compile: " +
                             (input ? "the input '" + num::symbol_name(name) + "' is not a symbol of the closed form"
                                    : "a value is given for '" + num::symbol_name(name) +
                                          "', which the closed form does not have") +
                             " (its symbols: " + (list.empty() ? std::string("none") : list) + ")");
}

compiled compile(const state_ptr& st, const py_value& e, const std::vector<std::string>& inputs,
                 const py::dict& values, bool stable) {
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
        raise_error("LanguageTypeError",
                    "compile: the closed form must be an expression or a list of them, not " + e.v.a_kind(), "", 0, 0,
                    "");
    compiled c;
    std::string message;
    std::exception_ptr what;
    try {
        lang::data_values d;
        if (!values.empty()) {
            // the relations name = value, as the language makes them (vectors as [x, y, z]); the
            // name read as the language reads it (a symbol, or the value of a variable)
            lang::list relations;
            for (const auto& [k, v] : values) {
                const lang::value rhs = from_python(v);
                try {
                    if (!py::isinstance<py::str>(k))
                        throw py::type_error("compile: the names of values are strings, not " +
                                             py::str(k.get_type().attr("__name__")).cast<std::string>());
                    relations.push_back(lang::binary_op("=", st->s.evaluate(k.cast<std::string>()), rhs));
                } catch (const symrep::error&) {
                    throw;
                } catch (const py::builtin_exception&) {
                    throw;
                } catch (const std::exception& failure) {
                    throw symrep::error(lang::message_of(failure));
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
            check_value_name(sym, forms, d, true);
            if (std::find(c.names.begin(), c.names.end(), name) != c.names.end())
                throw symrep::type_error("compile: the input '" + name + "' is named twice");
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
    } catch (const py::builtin_exception&) {
        throw;  // a wrong Python type: Python's TypeError
    } catch (const py::error_already_set&) {
        throw;
    } catch (const std::exception& ex) {
        message = ex.what();
        what = std::current_exception();
    }
    if (!message.empty())
        raise_error(error_class(what, message), message.rfind("compile: ", 0) == 0 ? message : "compile: " + message,
                    "", 0, 0, "", what);
    return c;
}

// f(**arrays): every input a scalar or an array of n values (vectors: n x 3 or 3); the result
// n x n_outputs (n_outputs == 1: a vector of n values).
// How f(...) evaluates: checked (the default), the stable evaluator, or the bare double program.
enum class evaluation { checked, stable, unchecked };

// The accuracy the checked path proves for every output (relative to its value); docs/python.md.
constexpr double plain_rel_tol = 1e-6;

py::array_t<double> evaluate(const compiled& c, const py::args& args, const py::kwargs& given, evaluation mode) {
    // the inputs by position (in the order of c.inputs) and by name, as a Python function takes them
    if (args.size() > c.names.size())
        throw py::type_error("takes " + std::to_string(c.names.size()) + " input" + (c.names.size() == 1 ? "" : "s") +
                             " but " + std::to_string(args.size()) + " were given by position");
    py::dict kw;
    for (const auto& [key, x] : given) kw[key] = x;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (kw.contains(c.names[i].c_str()))
            throw py::type_error("got multiple values for input '" + c.names[i] + "'");
        kw[c.names[i].c_str()] = args[i];
    }
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

// v.name: the builtin name(v, ...) as a bound method, made by symrep._methods (a Python
// function with the builtin's signature and its help as the docstring: help(v.inverse))
py::object builtin_method(const py::object& self, const std::string& name) {
    const py_value& v = self.cast<const py_value&>();
    if (name.rfind("_", 0) == 0) throw py::attribute_error(name);
    if (!v.state->s.builtins().find(name))
        throw py::attribute_error("'" + name + "' is neither an attribute of a symrep value nor a builtin");
    return py::module_::import("symrep._methods").attr("bound_builtin")(self, name);
}

// (signature, help text, min_args, max_args (-1: any number), option names) of a builtin, or None
py::object builtin_info(const state_ptr& st, const std::string& name) {
    const lang::builtin* b = st->s.builtins().find(name);
    if (!b) return py::none();
    return py::make_tuple(b->signature, lang::help_text(st->s.builtins(), name), b->min_args,
                          b->max_args == SIZE_MAX ? -1 : py::ssize_t(b->max_args), b->options);
}

// The expression tree of a value for symrep._sympy (a walk, not a printed text): nested tuples
//   ("integer", int) ("rational", p, q) ("float", text, digits) ("complex", re, im)
//   ("symbol", name, assumption: "real"/"positive"/"complex") ("constant", name)
//   ("add", [..]) ("mul", [..]) ("power", b, e) ("function", name, [..]) ("relation", op, l, r)
//   ("matrix", rows, cols, [entries row by row]) ("list", [..]) ("boolean", b) ("string", s)
//   ("vector", what: a vector symbol or an operation on vectors, its text)
//   ("other", kind, text): no counterpart (an element, an algebra, a GiNaC object unknown here)
py::object tree_of_ex(const GiNaC::ex& e);

py::object tree_of_numeric(const GiNaC::numeric& x) {
    if (x.is_integer()) return py::make_tuple("integer", python_int(x));
    if (x.is_rational()) return py::make_tuple("rational", python_int(x.numer()), python_int(x.denom()));
    if (x.is_real()) {
        std::ostringstream o;
        o << x;  // CLN's decimal text of the float, every digit it holds
        return py::make_tuple("float", o.str(), long(GiNaC::Digits));
    }
    return py::make_tuple("complex", tree_of_numeric(x.real()), tree_of_numeric(x.imag()));
}

py::object tree_of_ex(const GiNaC::ex& e) {
    const auto kids = [&] {
        py::list l;
        for (std::size_t i = 0; i < e.nops(); ++i) l.append(tree_of_ex(e.op(i)));
        return l;
    };
    if (is_vector_symbol(e)) return py::make_tuple("vector", "a vector", lang::print_value(lang::value(e), false));
    if (GiNaC::is_a<GiNaC::numeric>(e)) return tree_of_numeric(GiNaC::ex_to<GiNaC::numeric>(e));
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
        const char* a = e.info(GiNaC::info_flags::positive) ? "positive" : e.info(GiNaC::info_flags::real) ? "real" : "complex";
        return py::make_tuple("symbol", GiNaC::ex_to<GiNaC::symbol>(e).get_name(), a);
    }
    if (GiNaC::is_a<GiNaC::constant>(e)) {
        std::ostringstream o;
        o << e;
        return py::make_tuple("constant", o.str());
    }
    if (GiNaC::is_a<GiNaC::add>(e)) return py::make_tuple("add", kids());
    if (GiNaC::is_a<GiNaC::mul>(e)) return py::make_tuple("mul", kids());
    if (GiNaC::is_a<GiNaC::power>(e)) return py::make_tuple("power", tree_of_ex(e.op(0)), tree_of_ex(e.op(1)));
    if (GiNaC::is_a<GiNaC::function>(e)) return py::make_tuple("function", GiNaC::ex_to<GiNaC::function>(e).get_name(), kids());
    if (GiNaC::is_a<GiNaC::relational>(e)) {
        const GiNaC::relational& r = GiNaC::ex_to<GiNaC::relational>(e);
        const char* op = r.info(GiNaC::info_flags::relation_equal)           ? "="
                         : r.info(GiNaC::info_flags::relation_not_equal)     ? "!="
                         : r.info(GiNaC::info_flags::relation_less)          ? "<"
                         : r.info(GiNaC::info_flags::relation_less_or_equal) ? "<="
                         : r.info(GiNaC::info_flags::relation_greater)       ? ">"
                                                                      : ">=";
        return py::make_tuple("relation", op, tree_of_ex(r.lhs()), tree_of_ex(r.rhs()));
    }
    if (GiNaC::is_a<GiNaC::matrix>(e)) {
        const GiNaC::matrix& m = GiNaC::ex_to<GiNaC::matrix>(e);
        py::list entries;
        for (unsigned i = 0; i < m.rows(); ++i)
            for (unsigned j = 0; j < m.cols(); ++j) entries.append(tree_of_ex(m(i, j)));
        return py::make_tuple("matrix", m.rows(), m.cols(), entries);
    }
    return py::make_tuple("other", GiNaC::ex_to<GiNaC::basic>(e).class_name(), lang::print_value(lang::value(e), false));
}

py::object tree_of(const lang::value& v) {
    if (v.is_bool()) return py::make_tuple("boolean", v.as_bool());
    if (v.is_string()) return py::make_tuple("string", v.as_string());
    if (v.is_list()) {
        py::list l;
        for (const lang::value& x : v.as_list()) l.append(tree_of(x));
        return py::make_tuple("list", l);
    }
    if (v.is_ex()) {
        // a dual quantity (eps^2 = 0, dual/dual.h) has none either: SymPy's eps would square to eps^2
        if (dual::has_dual_unit(v.as_ex())) return py::make_tuple("dual", lang::print_value(v, false));
        // a vector expression (x, ., |v|) has no SymPy counterpart: named as a whole
        for (auto it = v.as_ex().preorder_begin(); it != v.as_ex().preorder_end(); ++it)
            if (is_vector_symbol(*it))
                return py::make_tuple("vector", "a vector expression", lang::print_value(v, false));
        return tree_of_ex(v.as_ex());
    }
    return py::make_tuple("other", v.kind(), lang::print_value(v, false));
}

// The declarations a value's canonical text needs to be read back (pickling): its vector
// symbols and its positive symbols, sorted by name
py::tuple declarations_of(const lang::value& v) {
    std::set<std::string> vectors, positives;
    std::function<void(const lang::value&)> walk = [&](const lang::value& x) {
        if (x.is_list())
            for (const lang::value& y : x.as_list()) walk(y);
        if (!x.is_ex()) return;
        for (auto it = x.as_ex().preorder_begin(); it != x.as_ex().preorder_end(); ++it) {
            if (!GiNaC::is_a<GiNaC::symbol>(*it)) continue;
            const std::string n = GiNaC::ex_to<GiNaC::symbol>(*it).get_name();
            if (is_vector_symbol(*it)) vectors.insert(n);
            else if (it->info(GiNaC::info_flags::positive)) positives.insert(n);
        }
    };
    walk(v);
    return py::make_tuple(std::vector<std::string>(vectors.begin(), vectors.end()),
                          std::vector<std::string>(positives.begin(), positives.end()));
}

// int(v), operator.index(v): an exact integer only (a non-integer number: ValueError, as
// int("2.5"); no number: TypeError)
py::object to_int(const py_value& v) {
    if (v.v.is_ex() && GiNaC::is_a<GiNaC::numeric>(v.v.as_ex())) {
        const GiNaC::numeric x = GiNaC::ex_to<GiNaC::numeric>(v.v.as_ex());
        if (x.is_integer()) return python_int(x);
        throw py::value_error("not an integer: " + lang::print_value(v.v, false) +
                              " (int() of a symrep value is exact; use float(), math.floor or round)");
    }
    throw py::type_error("int() of a symrep " + v.v.kind() + " that is no integer: " + lang::print_value(v.v, false));
}

std::vector<std::string> builtin_names(const state_ptr& st) {
    std::vector<std::string> names;
    for (const auto* b : st->s.builtins().all()) names.push_back(b->name);
    return names;
}

}  // namespace

void bind_progress(py::module_& m);  // progress.cpp: ProgressScope, ProgressReport (core/progress.h)

PYBIND11_MODULE(_symrep, m) {
    bind_progress(m);
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
             "Runs the statements of `code` (the symrep language, docs/language.md) and returns the value of "
             "the last one (None for a declaration); at the first failure raises symrep.Error (ParseError, "
             "ZeroDivisorError, DomainError, UndecidedError, LanguageTypeError, ...) with the line and column "
             "and the message the symrep program prints. The reference of a function, as `symrep --doc` and "
             "`help name` show it: s.help(name), or help(v.name) on a value v.")
        .def(
            "run",
            [](const state_ptr& st, const std::string& code, const std::string& name) {
                // the events of a cell in order: ("text", str), ("result", Value), ("file", path),
                // ("error", the symrep.Error subclass eval would raise); stops at the first error
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
                        // the exception Session.eval would raise (its class from the engine's type)
                        out.append(py::make_tuple(kind, error_object(error_class(e.original, e.message), e.message,
                                                                     e.where.file, e.where.line, e.where.column,
                                                                     e.source_line, e.original)));
                }
                return out;
            },
            py::arg("code"), py::arg("name") = "<cell>",
            "Runs a cell statement by statement, as the interactive prompt does, up to its first "
            "error; returns its events in order: ('text', printed text), ('result', Value), "
            "('file', path of a picture written), ('error', the symrep.Error (subclass) Session.eval would raise, "
            "with .message, .file, .line, .column, .source_line).")
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
            [](const state_ptr& st, const std::string& name, const py::args& args, const py::kwargs& kwargs) {
                std::vector<lang::value> a;
                for (const py::handle& x : args) a.push_back(from_python(x));
                return call(st, name, a, options_of(kwargs));
            },
            py::arg("name"),
            "Calls a builtin with Python arguments: s.call('inverse', w); keyword arguments are the "
            "builtin's options: s.call('trajectory', r, values, t, 'r.svg', view='3d').")
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
        .def("_builtin_info", &builtin_info, py::arg("name"),
             "(signature, help text, min_args, max_args or -1) of a builtin, or None (symrep._methods).")
        .def_property(
            "time_limit", [](const state_ptr& st) { return st->s.options().time_limit; },
            [](const state_ptr& st, double seconds) {
                if (!(seconds >= 0) || !std::isfinite(seconds))
                    throw py::value_error("time_limit: seconds >= 0 (0: no limit)");
                st->s.options().time_limit = seconds;
            },
            "Seconds a statement (eval, an operator, a builtin call) may run, 0 for no limit (the program's "
            "--time-limit); past it symrep.TimeLimitError.")
        .def(
            "value", [](const state_ptr& st, const py::object& x) { return py_value{from_python(x), st}; },
            py::arg("x"),
            "The Python object as a Value of this session: bool, int, Fraction, float, str, list, tuple, "
            "NumPy array (a list) or Value (TypeError for anything else).")
        .def(
            "symbol",
            [](const state_ptr& st, const std::string& name) {
                // a name the language reads as a symbol: letters, digits, _; no keyword or builtin constant
                bool ok = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0]));
                for (const char ch : name) ok = ok && (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_');
                for (const char* k : {"vector", "positive", "true", "false", "pi", "I", "eps"}) ok = ok && name != k;
                if (!ok)
                    throw py::value_error("not a name of the symrep language: " + py::repr(py::str(name)).cast<std::string>());
                return py_value{lang::value(st->s.symbol(name)), st};
            },
            py::arg("name"),
            "The session's symbol of that name (real; positive once declared `positive`), even where a "
            "variable of that name has a value (s.eval(name) gives the value).")
        .def(
            "compile",
            [](const state_ptr& st, const py::object& expression, const py::args& args, const py::kwargs& kw) {
                // compile(expression, inputs=(), values=None, stable=False, **parameter values): the
                // inputs a name, a list of names or several names by position; the values a dict
                // and/or keywords (name=value); stable=True accepted for compatibility
                const py_value e = py::isinstance<py::str>(expression) ? eval(st, expression.cast<std::string>())
                                  : py::isinstance<py_value>(expression)
                                      ? expression.cast<py_value>()
                                      : py_value{from_python(expression), st};
                std::vector<std::string> names;
                py::dict values;
                bool stable = false, have_inputs = false, have_values = false, have_stable = false;
                const auto add_names = [&](const py::handle& x) {
                    if (py::isinstance<py::str>(x)) return names.push_back(x.cast<std::string>());
                    if (!py::isinstance<py::list>(x) && !py::isinstance<py::tuple>(x))
                        throw py::type_error("compile: the inputs are names (str) or a list of names, not " +
                                             py::str(x.get_type().attr("__name__")).cast<std::string>());
                    for (const py::handle& y : x) {
                        if (!py::isinstance<py::str>(y))
                            throw py::type_error("compile: an input is a name (str), not " +
                                                 py::str(y.get_type().attr("__name__")).cast<std::string>());
                        names.push_back(y.cast<std::string>());
                    }
                };
                const auto add_values = [&](const py::handle& x) {
                    if (x.is_none()) return;
                    if (!py::isinstance<py::dict>(x))
                        throw py::type_error("compile: the values are a dict (name -> value), not " +
                                             py::str(x.get_type().attr("__name__")).cast<std::string>());
                    for (const auto& [k, v] : py::reinterpret_borrow<py::dict>(x)) values[k] = v;
                };
                for (const py::handle& x : args) {
                    if (!have_values && !have_stable && (py::isinstance<py::str>(x) ||
                                                         (!have_inputs && (py::isinstance<py::list>(x) ||
                                                                           py::isinstance<py::tuple>(x))))) {
                        add_names(x), have_inputs = true;
                    } else if (!have_values && !have_stable && (x.is_none() || py::isinstance<py::dict>(x))) {
                        add_values(x), have_values = true;
                    } else if (!have_stable && py::isinstance<py::bool_>(x)) {
                        stable = x.cast<bool>(), have_stable = true;
                    } else {
                        throw py::type_error("compile: unexpected argument " + py::repr(x).cast<std::string>() +
                                             " (compile(expression, inputs, values, **parameter values))");
                    }
                }
                for (const auto& [key, x] : kw) {
                    const std::string k = key.cast<std::string>();
                    if (k == "inputs") {
                        if (have_inputs) throw py::type_error("compile: the inputs are given twice");
                        add_names(x), have_inputs = true;
                    } else if (k == "values") {
                        if (have_values) throw py::type_error("compile: the values are given twice");
                        add_values(x), have_values = true;
                    } else if (k == "stable") {
                        stable = x.cast<bool>();
                    }
                }
                for (const auto& [key, x] : kw) {
                    const std::string k = key.cast<std::string>();
                    if (k == "inputs" || k == "values" || k == "stable") continue;
                    if (values.contains(key)) throw py::type_error("compile: a value for '" + k + "' is given twice");
                    values[key] = x;
                }
                return compile(st, e, names, values, stable);
            },
            py::arg("expression"),
            "compile(expression, inputs=(), values=None, **parameters) -> Compiled\n\n"
            "Compiles a closed form (a Value, or statements whose last value is one) in the named "
            "inputs (a name, a list of names, or several names by position: scalars; a vector input is "
            "three columns), the other symbols given by `values` (a dict name -> number, [x, y, z], NumPy "
            "array or Value) and/or by keywords: s.compile(r, 't', w0=0.38, w=[0, 0, 7.29e-5]). A name "
            "that is no symbol of the closed form raises symrep.LanguageTypeError (a TypeError) naming "
            "it. See Compiled.__call__.");

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
            "The value as a SymPy object by a walk of its expression tree (symrep/_sympy.py): numbers, "
            "symbols (real, or positive as declared), +, *, ^, the elementary functions, relations, "
            "matrices and vector literals (sympy.Matrix), lists (Python lists). What has no SymPy "
            "counterpart (a vector expression x, ., |v|, an element, an algebra, a function SymPy lacks) "
            "raises TypeError naming it.")
        .def(
            "_sympy_",
            [](const py::object& self) { return py::module_::import("symrep._sympy").attr("to_sympy")(self); },
            "sympy.sympify(v): the same as v.to_sympy().")
        .def(
            "_op",
            [](const py_value& a, const std::string& op, const py::object& b) {
                return binary_method(a, b, op);
            },
            py::arg("op"), py::arg("other"), "a op b by the language's arithmetic (op: + - * / ^ = x .).")
        .def("_tree", [](const py_value& v) { return tree_of(v.v); },
             "The expression tree as nested tuples (for symrep._sympy; see module.cpp, tree_of).")
        .def("_declarations", [](const py_value& v) { return declarations_of(v.v); },
             "(vector symbols, positive symbols) of the value, sorted: what its text needs to be read back.")
        .def("__reduce__",
             [](const py::object& self) {
                 return py::module_::import("symrep._methods").attr("reduce_value")(self);
             },
             "Pickling: the canonical text, the kind and the declarations the text needs; see "
             "symrep.restore_session.")
        .def("__abs__", [](const py_value& v) { return call(v.state, "abs", {v.v}); }, "abs(v): the builtin abs.")
        .def("__int__", &to_int, "int(v) for an exact integer (ValueError for another number, TypeError else).")
        .def("__index__", &to_int, "operator.index(v) for an exact integer.")
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
        .def("cross", [](const py_value& a, const py::object& b) { return binary_method(a, b, "x"); },
             py::arg("other"), "The cross product a x b (vectors).")
        .def("dot", [](const py_value& a, const py::object& b) { return binary_method(a, b, "."); },
             py::arg("other"), "The dot product a . b (vectors).")
        .def("__eq__", [](const py_value& a, const py::object& b) -> py::object {
            // exact equality as the language decides it (==); an undecided comparison raises;
            // None and objects that are no values of the language are not equal
            if (b.is_none()) return py::bool_(false);
            const std::optional<lang::value> other = try_from_python(b);
            // a dict, an object: no value of the language equals it (a SymPy object: SymPy's ==)
            if (!other) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
            const py_value r = engine_call(a.state, [&] { return lang::value(lang::values_equal(a.v, *other)); });
            return py::bool_(r.v.as_bool());
        })
        .def("__hash__", [](const py_value& v) { return py::hash(py::str(lang::print_value(v.v, true))); })
        .def(
            "call",
            [](const py_value& v, const std::string& name, const py::args& args, const py::kwargs& kwargs) {
                std::vector<lang::value> a{v.v};
                for (const py::handle& x : args) a.push_back(from_python(x));
                return call(v.state, name, a, options_of(kwargs));
            },
            py::arg("name"),
            "name(self, args..., option=value...): v.call('inverse') is inverse(v); keyword "
            "arguments are the builtin's options (view='3d').");

    compiled_class
        .def_property_readonly("inputs", [](const compiled& c) { return c.names; })
        .def_property_readonly("columns", [](const compiled& c) { return c.inputs; })
        .def_property_readonly("n_outputs", [](const compiled& c) { return c.n_outputs; })
        .def_property_readonly("n_instructions", [](const compiled& c) { return c.f.n_instructions(); })
        .def_property_readonly("expression", [](const compiled& c) { return c.text; })
        .def("listing", [](const compiled& c) { return c.f.listing(); })
        .def(
            "__call__",
            [](const compiled& c, const py::args& a, const py::kwargs& kw) {
                return evaluate(c, a, kw, evaluation::checked);
            },
            "f(t_array, ...) or f(t=array, ...) (the inputs by position in the order of .inputs, or by name): the values at every point, n x n_outputs (n for one output), each output "
            "proved correct to 1e-6 relative by the double program's running error bound; points where "
            "the bound does not prove it are evaluated by the stable evaluator.")
        .def(
            "stable",
            [](const compiled& c, const py::args& a, const py::kwargs& kw) {
                return evaluate(c, a, kw, evaluation::stable);
            },
            "The stable evaluator (numeric/stable_evaluator.h: error bounds, binary128 and exact "
            "tiers where double cancels), point by point: every output to 1e-14 relative.")
        .def(
            "unchecked",
            [](const compiled& c, const py::args& a, const py::kwargs& kw) {
                return evaluate(c, a, kw, evaluation::unchecked);
            },
            "The bare double program (eval_many), fastest, with no accuracy check: where the closed "
            "form cancels, its values can be wrong in every digit.");

    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const symrep::error& e) {
            // symrep.<class> (error_class) without a place
            const std::string cls = error_class(p, e.what());
            py::object error = py::module_::import("symrep").attr(cls.c_str());
            py::object x = error(lang::reported_message(e.what()), py::none(), py::none(), py::none(), py::none());
            PyErr_SetObject(error.ptr(), x.ptr());
        }
    });
}
