// symrep/lang/builtins.h -- the functions callable from symrep scripts.
//
// Each builtin carries its own documentation (signature, meaning, the thesis
// equation it implements, an example); `symrep --doc` renders the registry as
// Markdown and docs/language.md is checked against it by a test, so the
// reference and the program never disagree.
//
// Builtins are registered explicitly (no static initializers, which a static
// library would drop): the interpreter calls every register_* function below.
// Each module declares its builtins one way: a table of builtin_declaration rows
// (name, signature, summary, equation, example, arity, body) given to add_builtins,
// each body a named function `builtin_NAME` in the module's lang/builtins_<module>.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "symrep/core/error.h"
#include "symrep/lang/value.h"

namespace symrep::lang {

/// What a builtin may ask of the running session.
class context {
public:
    virtual ~context() = default;
    /// The session's real symbol with this name (created on first use). Returned as an
    /// ex: copying a GiNaC::realsymbol into a GiNaC::symbol would slice it into a
    /// different (complex) symbol.
    virtual GiNaC::ex symbol(const std::string& name) = 0;
    /// Where print() and friends write.
    virtual std::ostream& out() = 0;
    /// Told of every file a builtin writes (plot, trajectory, hodograph): front-ends show the
    /// pictures of a statement (the Jupyter kernel). The full path.
    virtual void wrote_file(const std::string& path) {}
    /// A builtin's report beside its result (identify's points, condition number, ...): `prose`
    /// for people (one or more lines, each ending in a newline); `fields` the same as the members
    /// of a JSON object ("\"points\": 256, ..." without braces), which a session under
    /// --format json writes as one line {"file", "line", "kind": "report", "from", ...fields}.
    virtual void report_fields(const std::string& from, const std::string& prose, const std::string& fields) {
        out() << prose;
    }
    /// The named options of the call being run (name = value for a name the builtin declares
    /// in its `options`, e.g. view = "top"), in the order written; set by the session around
    /// the builtin's body. named_option() finds one (nullptr when not given).
    std::vector<std::pair<std::string, value>> named_options;
    const value* named_option(const std::string& name) const {
        for (const auto& o : named_options)
            if (o.first == name) return &o.second;
        return nullptr;
    }
};

struct builtin {
    std::string name;
    std::string signature;  ///< e.g. "inverse(w)"
    std::string summary;    ///< what it does, one or two sentences
    std::string equation;   ///< thesis equation(s), e.g. "(III.1.57)"; may be empty
    std::string example;    ///< a statement that runs, e.g. "inverse(mc(1, [1,2,0,0]))"
    std::string section;    ///< grouping in the reference, e.g. "Multicomplex algebra"
    std::size_t min_args = 0;
    std::size_t max_args = 0;  ///< any_number for variadic
    std::function<value(const std::vector<value>& args, context& ctx)> fn;
    /// Names taken as options: an argument `name = value` with such a name is not positional
    /// (it does not count in min_args..max_args) and reaches the body as context::named_options.
    std::vector<std::string> options;
};

class registry {
public:
    /// Adds a builtin; a duplicate name is a programming error (std::logic_error).
    void add(builtin b);
    const builtin* find(const std::string& name) const;
    /// All builtins, sorted by section then name.
    std::vector<const builtin*> all() const;

private:
    std::map<std::string, builtin> table_;
};

/// The body of a builtin: a named function beside the module it serves
/// (lang/builtins_<module>.cpp). It receives the builtin itself (its name and signature,
/// for the arg_* checkers' messages), the arguments (their number already checked against
/// the arity) and the session.
using builtin_body = std::function<value(const builtin& self, const std::vector<value>& args, context& ctx)>;

/// max_args of a builtin that takes any number of arguments from min_args on.
inline constexpr std::size_t any_number = SIZE_MAX;

/// The one way to declare a builtin: a row of its module's registration table,
///
///     {name, signature, summary, equation, example, min_args, max_args, body}
///
/// e.g. {"inverse", "inverse(w)", "The inverse of ...", "(III.1.57)", "inverse(mc(1, [1,2,0,0]))", 1, 1,
/// builtin_inverse}. The texts are those of `builtin` (`symrep --doc`, help); the equation may be "".
struct builtin_declaration {
    std::string name;
    std::string signature;
    std::string summary;
    std::string equation;
    std::string example;
    std::size_t min_args = 0;
    std::size_t max_args = 0;  ///< any_number for variadic
    builtin_body body;
    std::vector<std::string> options = {};  ///< named options (builtin::options); most have none
};

/// Registers every row of `table` in `section` (a name registered twice: std::logic_error).
void add_builtins(registry& r, const std::string& section, std::vector<builtin_declaration> table);

// --- argument checking: each throws type_error naming the function and argument
const element& arg_element(const std::vector<value>& args, std::size_t i, const builtin& b);
const algebra_ptr& arg_algebra(const std::vector<value>& args, std::size_t i, const builtin& b);
const GiNaC::ex& arg_ex(const std::vector<value>& args, std::size_t i, const builtin& b);
const list& arg_list(const std::vector<value>& args, std::size_t i, const builtin& b);
const std::string& arg_string(const std::vector<value>& args, std::size_t i, const builtin& b);
/// A non-negative integer argument (exact integer expression).
long arg_int(const std::vector<value>& args, std::size_t i, const builtin& b, long min, long max);
/// A GiNaC symbol argument (a reference into args: keep it as a reference, since
/// copying a realsymbol into a GiNaC::symbol slices it).
const GiNaC::symbol& arg_symbol(const std::vector<value>& args, std::size_t i, const builtin& b);
/// A list of expressions (each entry must be an expression).
std::vector<GiNaC::ex> arg_ex_list(const std::vector<value>& args, std::size_t i, const builtin& b);
/// True when e is or holds a matrix.
bool has_matrix(const GiNaC::ex& e);

/// f(), with the type_error and domain_error messages of the layers below named by the builtin
/// ("eval: symbol 'k' has no value"), as the language shows every refusal; a message that
/// already begins with the builtin's name is passed on as it is.
template <class F>
auto named_by(const builtin& b, F&& f) -> decltype(f()) {
    try {
        return f();
    } catch (const type_error& e) {
        const std::string m = e.what();
        if (m.rfind(b.name + ":", 0) == 0) throw;
        throw type_error(b.name + ": " + m);
    } catch (const domain_error& e) {
        const std::string m = e.what();
        if (m.rfind(b.name + ":", 0) == 0) throw;
        throw domain_error(b.name + ": " + m);
    }
}

// --- registration, one function per part of the engine ---------------------------
void register_core_builtins(registry& r);         // lang/builtins_core.cpp: print, subs, diff, expand, ...
void register_algebra_builtins(registry& r);      // lang/builtins_algebra.cpp: generic algebras, elements
void register_multicomplex_builtins(registry& r); // lang/builtins_multicomplex.cpp
void register_sobrero_builtins(registry& r);      // lang/builtins_sobrero.cpp
void register_walsh_builtins(registry& r);        // lang/builtins_walsh.cpp
void register_polynomial_builtins(registry& r);   // lang/builtins_polynomial.cpp
void register_output_builtins(registry& r);       // lang/builtins_output.cpp
void register_expect_builtins(registry& r);       // lang/builtins_expect.cpp: expect, expect_near
void register_mechanics_builtins(registry& r);    // lang/builtins_mechanics.cpp: ode, check, eval, verify
void register_rules_builtins(registry& r);        // lang/builtins_rules.cpp: load_rules, rewrite, rules
void register_plot_builtins(registry& r);         // lang/builtins_plot.cpp: plot, trajectory, hodograph
void register_transforms_builtins(registry& r);  // lang/builtins_transforms.cpp: laplace, inverse_laplace, transform
void register_identification_builtins(registry& r);  // lang/builtins_identification.cpp: identify, operational matrices
void register_signals_builtins(registry& r);      // lang/builtins_signals.cpp: represent, signal, sampling
void register_dual_builtins(registry& r);         // lang/builtins_dual.cpp: dual, primal, dual_part
void register_screw_builtins(registry& r);        // lang/builtins_screw.cpp: screw motion, dual quaternions
void register_frames_builtins(registry& r);       // lang/builtins_frames.cpp: moving_frame
void register_relative_pose_builtins(registry& r);  // lang/builtins_relative_pose.cpp: relative_pose, pose_dual_quaternion

/// solve(P) for a problem made by ode(...): the exact solution (lang/builtins_mechanics.cpp).
value solve_problem(const value& p);
/// solve(P, values): the scene's exact solution in its smallest model; the model
/// report goes to c.out() (lang/builtins_mechanics.cpp, mechanics/scene.h).
value solve_scene(const builtin& b, const std::vector<value>& a, context& c);

}  // namespace symrep::lang
