// symrep/numeric/compile.cpp -- compilation of closed forms to a register program, and its listing (see evaluator.h).
#include "symrep/numeric/evaluator.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <sstream>
#include <tuple>
#include <unordered_map>

#include "symrep/core/error.h"
#include "symrep/scalar/scalar.h"
#include "symrep/numeric/certified.h"
#include "symrep/numeric/reference.h"

namespace symrep::num {

namespace {

struct function_entry {
    const char* name;
    opcode op;
    std::size_t arity;
};

const function_entry function_table[] = {
    {"sqrt", opcode::sqrt, 1},   {"exp", opcode::exp, 1},     {"log", opcode::log, 1},
    {"abs", opcode::abs, 1},     {"sin", opcode::sin, 1},     {"cos", opcode::cos, 1},
    {"tan", opcode::tan, 1},     {"asin", opcode::asin, 1},   {"acos", opcode::acos, 1},
    {"atan", opcode::atan, 1},   {"atan2", opcode::atan2, 2}, {"sinh", opcode::sinh, 1},
    {"cosh", opcode::cosh, 1},   {"tanh", opcode::tanh, 1},   {"asinh", opcode::asinh, 1},
    {"acosh", opcode::acosh, 1}, {"atanh", opcode::atanh, 1},
};

std::string supported_functions() {
    std::string s;
    for (const auto& f : function_table) {
        if (!s.empty()) s += ", ";
        s += f.name;
    }
    return s;
}

bool is_unary(opcode op) {
    switch (op) {
        case opcode::add:
        case opcode::sub:
        case opcode::mul:
        case opcode::div:
        case opcode::pow:
        case opcode::atan2:
        case opcode::sincos:
            return false;
        default:
            return true;
    }
}

// Register numbering during the build: inputs are [0, n_inputs), constants and
// temporaries get tagged indices that finish() renumbers to their final place.
constexpr std::uint32_t const_tag = 0x80000000u;
constexpr std::uint32_t temp_tag = 0x40000000u;
constexpr std::uint32_t index_mask = 0x3fffffffu;

}  // namespace

const char* opcode_name(opcode op) {
    switch (op) {
        case opcode::add: return "add";
        case opcode::sub: return "sub";
        case opcode::mul: return "mul";
        case opcode::div: return "div";
        case opcode::neg: return "neg";
        case opcode::pow: return "pow";
        case opcode::sqrt: return "sqrt";
        case opcode::exp: return "exp";
        case opcode::log: return "log";
        case opcode::abs: return "abs";
        case opcode::sin: return "sin";
        case opcode::cos: return "cos";
        case opcode::tan: return "tan";
        case opcode::asin: return "asin";
        case opcode::acos: return "acos";
        case opcode::atan: return "atan";
        case opcode::atan2: return "atan2";
        case opcode::sinh: return "sinh";
        case opcode::cosh: return "cosh";
        case opcode::tanh: return "tanh";
        case opcode::asinh: return "asinh";
        case opcode::acosh: return "acosh";
        case opcode::atanh: return "atanh";
        case opcode::sincos: return "sincos";
    }
    return "?";
}

/// Builds the flat program of a compiled_function (one per compile() call).
class program_builder {
public:
    program_builder(const std::vector<GiNaC::ex>& inputs, bool share)
        : inputs_(inputs), share_(share) {
        for (std::size_t i = 0; i < inputs.size(); ++i) {
            if (!GiNaC::is_a<GiNaC::symbol>(inputs[i]))
                throw type_error("compile: input " + std::to_string(i + 1) + " is not a symbol");
            auto [it, fresh] = input_reg_.emplace(GiNaC::ex(inputs[i]), static_cast<std::uint32_t>(i));
            if (!fresh)
                throw type_error("compile: input symbol '" + symbol_name(inputs[i]) +
                                 "' is listed twice");
        }
    }

