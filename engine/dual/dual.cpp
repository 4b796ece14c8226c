// symrep/dual/dual.cpp -- dual numbers and vectors: the reduction modulo eps^2
// by the dual extension of every function (dual.h).
#include "symrep/dual/dual.h"

#include <string>

#include "symrep/core/error.h"
#include "symrep/scalar/equality.h"
#include "symrep/scalar/scalar.h"
#include "symrep/vector/vector.h"

namespace symrep::dual {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;

const ex& dual_unit() {
    static const ex eps = GiNaC::realsymbol("eps", "\\varepsilon");
    return eps;
}

bool has_dual_unit(const ex& e) { return e.has(dual_unit()); }

namespace {

std::string text(const ex& e) { return symrep::to_string(e); }

[[noreturn]] void throw_pure_dual(const ex& whole, const std::string& what) {
    throw zero_divisor_error("the dual number " + text(whole) + " " + what +
                             ": its primal part is 0, so it is a zero divisor (eps * eps = 0)", {});
}

// true when the primal part p is proved 0; domain_error when it cannot be decided.
bool primal_is_zero(const ex& p, const ex& whole) {
    return !is_nonzero_generic(p, "the primal part of " + text(whole));
}

bool unknown_derivative(const ex& d) {
    for (GiNaC::const_preorder_iterator i = d.preorder_begin(); i != d.preorder_end(); ++i)
        if (is_a<GiNaC::fderivative>(*i)) return true;
    return false;
}

dual_parts parts_of(const ex& e);

dual_parts parts_of_function(const ex& e) {
    const auto& f = ex_to<GiNaC::function>(e);
    const std::size_t n = f.nops();
    GiNaC::exvector primals, duals;
    bool any_dual = false;
    for (std::size_t i = 0; i < n; ++i) {
        dual_parts p = parts_of(f.op(i));
        any_dual = any_dual || !p.dual.is_zero();
        primals.push_back(p.primal);
        duals.push_back(p.dual);
    }
    const unsigned serial = f.get_serial();
    // cross, dot and the triple product are multilinear: the product rule.
    if (serial == vcross_SERIAL::serial || serial == vdot_SERIAL::serial || serial == vtriple_SERIAL::serial) {
        ex primal = GiNaC::function(serial, primals);
        ex dual = 0;
        for (std::size_t i = 0; i < n; ++i) {
            if (duals[i].is_zero()) continue;
            GiNaC::exvector a = primals;
            a[i] = duals[i];
            dual += GiNaC::function(serial, a);
        }
        return {primal, dual};
    }
    ex primal;
    try {
        primal = GiNaC::function(serial, primals).eval();
    } catch (const GiNaC::pole_error&) {
        throw_pure_dual(n == 1 ? f.op(0) : e, "is the argument of " + f.get_name() + " at its singular point");
    } catch (const std::domain_error&) {
        throw_pure_dual(n == 1 ? f.op(0) : e, "is the argument of " + f.get_name() + " at its singular point");
    }
    if (!any_dual) return {primal, 0};
    // f(a + eps b) = f(a) + eps sum_i b_i d_i f(a): partial derivatives at fresh symbols.
    GiNaC::exvector s;
    for (std::size_t i = 0; i < n; ++i) s.push_back(GiNaC::realsymbol());
    const ex at_symbols = GiNaC::function(serial, s);
    GiNaC::exmap back;
    for (std::size_t i = 0; i < n; ++i) back[s[i]] = primals[i];
    ex dual = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (duals[i].is_zero()) continue;
        const ex d = at_symbols.diff(ex_to<GiNaC::symbol>(s[i]));
        if (unknown_derivative(d))
            throw domain_error("the dual extension of " + f.get_name() + " needs its derivative, which is not known (in " +
                               text(e) + ")");
        ex at;
        try {
            at = d.subs(back);
        } catch (const GiNaC::pole_error&) {
            throw_pure_dual(e, "makes the derivative of " + f.get_name() + " singular");
        } catch (const std::domain_error&) {
            throw_pure_dual(e, "makes the derivative of " + f.get_name() + " singular");
        }
        dual += duals[i] * at;
    }
    return {primal, dual};
}

dual_parts parts_of(const ex& e) {
    if (!e.has(dual_unit())) return {e, 0};
    if (e.is_equal(dual_unit())) return {0, 1};
    if (is_a<GiNaC::add>(e)) {
        ex p = 0, d = 0;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            dual_parts q = parts_of(e.op(i));
            p += q.primal;
            d += q.dual;
        }
        return {p, d};
    }
    if (is_a<GiNaC::mul>(e)) {
        ex p = 1, d = 0;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            dual_parts q = parts_of(e.op(i));
            d = d * q.primal + p * q.dual;  // (p + eps d)(q.p + eps q.d)
            p = p * q.primal;
        }
        return {p, d};
    }
    if (is_a<GiNaC::power>(e)) {
        const dual_parts b = parts_of(e.op(0));
        const ex& x = e.op(1);
        if (!x.has(dual_unit())) {
            if (x.info(GiNaC::info_flags::posint)) {
                if (x.is_equal(1)) return b;
                return {GiNaC::pow(b.primal, x), x * GiNaC::pow(b.primal, x - 1) * b.dual};
            }
            if (primal_is_zero(b.primal, e)) throw_pure_dual(e.op(0), "is raised to the power " + text(x));
            return {GiNaC::pow(b.primal, x), x * GiNaC::pow(b.primal, x - 1) * b.dual};
        }
        // b^x = exp(x log b): d = b^x (x' log b + x b'/b)
        const dual_parts y = parts_of(x);
        if (primal_is_zero(b.primal, e)) throw_pure_dual(e.op(0), "is raised to a dual power");
        const ex p = GiNaC::pow(b.primal, y.primal);
        return {p, p * (y.dual * GiNaC::log(b.primal) + y.primal * b.dual / b.primal)};
    }
    if (is_a<GiNaC::matrix>(e)) {
        const auto& m = ex_to<GiNaC::matrix>(e);
        GiNaC::matrix p(m.rows(), m.cols()), d(m.rows(), m.cols());
        for (unsigned r = 0; r < m.rows(); ++r)
            for (unsigned c = 0; c < m.cols(); ++c) {
                dual_parts q = parts_of(m(r, c));
                p(r, c) = q.primal;
                d(r, c) = q.dual;
            }
        return {p, d};
    }
    if (is_a<GiNaC::function>(e)) return parts_of_function(e);
    if (is_a<GiNaC::relational>(e)) {
        if (!e.info(GiNaC::info_flags::relation_equal))
            throw domain_error("no dual extension of the inequality " + text(e) + ": dual numbers are not ordered");
        const dual_parts l = parts_of(e.lhs()), h = parts_of(e.rhs());
        return {l.primal == h.primal, l.dual == h.dual};
    }
    if (is_a<GiNaC::lst>(e)) {
        GiNaC::lst p, d;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            dual_parts q = parts_of(e.op(i));
            p.append(q.primal);
            d.append(q.dual);
        }
        return {p, d};
    }
    throw domain_error("no dual extension of " + text(e) + " (an integral or another object with the dual unit inside)");
}

}  // namespace

