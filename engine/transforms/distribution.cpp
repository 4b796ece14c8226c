// symrep/transforms/distribution.cpp -- see distribution.h.
#include "symrep/transforms/distribution.h"

#include "symrep/core/error.h"
#include "symrep/scalar/scalar.h"

namespace symrep::transforms {

using GiNaC::ex;

namespace {

ex dirac_eval(const ex& x, const ex& k) {
    if (GiNaC::is_a<GiNaC::numeric>(x) && !x.is_zero()) return 0;
    return dirac(x, k).hold();
}

ex dirac_deriv(const ex& x, const ex& k, unsigned diff_param) {
    if (diff_param == 1) throw domain_error("dirac: the order k of delta^(k) is not a variable");
    return dirac(x, k + 1);
}

}  // namespace

REGISTER_FUNCTION(dirac, eval_func(dirac_eval).derivative_func(dirac_deriv).set_name("dirac").set_return_type(
                             GiNaC::return_types::commutative))

bool has_impulse(const ex& f) {
    for (GiNaC::const_preorder_iterator i = f.preorder_begin(); i != f.preorder_end(); ++i)
        if (is_ex_the_function(*i, dirac)) return true;
    return false;
}

split_signal split_impulses(const ex& f, const GiNaC::symbol& t) {
    split_signal out;
    out.regular = 0;
    if (!has_impulse(f)) {
        out.regular = f;
        return out;
    }
    const ex e = GiNaC::expand(f);
    const auto refuse = [&](const ex& term, const std::string& why) {
        throw domain_error("transform: the impulse term " + message_text(term, text_limit::report) + " " + why +
                           " (impulses enter a signal linearly: c(t)*dirac(alpha*t + beta, k))");
    };
    const auto one_term = [&](const ex& term) {
        if (!has_impulse(term)) {
            out.regular += term;
            return;
        }
        ex c = 1, delta;
        const bool product = GiNaC::is_a<GiNaC::mul>(term);
        const std::size_t n = product ? term.nops() : 1;
        for (std::size_t i = 0; i < n; ++i) {
            const ex x = product ? term.op(i) : term;
            if (is_ex_the_function(x, dirac)) {
                if (!delta.is_zero()) refuse(term, "is a product of impulses");
                delta = x;
            } else if (has_impulse(x)) {
                refuse(term, "holds an impulse inside another function or power");
            } else {
                c *= x;
            }
        }
        const ex arg = delta.op(0), kx = delta.op(1);
        if (!kx.info(GiNaC::info_flags::nonnegint)) refuse(term, "has an order k that is not a non-negative integer");
        const unsigned k = unsigned(GiNaC::ex_to<GiNaC::numeric>(kx).to_int());
        if (!arg.is_polynomial(t) || arg.degree(t) != 1) refuse(term, "has an argument that is not linear in t");
        const ex alpha = tidy(arg.coeff(t, 1)), beta = tidy(arg.coeff(t, 0));
        if (!GiNaC::is_a<GiNaC::numeric>(alpha) || !GiNaC::ex_to<GiNaC::numeric>(alpha).is_real() || alpha.is_zero())
            refuse(term, "has a coefficient of t that is not a nonzero real number");
        if (beta.has(t)) refuse(term, "has an argument that is not linear in t");
        const ex a = tidy(-beta / alpha);
        const ex scale = 1 / (GiNaC::abs(alpha) * GiNaC::pow(alpha, k));
        // c(t) delta^(k)(t - a) = sum_j (-1)^j C(k, j) c^(j)(a) delta^(k-j)(t - a)
        ex cj = c;
        for (unsigned j = 0; j <= k; ++j) {
            const ex coefficient =
                tidy(scale * GiNaC::pow(-1, j) * GiNaC::binomial(k, j) * cj.subs(t == a));
            if (!coefficient.is_zero()) out.impulses.push_back({coefficient, a, k - j});
            cj = cj.diff(t);
        }
    };
    if (GiNaC::is_a<GiNaC::add>(e))
        for (std::size_t i = 0; i < e.nops(); ++i) one_term(e.op(i));
    else
        one_term(e);
    return out;
}

coeffs impulse_transform(const algebra_ptr& A, const coeffs& d, const std::vector<impulse>& impulses, bool all) {
    coeffs out = A->zero();
    const GiNaC::symbol u("u");
    coeffs expd;  // exp(-d u)
    for (const impulse& x : impulses) {
        if (!all) {
            const ex a = x.a;
            if (!GiNaC::is_a<GiNaC::numeric>(a) && !a.info(GiNaC::info_flags::nonnegative) &&
                !a.info(GiNaC::info_flags::negative))
                throw domain_error("transform: cannot decide whether the impulse at t = " +
                                   message_text(a, text_limit::report) +
                                   " lies in t >= 0 (give its position a value)");
            if (GiNaC::is_a<GiNaC::numeric>(a) ? GiNaC::ex_to<GiNaC::numeric>(a).is_negative()
                                               : bool(a.info(GiNaC::info_flags::negative)))
                continue;
        }
        coeffs term = A->power(d, x.k);
        if (!x.a.is_zero()) {
            if (expd.empty()) expd = A->exp(algebra::scale(-1, d), u);
            coeffs shift = expd;
            for (ex& y : shift) y = y.subs(u == x.a);
            term = A->multiply(term, shift);
        }
        out = algebra::add(out, algebra::scale(x.c, term));
    }
    for (ex& y : out) y = tidy(y);
    return out;
}

}  // namespace symrep::transforms