    /// A text that identifies e up to the order of the operands of sums and
    /// products, which GiNaC sets by hash values that can differ between runs:
    /// operands are compiled in the order of these keys, so that the same
    /// closed form gives the same program (and the same roundings) every run.
    const std::string& key(const GiNaC::ex& e) {
        using namespace GiNaC;
        auto it = keys_.find(e);
        if (it != keys_.end()) return it->second;
        std::string k;
        if (is_a<symbol>(e)) {
            k = "s" + ex_to<symbol>(e).get_name();
        } else if (is_a<add>(e) || is_a<mul>(e)) {
            std::vector<std::string> parts;
            for (std::size_t i = 0; i < e.nops(); ++i) parts.push_back(key(e.op(i)));
            std::sort(parts.begin(), parts.end());
            k = is_a<add>(e) ? "+(" : "*(";
            for (const std::string& x : parts) k += x + ",";
            k += ")";
        } else if (is_a<power>(e)) {
            k = "^(" + key(e.op(0)) + "," + key(e.op(1)) + ")";
        } else if (is_a<function>(e)) {
            k = "f" + ex_to<function>(e).get_name() + "(";
            for (std::size_t i = 0; i < e.nops(); ++i) k += key(e.op(i)) + ",";
            k += ")";
        } else {
            std::ostringstream os;
            os << e;
            k = "n" + os.str();
        }
        return keys_.emplace(e, std::move(k)).first->second;
    }

    /// The operands sorted by key (stable for equal keys).
    std::vector<GiNaC::ex> in_key_order(std::vector<GiNaC::ex> v) {
        std::stable_sort(v.begin(), v.end(), [&](const GiNaC::ex& a, const GiNaC::ex& b) { return key(a) < key(b); });
        return v;
    }

    std::uint32_t node(const GiNaC::ex& e) {
        if (share_) {
            auto it = memo_.find(e);
            if (it != memo_.end()) return it->second;
        }
        std::uint32_t r = compile_uncached(e);
        if (share_) memo_.emplace(e, r);
        return r;
    }

    compiled_function finish(const std::vector<std::uint32_t>& outputs) {
        if (share_) fuse_sincos();
        compiled_function f;
        f.n_inputs_ = inputs_.size();
        f.constants_ = constants_;
        f.constant_sources_ = constant_sources_;
        for (std::size_t k = 0; k < constant_known_.size(); ++k)
            if (!constant_known_[k]) f.constant_sources_[k] = GiNaC::ex();
        f.constant_known_ = constant_known_;
        const auto n_in = static_cast<std::uint32_t>(inputs_.size());
        const auto n_const = static_cast<std::uint32_t>(constants_.size());
        auto place = [&](std::uint32_t r) -> std::uint32_t {
            if (r & const_tag) return n_in + (r & index_mask);
            if (r & temp_tag) return n_in + n_const + (r & index_mask);
            return r;
        };
        f.program_.reserve(program_.size());
        for (instruction ins : program_) {
            ins.dst = place(ins.dst);
            ins.a = place(ins.a);
            ins.b = is_unary(ins.op) ? 0 : place(ins.b);
            f.program_.push_back(ins);
        }
        for (auto r : outputs) f.outputs_.push_back(place(r));
        f.n_registers_ = n_in + n_const + n_temps_;
        return f;
    }

private:
    /// sin(a) and cos(a) of the same register become one sincos instruction at
    /// the place of the earlier one (both results are then ready before any use).
    void fuse_sincos() {
        std::map<std::uint32_t, std::size_t> sin_at, cos_at;
        for (std::size_t i = 0; i < program_.size(); ++i) {
            if (program_[i].op == opcode::sin) sin_at.emplace(program_[i].a, i);
            if (program_[i].op == opcode::cos) cos_at.emplace(program_[i].a, i);
        }
        std::vector<bool> drop(program_.size(), false);
        bool any = false;
        for (const auto& [a, i] : sin_at) {
            auto c = cos_at.find(a);
            if (c == cos_at.end()) continue;
            const std::size_t j = c->second;
            const instruction fused{opcode::sincos, program_[i].dst, a, program_[j].dst};
            program_[std::min(i, j)] = fused;
            drop[std::max(i, j)] = true;
            any = true;
        }
        if (!any) return;
        std::vector<instruction> kept;
        kept.reserve(program_.size());
        for (std::size_t i = 0; i < program_.size(); ++i)
            if (!drop[i]) kept.push_back(program_[i]);
        program_.swap(kept);
    }

    const std::vector<GiNaC::ex>& inputs_;
    bool share_;
    std::unordered_map<GiNaC::ex, std::uint32_t, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> input_reg_;
    std::unordered_map<GiNaC::ex, std::string, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> keys_;
    std::unordered_map<GiNaC::ex, std::uint32_t, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> memo_;
    std::unordered_map<GiNaC::ex, bool, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> constant_memo_;
    std::map<std::uint64_t, std::uint32_t> constant_reg_;  // by bit pattern
    std::map<std::tuple<opcode, std::uint32_t, std::uint32_t>, std::uint32_t> value_numbers_;
    std::vector<double> constants_;
    std::vector<GiNaC::ex> constant_sources_;
    std::vector<char> constant_known_;
    std::vector<instruction> program_;
    std::uint32_t n_temps_ = 0;

