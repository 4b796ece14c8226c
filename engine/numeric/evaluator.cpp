// symrep/numeric/evaluator.cpp -- execution of a compiled program: one point, blocks of points, 3-vectors (see evaluator.h).
#include "symrep/numeric/evaluator.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <sstream>
#include <tuple>
#include <unordered_map>

#include "symrep/core/error.h"
#include "symrep/numeric/reference.h"

namespace symrep::num {

// The interpreter loop. With GCC/Clang it is direct-threaded (computed goto:
// each handler ends with its own indirect jump, which the branch predictor
// learns per handler); elsewhere a plain switch.

void compiled_function::run(double* r) const {
    const instruction* ip = program_.data();
    const instruction* const end = ip + program_.size();
#if defined(__GNUC__)
    static const void* const labels[] = {
        &&op_add, &&op_sub, &&op_mul, &&op_div, &&op_neg, &&op_pow, &&op_sqrt, &&op_exp, &&op_log, &&op_abs, &&op_sin, &&op_cos, &&op_tan, &&op_asin, &&op_acos, &&op_atan, &&op_atan2, &&op_sinh, &&op_cosh, &&op_tanh, &&op_asinh, &&op_acosh, &&op_atanh, &&op_sincos};
    static_assert(sizeof(labels) / sizeof(labels[0]) == static_cast<std::size_t>(opcode::sincos) + 1);
#define SYMREP_NEXT()                                   \
    do {                                                \
        if (++ip == end) return;                        \
        goto *labels[static_cast<std::size_t>(ip->op)]; \
    } while (0)
    if (ip == end) return;
    goto *labels[static_cast<std::size_t>(ip->op)];
op_add:
    r[ip->dst] = r[ip->a] + r[ip->b];
    SYMREP_NEXT();
op_sub:
    r[ip->dst] = r[ip->a] - r[ip->b];
    SYMREP_NEXT();
op_mul:
    r[ip->dst] = r[ip->a] * r[ip->b];
    SYMREP_NEXT();
op_div:
    r[ip->dst] = r[ip->a] / r[ip->b];
    SYMREP_NEXT();
op_neg:
    r[ip->dst] = -r[ip->a];
    SYMREP_NEXT();
op_pow:
    r[ip->dst] = std::pow(r[ip->a], r[ip->b]);
    SYMREP_NEXT();
op_sqrt:
    r[ip->dst] = std::sqrt(r[ip->a]);
    SYMREP_NEXT();
op_exp:
    r[ip->dst] = std::exp(r[ip->a]);
    SYMREP_NEXT();
op_log:
    r[ip->dst] = std::log(r[ip->a]);
    SYMREP_NEXT();
op_abs:
    r[ip->dst] = std::fabs(r[ip->a]);
    SYMREP_NEXT();
op_sin:
    r[ip->dst] = std::sin(r[ip->a]);
    SYMREP_NEXT();
op_cos:
    r[ip->dst] = std::cos(r[ip->a]);
    SYMREP_NEXT();
op_tan:
    r[ip->dst] = std::tan(r[ip->a]);
    SYMREP_NEXT();
op_asin:
    r[ip->dst] = std::asin(r[ip->a]);
    SYMREP_NEXT();
op_acos:
    r[ip->dst] = std::acos(r[ip->a]);
    SYMREP_NEXT();
op_atan:
    r[ip->dst] = std::atan(r[ip->a]);
    SYMREP_NEXT();
op_atan2:
    r[ip->dst] = std::atan2(r[ip->a], r[ip->b]);
    SYMREP_NEXT();
op_sinh:
    r[ip->dst] = std::sinh(r[ip->a]);
    SYMREP_NEXT();
op_cosh:
    r[ip->dst] = std::cosh(r[ip->a]);
    SYMREP_NEXT();
op_tanh:
    r[ip->dst] = std::tanh(r[ip->a]);
    SYMREP_NEXT();
op_asinh:
    r[ip->dst] = std::asinh(r[ip->a]);
    SYMREP_NEXT();
op_acosh:
    r[ip->dst] = std::acosh(r[ip->a]);
    SYMREP_NEXT();
op_atanh:
    r[ip->dst] = std::atanh(r[ip->a]);
    SYMREP_NEXT();
op_sincos : {
        const double a = r[ip->a];
        r[ip->dst] = std::sin(a);
        r[ip->b] = std::cos(a);
    }
    SYMREP_NEXT();
#undef SYMREP_NEXT
#else
    for (; ip != end; ++ip) {
        switch (ip->op) {
            case opcode::add: r[ip->dst] = r[ip->a] + r[ip->b]; break;
            case opcode::sub: r[ip->dst] = r[ip->a] - r[ip->b]; break;
            case opcode::mul: r[ip->dst] = r[ip->a] * r[ip->b]; break;
            case opcode::div: r[ip->dst] = r[ip->a] / r[ip->b]; break;
            case opcode::neg: r[ip->dst] = -r[ip->a]; break;
            case opcode::pow: r[ip->dst] = std::pow(r[ip->a], r[ip->b]); break;
            case opcode::sqrt: r[ip->dst] = std::sqrt(r[ip->a]); break;
            case opcode::exp: r[ip->dst] = std::exp(r[ip->a]); break;
            case opcode::log: r[ip->dst] = std::log(r[ip->a]); break;
            case opcode::abs: r[ip->dst] = std::fabs(r[ip->a]); break;
            case opcode::sin: r[ip->dst] = std::sin(r[ip->a]); break;
            case opcode::cos: r[ip->dst] = std::cos(r[ip->a]); break;
            case opcode::tan: r[ip->dst] = std::tan(r[ip->a]); break;
            case opcode::asin: r[ip->dst] = std::asin(r[ip->a]); break;
            case opcode::acos: r[ip->dst] = std::acos(r[ip->a]); break;
            case opcode::atan: r[ip->dst] = std::atan(r[ip->a]); break;
            case opcode::atan2: r[ip->dst] = std::atan2(r[ip->a], r[ip->b]); break;
            case opcode::sinh: r[ip->dst] = std::sinh(r[ip->a]); break;
            case opcode::cosh: r[ip->dst] = std::cosh(r[ip->a]); break;
            case opcode::tanh: r[ip->dst] = std::tanh(r[ip->a]); break;
            case opcode::asinh: r[ip->dst] = std::asinh(r[ip->a]); break;
            case opcode::acosh: r[ip->dst] = std::acosh(r[ip->a]); break;
            case opcode::atanh: r[ip->dst] = std::atanh(r[ip->a]); break;
            case opcode::sincos: {
                const double a = r[ip->a];
                r[ip->dst] = std::sin(a);
                r[ip->b] = std::cos(a);
                break;
            }
        }
    }
#endif
}

void compiled_function::eval(const double* in, double* out) const {
    // Small register files live on the stack (no allocation, no thread-local
    // lookup); larger ones in a per-thread buffer.
    constexpr std::size_t stack_registers = 512;
    double stack[stack_registers];
    double* r = stack;
    if (n_registers_ > stack_registers) {
        thread_local std::vector<double> scratch;
        if (scratch.size() < n_registers_) scratch.resize(n_registers_);
        r = scratch.data();
    }
    for (std::size_t i = 0; i < n_inputs_; ++i) r[i] = in[i];
    const double* c = constants_.data();
    for (std::size_t i = 0, n = constants_.size(); i < n; ++i) r[n_inputs_ + i] = c[i];
    run(r);
    for (std::size_t i = 0; i < outputs_.size(); ++i) out[i] = r[outputs_[i]];
}

// Block version of run(): register i occupies r[i * B, (i + 1) * B). Every
// instruction writes a fresh register (the program is in SSA form), so the
// destination never aliases an operand.
void compiled_function::run_block(double* r) const {
    constexpr std::size_t B = block_size;
    for (const instruction& ins : program_) {
        double* __restrict__ d = r + std::size_t{ins.dst} * B;
        const double* __restrict__ a = r + std::size_t{ins.a} * B;
        const double* __restrict__ b = r + std::size_t{ins.b} * B;
        switch (ins.op) {
            case opcode::add: for (std::size_t k = 0; k < B; ++k) d[k] = a[k] + b[k]; break;
            case opcode::sub: for (std::size_t k = 0; k < B; ++k) d[k] = a[k] - b[k]; break;
            case opcode::mul: for (std::size_t k = 0; k < B; ++k) d[k] = a[k] * b[k]; break;
            case opcode::div: for (std::size_t k = 0; k < B; ++k) d[k] = a[k] / b[k]; break;
            case opcode::neg: for (std::size_t k = 0; k < B; ++k) d[k] = -a[k]; break;
            case opcode::pow: for (std::size_t k = 0; k < B; ++k) d[k] = std::pow(a[k], b[k]); break;
            case opcode::sqrt: for (std::size_t k = 0; k < B; ++k) d[k] = std::sqrt(a[k]); break;
            case opcode::exp: for (std::size_t k = 0; k < B; ++k) d[k] = std::exp(a[k]); break;
            case opcode::log: for (std::size_t k = 0; k < B; ++k) d[k] = std::log(a[k]); break;
            case opcode::abs: for (std::size_t k = 0; k < B; ++k) d[k] = std::fabs(a[k]); break;
            case opcode::sin: for (std::size_t k = 0; k < B; ++k) d[k] = std::sin(a[k]); break;
            case opcode::cos: for (std::size_t k = 0; k < B; ++k) d[k] = std::cos(a[k]); break;
            case opcode::tan: for (std::size_t k = 0; k < B; ++k) d[k] = std::tan(a[k]); break;
            case opcode::asin: for (std::size_t k = 0; k < B; ++k) d[k] = std::asin(a[k]); break;
            case opcode::acos: for (std::size_t k = 0; k < B; ++k) d[k] = std::acos(a[k]); break;
            case opcode::atan: for (std::size_t k = 0; k < B; ++k) d[k] = std::atan(a[k]); break;
            case opcode::atan2: for (std::size_t k = 0; k < B; ++k) d[k] = std::atan2(a[k], b[k]); break;
            case opcode::sinh: for (std::size_t k = 0; k < B; ++k) d[k] = std::sinh(a[k]); break;
            case opcode::cosh: for (std::size_t k = 0; k < B; ++k) d[k] = std::cosh(a[k]); break;
            case opcode::tanh: for (std::size_t k = 0; k < B; ++k) d[k] = std::tanh(a[k]); break;
            case opcode::asinh: for (std::size_t k = 0; k < B; ++k) d[k] = std::asinh(a[k]); break;
            case opcode::acosh: for (std::size_t k = 0; k < B; ++k) d[k] = std::acosh(a[k]); break;
            case opcode::atanh: for (std::size_t k = 0; k < B; ++k) d[k] = std::atanh(a[k]); break;
            case opcode::sincos: {
                double* __restrict__ c = r + std::size_t{ins.b} * B;
                for (std::size_t k = 0; k < B; ++k) {
                    d[k] = std::sin(a[k]);
                    c[k] = std::cos(a[k]);
                }
                break;
            }
        }
    }
}

void compiled_function::eval_many(const double* in, double* out, std::size_t n_points) const {
    constexpr std::size_t B = block_size;
    if (n_points == 0) return;
    thread_local std::vector<double> scratch;
    if (scratch.size() < n_registers_ * B) scratch.resize(n_registers_ * B);
    double* r = scratch.data();
    const std::size_t n_out = outputs_.size();
    for (std::size_t c = 0; c < constants_.size(); ++c)
        std::fill(r + (n_inputs_ + c) * B, r + (n_inputs_ + c + 1) * B, constants_[c]);
    for (std::size_t p0 = 0; p0 < n_points; p0 += B) {
        const std::size_t m = std::min(B, n_points - p0);
        for (std::size_t i = 0; i < n_inputs_; ++i) {
            double* ri = r + i * B;
            for (std::size_t k = 0; k < m; ++k) ri[k] = in[(p0 + k) * n_inputs_ + i];
            for (std::size_t k = m; k < B; ++k) ri[k] = ri[0];  // unused lanes: a valid point
        }
        run_block(r);
        for (std::size_t j = 0; j < n_out; ++j) {
            const double* rj = r + std::size_t{outputs_[j]} * B;
            for (std::size_t k = 0; k < m; ++k) out[(p0 + k) * n_out + j] = rj[k];
        }
    }
}

std::vector<double> compiled_function::operator()(const std::vector<double>& in) const {
    if (in.size() != n_inputs_)
        throw type_error("compiled function takes " + std::to_string(n_inputs_) + " input(s), got " +
                         std::to_string(in.size()));
    std::vector<double> out(outputs_.size());
    eval(in.data(), out.data());
    return out;
}

Eigen::Vector3d compiled_function::eval3(const double* in) const {
    if (outputs_.size() != 3)
        throw type_error("eval3: the compiled function has " + std::to_string(outputs_.size()) +
                         " output(s), not 3");
    Eigen::Vector3d v;
    eval(in, v.data());
    return v;
}

Eigen::Vector3d compiled_function::eval3(const std::vector<double>& in) const {
    if (in.size() != n_inputs_)
        throw type_error("compiled function takes " + std::to_string(n_inputs_) + " input(s), got " +
                         std::to_string(in.size()));
    return eval3(in.data());
}

}  // namespace symrep::num