dual_parts parts(const ex& e) { return parts_of(e); }

namespace {
// relations, lists and matrices: each side, item or entry on its own
struct reduce_map : GiNaC::map_function {
    ex operator()(const ex& e) override { return reduce(e); }
};
}  // namespace

ex reduce(const ex& e) {
    if (!e.has(dual_unit())) return e;
    if (is_a<GiNaC::relational>(e) || is_a<GiNaC::lst>(e) || is_a<GiNaC::matrix>(e)) {
        reduce_map m;
        return e.map(m);
    }
    dual_parts p = parts_of(e);
    return make_dual(p.primal, p.dual);
}

ex primal(const ex& e) { return parts_of(e).primal; }
ex dual_part(const ex& e) { return parts_of(e).dual; }

ex make_dual(const ex& a, const ex& b) {
    if (a.has(dual_unit()) || b.has(dual_unit()))
        throw type_error("make_dual(a, b): the parts must be free of the dual unit eps");
    if (!a.is_zero() && !b.is_zero() && is_vector(a) != is_vector(b))
        throw type_error("make_dual(a, b): a and b must both be scalars or both be vectors");
    // two vector literals (or one and 0): one literal with dual components, [1, eps, 0]
    if ((is_a<GiNaC::matrix>(a) || a.is_zero()) && (is_a<GiNaC::matrix>(b) || b.is_zero()) &&
        (is_a<GiNaC::matrix>(a) || is_a<GiNaC::matrix>(b)))
        return (a + dual_unit() * b).evalm();
    return a + dual_unit() * b;
}

ex dual_cross(const ex& a, const ex& b) {
    const dual_parts x = parts_of(a), y = parts_of(b);
    return make_dual(cross(x.primal, y.primal), cross(x.primal, y.dual) + cross(x.dual, y.primal));
}

ex dual_dot(const ex& a, const ex& b) {
    const dual_parts x = parts_of(a), y = parts_of(b);
    return make_dual(dot(x.primal, y.primal), dot(x.primal, y.dual) + dot(x.dual, y.primal));
}

ex dual_triple(const ex& a, const ex& b, const ex& c) {
    const dual_parts x = parts_of(a), y = parts_of(b), z = parts_of(c);
    return make_dual(triple(x.primal, y.primal, z.primal),
                     triple(x.dual, y.primal, z.primal) + triple(x.primal, y.dual, z.primal) +
                         triple(x.primal, y.primal, z.dual));
}

bool dual_equal(const ex& a, const ex& b) {
    const dual_parts x = parts_of(a), y = parts_of(b);
    return equal(x.primal, y.primal) && equal(x.dual, y.dual);
}

}  // namespace symrep::dual