    /// The register of constant v, the double nearest the exact `source`. The
    /// source is kept for evaluation in higher precision (stable_function); two
    /// different sources with one double value are recorded as known to double
    /// precision only.
    std::uint32_t constant(double v, const GiNaC::ex& source) {
        std::uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        auto it = constant_reg_.find(bits);
        if (it != constant_reg_.end()) {
            const std::size_t k = it->second & index_mask;
            if (!source.is_equal(constant_sources_[k])) constant_known_[k] = 0;
            return it->second;
        }
        auto r = const_tag | static_cast<std::uint32_t>(constants_.size());
        constants_.push_back(v);
        constant_sources_.push_back(source);
        constant_known_.push_back(1);
        constant_reg_.emplace(bits, r);
        return r;
    }

    std::uint32_t emit(opcode op, std::uint32_t a, std::uint32_t b = 0) {
        if (is_unary(op)) b = 0;
        auto key = std::make_tuple(op, a, b);
        if (share_) {
            auto it = value_numbers_.find(key);
            if (it != value_numbers_.end()) return it->second;
        }
        if (n_temps_ > index_mask) throw size_error("compile: the closed form is too large");
        std::uint32_t dst = temp_tag | n_temps_++;
        program_.push_back({op, dst, a, b});
        if (share_) value_numbers_.emplace(key, dst);
        return dst;
    }

    /// base^n for an integer n >= 1 by repeated squaring; partial powers are
    /// shared through emit()'s value numbering.
    std::uint32_t powi(std::uint32_t base, unsigned long n) {
        if (n == 1) return base;
        if (n % 2 == 0) {
            std::uint32_t h = powi(base, n / 2);
            return emit(opcode::mul, h, h);
        }
        return emit(opcode::mul, powi(base, n - 1), base);
    }

    /// True if e contains no symbol (so it evaluates to a number).
    bool is_constant(const GiNaC::ex& e) {
        if (GiNaC::is_a<GiNaC::symbol>(e)) return false;
        if (e.nops() == 0) return true;
        auto it = constant_memo_.find(e);
        if (it != constant_memo_.end()) return it->second;
        bool c = true;
        for (std::size_t i = 0; i < e.nops() && c; ++i) c = is_constant(e.op(i));
        constant_memo_.emplace(e, c);
        return c;
    }

    /// The double nearest the exact value of the symbol-free e, with a proved
    /// error bound (numeric/certified.h): GiNaC's evalf at its 17 digits gives 0
    /// for 1 - cos(1e-10). False where the bound does not apply (then evalf).
    static bool accurate_constant(const GiNaC::ex& e, double& out) {
        try {
            const certified_result r = certified_double(e, 0x1p-60, 2560);
            if (!r.proved) return false;
            out = r.value;
            return true;
        } catch (const std::exception&) {
            return false;
        }
    }

    static double real_value(const GiNaC::numeric& n, const GiNaC::ex& where) {
        if (!n.is_real())
            throw domain_error("cannot evaluate numerically: complex value " + message_text(where) +
                               " (the evaluator works in real doubles)");
        return n.to_double();
    }

    std::uint32_t compile_uncached(const GiNaC::ex& e) {
        using namespace GiNaC;
        if (is_a<symbol>(e)) {
            auto it = input_reg_.find(e);
            if (it != input_reg_.end()) return it->second;
            std::string names;
            for (const auto& s : inputs_) names += (names.empty() ? "" : ", ") + symbol_name(s);
            throw type_error("cannot evaluate numerically: symbol '" + ex_to<symbol>(e).get_name() +
                             "' has no value (inputs: " + (names.empty() ? "none" : names) + ")");
        }
        if (is_a<GiNaC::numeric>(e)) return constant(real_value(ex_to<GiNaC::numeric>(e), e), e);
        if (is_a<lst>(e) || is_a<matrix>(e))
            throw type_error("cannot compile a list or matrix inside a scalar output: " + message_text(e));
        if (is_a<relational>(e))
            throw type_error("cannot compile an equation or comparison: " + message_text(e));
        if (is_constant(e)) {
            // Subtrees without symbols are computed once, by GiNaC, at compile time.
            double c;
            if (accurate_constant(e, c)) return constant(c, e);
            ex v;
            try {
                v = e.evalf();
            } catch (const std::exception&) {
                v = e;
            }
            if (is_a<GiNaC::numeric>(v)) return constant(real_value(ex_to<GiNaC::numeric>(v), e), e);
            // No numeric value (e.g. an unsupported function): compile structurally,
            // which names what is not supported.
        }
        if (is_a<add>(e)) return compile_add(e);
        if (is_a<mul>(e)) return compile_mul(e);
        if (is_a<power>(e)) return compile_power(e);
        if (is_a<function>(e)) return compile_function(e);
        throw type_error("cannot compile " + message_text(e) + " (not a number, input symbol, sum, product, "
                         "power or supported function)");
    }

