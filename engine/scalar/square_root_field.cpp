// symrep/scalar/square_root_field.cpp -- coefficients brought into the field of their one
// square root (scalar.h: in_square_root_field, simplified_square_roots). Moved here from
// mechanics/cauchy_problem.cpp so that the solver and the responses of signals/ share them.
#include <functional>
#include <map>

#include "symrep/scalar/scalar.h"

namespace symrep {

using GiNaC::ex;

// c in Q(...)[q]/(q^2 - A) for its one square root q = sqrt(A) of an expression:
// (M1 + M2 q)/D with M1, M2, D free of q (denominators rationalized by the
// conjugate), each part normalized. The solution of the reduced Foucault problem
// (VI.2.94) then has w0^2 where 1/(sqrt(w0^2 + |w|^2) - |w|) stood, and its
// coefficients collapse to the thesis's. Normalized (one fraction) without a root; unchanged
// with several.
ex in_square_root_field(const ex& c, bool rational_bases) {
    const square_roots_as_symbols r = with_square_roots_as_symbols(c, rational_bases);
    if (r.roots.empty()) {
        if (const auto s = sum_of_fractions(c)) return *s;
        return one_fraction(c);
    }
    if (r.roots.size() != 1 || r.roots[0].first.has(GiNaC::I)) return c;  // several: left as it is
    const ex& root = r.roots[0].first;
    const ex& q = r.roots[0].second;
    // the root inside another radical (Cardano's cube root of a + sqrt(D)) or inside a function
    // (cos(acos(8 sqrt(13)/169)/3) of three real roots): not a polynomial in q; left as it is
    for (auto it = r.e.preorder_begin(); it != r.e.preorder_end(); ++it)
        if ((GiNaC::is_a<GiNaC::function>(*it) && it->has(q)) ||
            (GiNaC::is_a<GiNaC::power>(*it) && it->op(0).has(q) &&
             !(GiNaC::is_a<GiNaC::numeric>(it->op(1)) && GiNaC::ex_to<GiNaC::numeric>(it->op(1)).is_integer())))
            return c;
    const ex nd = GiNaC::normal(r.e).numer_denom();
    auto reduce = [&](const ex& p) {  // p mod q^2 - A, as (p0, p1): p0 + p1 q
        const ex m = GiNaC::expand(GiNaC::rem(GiNaC::expand(p), GiNaC::pow(q, 2) - root, q, false));
        return std::make_pair(m.coeff(q, 0), m.coeff(q, 1));
    };
    const auto [n0, n1] = reduce(nd.op(0));
    const auto [d0, d1] = reduce(nd.op(1));
    // (n0 + n1 q)/(d0 + d1 q) = (n0 + n1 q)(d0 - d1 q)/(d0^2 - d1^2 A)
    const ex den = GiNaC::normal(d0 * d0 - d1 * d1 * root);
    if (den.is_zero()) return c;
    const ex m0 = GiNaC::normal((n0 * d0 - n1 * d1 * root) / den), m1 = GiNaC::normal((n1 * d0 - n0 * d1) / den);
    return m0 + m1 * GiNaC::sqrt(root);
}

// Each coefficient of the functions of t in c (sin, cos, exp of t, powers of t)
// brought into the field of its square root (in_square_root_field), then summed.
ex simplified_square_roots(const ex& c, const ex& t, bool rational_bases) {
    std::map<ex, ex, GiNaC::ex_is_less> by_t;  // t-part -> its coefficient
    // a term whose factors in t are single functions (t^k, exp, sin, cos) is split as it is;
    // only one with a sum in t is expanded (its coefficient fractions stay whole)
    std::function<void(const ex&, bool)> take = [&](const ex& term, bool expanded) {
        ex tp = 1, rest = 1;
        for (std::size_t j = 0; j < (GiNaC::is_a<GiNaC::mul>(term) ? term.nops() : 1); ++j) {
            const ex f = GiNaC::is_a<GiNaC::mul>(term) ? term.op(j) : term;
            if (!f.has(t)) {
                rest *= f;
            } else if (!expanded && (GiNaC::is_a<GiNaC::add>(f) || (GiNaC::is_a<GiNaC::power>(f) &&
                                                                   GiNaC::is_a<GiNaC::add>(f.op(0))))) {
                const ex e = GiNaC::expand(term);
                for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1); ++i)
                    take(GiNaC::is_a<GiNaC::add>(e) ? e.op(i) : e, true);
                return;
            } else {
                tp *= f;
            }
        }
        by_t[tp] += rest;
    };
    for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(c) ? c.nops() : 1); ++i)
        take(GiNaC::is_a<GiNaC::add>(c) ? c.op(i) : c, false);
    ex out = 0;
    for (const auto& [tp, k] : by_t) out += in_square_root_field(k, rational_bases) * tp;
    return out;
}

}  // namespace symrep

namespace symrep {

// the number field of the square roots of rationals in c (scalar.h)
ex in_square_roots_field(const ex& c, std::size_t max_roots) {
    const square_roots_as_symbols r = with_square_roots_as_symbols(c, true);
    std::vector<std::pair<GiNaC::numeric, ex>> field;  // b_i, q_i
    GiNaC::exmap others;                                // the roots of non-numbers back as they were
    for (const auto& [b, q] : r.roots) {
        if (GiNaC::is_a<GiNaC::numeric>(b) && GiNaC::ex_to<GiNaC::numeric>(b).is_rational())
            field.emplace_back(GiNaC::ex_to<GiNaC::numeric>(b), q);
        else
            others[q] = GiNaC::sqrt(b);
    }
    if (field.empty() || field.size() > max_roots) return c;
    for (int pass = 0; pass < 2 && !others.empty(); ++pass)  // a base may hold an earlier root
        for (auto& [q, s] : others) s = s.subs(others, GiNaC::subs_options::no_pattern);
    const ex e = others.empty() ? r.e : r.e.subs(others, GiNaC::subs_options::no_pattern);
    // p modulo every q_i^2 - b_i: each power q^k as b^(k div 2) q^(k mod 2)
    auto reduce = [&](ex p) {
        for (const auto& [b, q] : field) {
            p = GiNaC::expand(p);
            const int n = p.degree(q);
            if (n < 2) continue;
            ex out = 0;
            for (int k = 0; k <= n; ++k) out += p.coeff(q, k) * GiNaC::pow(GiNaC::ex(b), k / 2) * GiNaC::pow(q, k % 2);
            p = out;
        }
        return GiNaC::expand(p);
    };
    const ex nd = GiNaC::normal(e).numer_denom();
    ex N = reduce(nd.op(0)), D = reduce(nd.op(1));
    for (const auto& [b, q] : field) {
        const ex d1 = D.coeff(q, 1);
        if (d1.is_zero()) continue;
        const ex conjugate = D.coeff(q, 0) - d1 * q;  // (d0 + d1 q)(d0 - d1 q) = d0^2 - d1^2 b
        N = reduce(N * conjugate);
        D = reduce(D * conjugate);
        if (D.is_zero()) return c;
    }
    GiNaC::exmap back;
    for (const auto& [b, q] : field) back[q] = GiNaC::sqrt(GiNaC::ex(b));
    return GiNaC::normal(N / D).subs(back, GiNaC::subs_options::no_pattern);
}

}  // namespace symrep
