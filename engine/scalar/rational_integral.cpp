// symrep/scalar/rational_integral.cpp -- int_0^t of a rational function by partial
// fractions over Q[x] (scalar/rational_integral.h).
#include "symrep/scalar/rational_integral.h"

#include <vector>

namespace symrep {

namespace {

struct factor_power {
    GiNaC::ex p;   // irreducible over Q, degree 1 or 2
    int k;         // its multiplicity
};

// The factors of den over Q, each of degree 1 or 2 (an irreducible quadratic without a real
// zero, of multiplicity one), with no zero in [0, inf); nothing otherwise.
std::optional<std::vector<factor_power>> admissible_factors(const GiNaC::ex& den, const GiNaC::ex& x) {
    const GiNaC::ex F = GiNaC::factor(den);
    std::vector<factor_power> out;
    for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::mul>(F) ? F.nops() : 1); ++i) {
        const GiNaC::ex f = GiNaC::is_a<GiNaC::mul>(F) ? F.op(i) : F;
        GiNaC::ex p = f;
        int k = 1;
        if (GiNaC::is_a<GiNaC::power>(f)) {
            if (!f.op(1).info(GiNaC::info_flags::posint)) return std::nullopt;
            p = f.op(0);
            k = GiNaC::ex_to<GiNaC::numeric>(f.op(1)).to_int();
        }
        if (!p.has(x)) continue;  // the numeric content
        const int deg = p.degree(x);
        if (deg == 1) {
            const GiNaC::ex a = p.coeff(x, 1), b = p.coeff(x, 0);
            // the zero -b/a must be negative: b/a > 0
            const GiNaC::ex q = b / a;
            if (!q.info(GiNaC::info_flags::positive)) return std::nullopt;
        } else if (deg == 2) {
            const GiNaC::ex a = p.coeff(x, 2), b = p.coeff(x, 1), c = p.coeff(x, 0);
            if (k != 1 || !(4 * a * c - b * b).info(GiNaC::info_flags::positive)) return std::nullopt;
        } else {
            return std::nullopt;
        }
        out.push_back({p, k});
    }
    return out;
}

}  // namespace

std::optional<GiNaC::ex> definite_rational_integral(const GiNaC::ex& f, const GiNaC::ex& x, const GiNaC::ex& t) {
    if (!GiNaC::is_a<GiNaC::symbol>(x) || !GiNaC::is_a<GiNaC::symbol>(t) || f.has(t)) return std::nullopt;
    const GiNaC::ex nd = GiNaC::normal(f).numer_denom();
    const GiNaC::ex num = GiNaC::expand(nd.op(0)), den = GiNaC::expand(nd.op(1));
    if (!num.is_polynomial(x) || !den.is_polynomial(x) || !den.has(x)) return std::nullopt;
    for (int i = 0; i <= den.degree(x); ++i)
        if (!den.coeff(x, i).info(GiNaC::info_flags::rational)) return std::nullopt;
    const auto factors = admissible_factors(den, x);
    if (!factors) return std::nullopt;

    // f = Pq + r/den; r/den = sum_j sum_(m <= k_j) (A_jm x + B_jm)/p_j^m (A only for quadratics)
    const GiNaC::ex Pq = GiNaC::quo(num, den, x), r = GiNaC::rem(num, den, x);
    GiNaC::lst unknowns;
    struct fraction {
        GiNaC::ex p, A, B;
        int m;
    };
    std::vector<fraction> parts;
    GiNaC::ex ansatz = 0;
    for (const auto& [p, k] : *factors)
        for (int m = 1; m <= k; ++m) {
            const GiNaC::symbol A, B;
            const bool quadratic = p.degree(x) == 2;
            if (quadratic) unknowns.append(A);
            unknowns.append(B);
            parts.push_back({p, quadratic ? GiNaC::ex(A) : GiNaC::ex(0), B, m});
            ansatz += ((quadratic ? GiNaC::ex(A) * x : GiNaC::ex(0)) + B) * GiNaC::quo(den, GiNaC::pow(p, m), x);
        }
    const GiNaC::ex diff = GiNaC::expand(r - ansatz);
    GiNaC::lst equations;
    for (int i = 0; i <= diff.degree(x); ++i) equations.append(diff.coeff(x, i) == 0);
    const GiNaC::ex solution = unknowns.nops() == 0 ? GiNaC::ex(GiNaC::lst{}) : GiNaC::lsolve(equations, unknowns);
    if (unknowns.nops() != 0 && solution.nops() != unknowns.nops()) return std::nullopt;

    // the polynomial part
    GiNaC::ex R = 0;
    const GiNaC::ex Pe = GiNaC::expand(Pq);
    for (int i = 0; i <= Pe.degree(x); ++i) R += Pe.coeff(x, i) * GiNaC::pow(t, i + 1) / (i + 1);
    for (const auto& part : parts) {
        const GiNaC::ex A = part.A.subs(solution), B = part.B.subs(solution);
        if (part.p.degree(x) == 1) {
            const GiNaC::ex a = part.p.coeff(x, 1), b = part.p.coeff(x, 0), pt = part.p.subs(x == t);
            if (part.m == 1) R += B / a * GiNaC::log(pt / b);
            else R += B / (a * (1 - part.m)) * (GiNaC::pow(pt, 1 - part.m) - GiNaC::pow(b, 1 - part.m));
        } else {
            // (A x + B)/p = A/(2a) p'/p + (B - A b/(2a))/p; int_0^t dx/p = 2/sqrt(D) [atan((2a x + b)/sqrt(D))]_0^t
            const GiNaC::ex a = part.p.coeff(x, 2), b = part.p.coeff(x, 1), c = part.p.coeff(x, 0);
            const GiNaC::ex sD = GiNaC::sqrt(4 * a * c - b * b);
            R += A / (2 * a) * GiNaC::log(part.p.subs(x == t) / c) +
                 (B - A * b / (2 * a)) * 2 / sD * (GiNaC::atan((2 * a * t + b) / sD) - GiNaC::atan(b / sD));
        }
    }
    // checked by differentiation (R(0) = 0 by construction)
    if (!GiNaC::normal(R.diff(GiNaC::ex_to<GiNaC::symbol>(t)) - f.subs(x == t)).is_zero()) return std::nullopt;
    return R;
}

}  // namespace symrep
