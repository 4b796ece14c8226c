// symrep/numeric/evaluator.h -- compile closed forms into fast double evaluators.
//
// numeric/ is the double-precision side of the engine: closed forms compiled
// to programs (compile.cpp, evaluator.cpp), the stable evaluator with
// precision tiers, the exact reference values, and integration with
// Boost.Odeint for verification. It includes core/ and scalar/
// (docs/architecture.md).
//
// compile() walks GiNaC expressions once and emits a flat program: a vector of
// three-address instructions over a register file of doubles. Structurally equal
// subtrees are computed once (hash-consing on GiNaC's ex hash and ex::is_equal),
// so x*y + sin(x*y) evaluates x*y a single time, and x^2, x^3, x^5 share their
// partial products; sin(u) and cos(u) of one argument are fused into one
// sincos instruction. Subtrees without input symbols (Pi, sqrt(2), 3/7, ...) are
// evaluated once at compile time by GiNaC's evalf and stored as constants.
//
// Supported: + - * / (as GiNaC represents them: sums, products, powers with
// exponent -1), powers (integer exponents by binary repeated multiplication,
// exponents +-1/2 by sqrt, anything else by std::pow), the constants Pi, Euler,
// Catalan and every real number, and the functions
//   sqrt exp log abs sin cos tan asin acos atan atan2 sinh cosh tanh
//   asinh acosh atanh.
// Anything else (a symbol not listed among the inputs, a complex number, an
// unsupported function, a list or matrix inside a scalar output, an equation)
// throws symrep::type_error / symrep::domain_error naming the culprit.
//
// Semantics are those of IEEE double arithmetic and <cmath>: log of a negative
// number gives NaN, 1/0 gives inf; nothing is checked at evaluation time.
//
// Namespace: symrep::num (not symrep::numeric, which would hide GiNaC::numeric
// for code inside namespace symrep that relies on `using GiNaC::numeric;`).
//
// Thread safety: a compiled_function is immutable after compile(); eval() is
// const and uses a register file on the stack (or a thread_local one for large
// programs), so one compiled_function
// may be evaluated from several threads at once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <ginac/ginac.h>

namespace symrep::num {

/// The operations of the flat program. Operands a, b and the destination are
/// register indices; registers [0, n_inputs) hold the inputs, the constants
/// follow, then the temporaries.
enum class opcode : std::uint8_t {
    add,    ///< r[dst] = r[a] + r[b]
    sub,    ///< r[dst] = r[a] - r[b]
    mul,    ///< r[dst] = r[a] * r[b]
    div,    ///< r[dst] = r[a] / r[b]
    neg,    ///< r[dst] = -r[a]
    pow,    ///< r[dst] = std::pow(r[a], r[b])   (non-integer exponents only)
    sqrt,
    exp,
    log,
    abs,
    sin,
    cos,
    tan,
    asin,
    acos,
    atan,
    atan2,  ///< r[dst] = std::atan2(r[a], r[b])
    sinh,
    cosh,
    tanh,
    asinh,
    acosh,
    atanh,
    sincos, ///< r[dst] = std::sin(r[a]), r[b] = std::cos(r[a])  (fused by compile())
};

/// One instruction of the flat program.
struct instruction {
    opcode op;
    std::uint32_t dst;
    std::uint32_t a;
    std::uint32_t b;  ///< unused by unary operations; the cos destination of sincos
};

/// Name of an opcode ("add", "sin", ...), for listings and tests.
const char* opcode_name(opcode op);

/// A closed form compiled to a flat double program. Build with compile().
class compiled_function {
public:
    compiled_function() = default;

    std::size_t n_inputs() const { return n_inputs_; }
    std::size_t n_outputs() const { return outputs_.size(); }
    /// Number of instructions executed per evaluation (copies of inputs,
    /// constants and outputs are not instructions).
    std::size_t n_instructions() const { return program_.size(); }
    /// Size of the register file: inputs + constants + temporaries.
    std::size_t n_registers() const { return n_registers_; }
    std::size_t n_constants() const { return constants_.size(); }
    const std::vector<instruction>& program() const { return program_; }

    /// Evaluate at one point: in[0..n_inputs()) -> out[0..n_outputs()).
    /// `in` and `out` may not overlap.
    void eval(const double* in, double* out) const;

    /// Convenience: inputs as a vector (size must be n_inputs(), else
    /// symrep::type_error), outputs returned as a vector.
    std::vector<double> operator()(const std::vector<double>& in) const;

    /// Convenience for vector-valued closed forms: requires n_outputs() == 3
    /// (else symrep::type_error).
    Eigen::Vector3d eval3(const double* in) const;
    Eigen::Vector3d eval3(const std::vector<double>& in) const;

    /// Evaluate at many points: `in` holds n_points rows of n_inputs() values,
    /// `out` receives n_points rows of n_outputs() values (row-major).
    /// Runs the program on blocks of `block_size` points at once (each
    /// instruction loops over the block, which the compiler vectorizes), so the
    /// interpreter's per-instruction overhead is shared by the block; several
    /// times faster per point than eval(), with bitwise the same results.
    void eval_many(const double* in, double* out, std::size_t n_points) const;
    static constexpr std::size_t block_size = 16;

    /// Human-readable listing of the program (one instruction per line).
    std::string listing() const;

private:
    friend class program_builder;
    friend class stable_function;
    std::size_t n_inputs_ = 0;
    std::size_t n_registers_ = 0;
    std::vector<double> constants_;        // copied to registers [n_inputs, n_inputs + size)
    // What each constant is the double of: an exact expression (an empty ex: the
    // double itself is exact), unless constant_known_ is 0 (two different values
    // rounded to this double; known to double precision only).
    std::vector<GiNaC::ex> constant_sources_;
    std::vector<char> constant_known_;
    std::vector<instruction> program_;
    std::vector<std::uint32_t> outputs_;   // register of each output

    void run(double* r) const;
    void run_block(double* r) const;  // registers of block_size lanes each
};

/// Options of compile(). The defaults are what every caller wants; the switch
/// exists so that tests and benchmarks can measure what sharing saves.
struct compile_options {
    /// Common-subexpression elimination: structurally equal subtrees share one
    /// register. Off: every occurrence is compiled again.
    bool share_subexpressions = true;
};

/// Compile scalar expressions `outputs` in the variables `inputs` (in this
/// order in eval()'s input array). Throws symrep::type_error for a symbol that
/// is not an input, an unsupported function or object; symrep::domain_error
/// for a complex constant; symrep::type_error for repeated inputs.
/// The name of a symbol (inputs are passed as ex so that realsymbols are not sliced).
inline std::string symbol_name(const GiNaC::ex& s) {
    return GiNaC::is_a<GiNaC::symbol>(s) ? GiNaC::ex_to<GiNaC::symbol>(s).get_name() : std::string("?");
}

compiled_function compile(const std::vector<GiNaC::ex>& outputs,
                          const std::vector<GiNaC::ex>& inputs,
                          const compile_options& options = {});

/// Compile one expression that is a scalar, a GiNaC list (lst) of scalars, or
/// a matrix (any shape, read row by row, so a 3x1 or 1x3 vector gives 3 outputs).
compiled_function compile(const GiNaC::ex& output, const std::vector<GiNaC::ex>& inputs,
                          const compile_options& options = {});

/// The scalars of a scalar, list of scalars or matrix (row by row), in order.
/// Nested lists are flattened depth-first. Used by compile() and verify().
std::vector<GiNaC::ex> flatten_outputs(const GiNaC::ex& e);

}  // namespace symrep::num