    /// A term t of a sum is written as -(u) with u "positive" if it is a
    /// negative number or a product with a negative numeric coefficient.
    static bool negated_term(const GiNaC::ex& t, GiNaC::ex& u) {
        using namespace GiNaC;
        if (is_a<GiNaC::numeric>(t) && ex_to<GiNaC::numeric>(t).is_real() && ex_to<GiNaC::numeric>(t).is_negative()) {
            u = -t;
            return true;
        }
        if (is_a<mul>(t)) {
            const ex c = t.op(t.nops() - 1);
            if (is_a<GiNaC::numeric>(c) && ex_to<GiNaC::numeric>(c).is_real() && ex_to<GiNaC::numeric>(c).is_negative()) {
                u = -t;
                return true;
            }
        }
        return false;
    }

    std::uint32_t compile_add(const GiNaC::ex& e) {
        std::uint32_t acc = 0;
        bool have = false;
        std::vector<std::uint32_t> negatives;
        // Symbol-free terms fold into one constant.
        // (Summed exactly: GiNaC would round a sum of floats to Digits at once,
        // and the constant's exact value is kept for stable_function.)
        GiNaC::ex csum = 0;
        std::vector<GiNaC::ex> terms;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            if (is_constant(e.op(i)))
                csum += exact_floats_of(e.op(i));
            else
                terms.push_back(e.op(i));
        }
        terms = in_key_order(std::move(terms));
        if (!csum.is_zero()) terms.push_back(csum);
        for (const GiNaC::ex& term : terms) {
            GiNaC::ex u;
            if (negated_term(term, u)) {
                negatives.push_back(node(u));
                continue;
            }
            std::uint32_t r = node(term);
            acc = have ? emit(opcode::add, acc, r) : r;
            have = true;
        }
        for (std::uint32_t r : negatives) {
            acc = have ? emit(opcode::sub, acc, r) : emit(opcode::neg, r);
            have = true;
        }
        return acc;
    }

    std::uint32_t compile_mul(const GiNaC::ex& e) {
        using namespace GiNaC;
        std::uint32_t num = 0, den = 0;
        bool have_num = false, have_den = false, negate = false;
        // Symbol-free factors (numeric coefficient, Pi, sqrt(2), ...) fold into one constant.
        // (Multiplied exactly, as the constant terms of a sum.)
        std::vector<ex> rest, cfactors;
        ex cprod = 1;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            if (is_constant(e.op(i))) {
                cfactors.push_back(e.op(i));
                cprod *= exact_floats_of(e.op(i));
            } else {
                rest.push_back(e.op(i));
            }
        }
        if (!cfactors.empty()) {
            ex v;
            double c = 0;
            const bool accurate = accurate_constant(cprod, c);
            try {
                v = accurate ? ex(c) : cprod.evalf();
            } catch (const std::exception&) {
                v = cprod;
            }
            if (is_a<GiNaC::numeric>(v)) {
                if (!accurate) c = real_value(ex_to<GiNaC::numeric>(v), cprod);
                if (c == -1.0) {
                    negate = true;
                } else if (c != 1.0) {
                    num = constant(c, cprod);
                    have_num = true;
                }
            } else {
                rest.insert(rest.end(), cfactors.begin(), cfactors.end());  // compiled one by one
            }
        }
        rest = in_key_order(std::move(rest));
        for (const ex& f : rest) {
            if (is_a<power>(f) && is_a<GiNaC::numeric>(f.op(1)) && ex_to<GiNaC::numeric>(f.op(1)).is_real() &&
                ex_to<GiNaC::numeric>(f.op(1)).is_negative()) {
                // A denominator factor b^(-k): divide by b^k.
                std::uint32_t r = node(power(f.op(0), -f.op(1)));
                den = have_den ? emit(opcode::mul, den, r) : r;
                have_den = true;
                continue;
            }
            std::uint32_t r = node(f);
            num = have_num ? emit(opcode::mul, num, r) : r;
            have_num = true;
        }
        std::uint32_t res;
        if (have_den)
            res = emit(opcode::div, have_num ? num : constant(1.0, 1), den);
        else
            res = have_num ? num : constant(1.0, 1);
        return negate ? emit(opcode::neg, res) : res;
    }

    std::uint32_t compile_power(const GiNaC::ex& e) {
        using namespace GiNaC;
        const ex b = e.op(0), x = e.op(1);
        if (is_a<GiNaC::numeric>(x) && ex_to<GiNaC::numeric>(x).is_real()) {
            const GiNaC::numeric& n = ex_to<GiNaC::numeric>(x);
            if (n.is_integer()) {
                if (n.is_zero()) return constant(1.0, 1);
                const GiNaC::numeric m = abs(n);
                if (m <= 1024) {
                    std::uint32_t r = powi(node(b), static_cast<unsigned long>(m.to_long()));
                    return n.is_negative() ? emit(opcode::div, constant(1.0, 1), r) : r;
                }
            } else if (n.denom() == 2) {
                // b^(p/2) = sqrt(b)^p
                const GiNaC::numeric p = abs(n.numer());
                if (p <= 1024) {
                    std::uint32_t s = emit(opcode::sqrt, node(b));
                    std::uint32_t r = powi(s, static_cast<unsigned long>(p.to_long()));
                    return n.is_negative() ? emit(opcode::div, constant(1.0, 1), r) : r;
                }
            }
            return emit(opcode::pow, node(b), constant(n.to_double(), n));
        }
        return emit(opcode::pow, node(b), node(x));
    }

    std::uint32_t compile_function(const GiNaC::ex& e) {
        using namespace GiNaC;
        const std::string name = ex_to<function>(e).get_name();
        for (const auto& f : function_table) {
            if (name != f.name) continue;
            if (e.nops() != f.arity) break;
            if (f.arity == 1) return emit(f.op, node(e.op(0)));
            return emit(f.op, node(e.op(0)), node(e.op(1)));
        }
        throw type_error("cannot evaluate numerically: unsupported function '" + name + "' in " +
                         message_text(e) + " (supported: " + supported_functions() + ")");
    }
};

std::vector<GiNaC::ex> flatten_outputs(const GiNaC::ex& e) {
    using namespace GiNaC;
    std::vector<ex> out;
    if (is_a<lst>(e)) {
        for (std::size_t i = 0; i < e.nops(); ++i) {
            auto sub = flatten_outputs(e.op(i));
            out.insert(out.end(), sub.begin(), sub.end());
        }
    } else if (is_a<matrix>(e)) {
        const matrix& m = ex_to<matrix>(e);
        for (unsigned i = 0; i < m.rows(); ++i)
            for (unsigned j = 0; j < m.cols(); ++j) out.push_back(m(i, j));
    } else {
        out.push_back(e);
    }
    return out;
}

compiled_function compile(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::ex>& inputs,
                          const compile_options& options) {
    program_builder b(inputs, options.share_subexpressions);
    std::vector<std::uint32_t> regs;
    regs.reserve(outputs.size());
    for (const auto& e : outputs) regs.push_back(b.node(e));
    return b.finish(regs);
}

compiled_function compile(const GiNaC::ex& output, const std::vector<GiNaC::ex>& inputs,
                          const compile_options& options) {
    return compile(flatten_outputs(output), inputs, options);
}

std::string compiled_function::listing() const {
    std::ostringstream os;
    os << "inputs r0..r" << (n_inputs_ ? n_inputs_ - 1 : 0) << (n_inputs_ ? "" : " (none)") << "\n";
    os.precision(17);
    for (std::size_t i = 0; i < constants_.size(); ++i)
        os << "r" << n_inputs_ + i << " = " << constants_[i] << "\n";
    for (const auto& ins : program_) {
        if (ins.op == opcode::sincos) {
            os << "r" << ins.dst << ", r" << ins.b << " = sincos r" << ins.a << "\n";
            continue;
        }
        os << "r" << ins.dst << " = " << opcode_name(ins.op) << " r" << ins.a;
        if (!is_unary(ins.op)) os << ", r" << ins.b;
        os << "\n";
    }
    os << "outputs";
    for (auto o : outputs_) os << " r" << o;
    os << "\n";
    return os.str();
}

}  // namespace symrep::num
