// symrep/mechanics/operator_ode.cpp -- the solver of operator_ode.h.
#include "symrep/mechanics/operator_ode.h"

#include <map>

#include "symrep/algebra/exact_linear.h"
#include "symrep/scalar/polynomial_roots.h"
#include "symrep/scalar/scalar.h"
#include "symrep/core/error.h"

namespace symrep::mechanics {

using GiNaC::ex;

namespace {

// sqrt of a polynomial, exact on its square factors: sqrt(4 (w0 - W)^2) = 2 (w0 - W)
// (up to a sign, which does not matter for a root pair). Not scalar's sign_free_sqrt: the sign of
// a square factor here is the one factor() gives (sign_free_sqrt chooses it at a generic point),
// and it decides which of the two roots of the quadratic over C below comes first.
ex sqrt_poly(const ex& e) {
    // GiNaC's factor() keeps the integer content: sqrt(4 a + 4 b) = 2 sqrt(a + b)
    const ex ee = GiNaC::expand(e);
    if (!ee.is_zero() && !GiNaC::is_a<GiNaC::numeric>(ee)) {
        const GiNaC::numeric c = ee.integer_content();
        if (!c.is_zero() && c != 1) return GiNaC::sqrt(ex(c)) * sqrt_poly(GiNaC::expand(ee / c));
    }
    GiNaC::exmap back;
    std::map<ex, ex, GiNaC::ex_is_less> seen;
    const ex f = GiNaC::factor(GiNaC::expand(atomize(GiNaC::expand(e), seen, back)));
    ex out = 1, rest = 1;
    for (const auto& [b, m] : factors_of(f)) {
        if (GiNaC::is_a<GiNaC::numeric>(b)) {
            // a negative unit stays under the root: which sign factor() gives the
            // other factors depends on the order of terms (GiNaC hashes, which vary
            // from run to run), and sqrt(u^2 + v^2) must not become i sqrt(-u^2 - v^2)
            const ex bm = GiNaC::pow(b, m);
            if (GiNaC::ex_to<GiNaC::numeric>(bm).is_negative()) {
                out *= GiNaC::sqrt(-bm);
                rest *= -1;
            } else {
                out *= GiNaC::sqrt(bm);
            }
            continue;
        }
        out *= GiNaC::pow(b, m / 2);
        if (m % 2) rest *= b;
    }
    return (out * GiNaC::sqrt(rest)).subs(back);
}

ex exact_sqrt(const ex& e) {
    const ex n = GiNaC::normal(e);
    return tidy(sqrt_poly(GiNaC::numer(n)) / sqrt_poly(GiNaC::denom(n)));
}

cex eval_poly(const std::vector<cex>& a, const cex& z) {
    cex r(ex(0), ex(0));
    for (std::size_t m = a.size(); m-- > 0;) r = tidy_cex(r * z + a[m]);
    return r;
}

std::vector<cex> derivative_poly(const std::vector<cex>& a) {
    std::vector<cex> d;
    for (std::size_t m = 1; m < a.size(); ++m) d.push_back(ex(long(m)) * a[m]);
    return d;
}

std::string poly_text(const std::vector<cex>& a) {
    const GiNaC::symbol s("s");
    ex p = 0;
    for (std::size_t m = 0; m < a.size(); ++m) p += (a[m].re + GiNaC::I * a[m].im) * GiNaC::pow(s, int(m));
    return message_text(p);
}

quasi_polynomial nth_derivative(quasi_polynomial q, unsigned n) {
    for (unsigned i = 0; i < n; ++i) q = q.derivative();
    return q;
}

}  // namespace

std::vector<characteristic_root> characteristic_roots(const std::vector<cex>& a, GiNaC::exmap* abbreviations) {
    if (a.empty() || is_zero_cex(a.back()))
        throw domain_error("characteristic polynomial " + poly_text(a) +
                           ": the leading coefficient is zero");
    const std::size_t M = a.size() - 1;
    if (M == 0) return {};
    std::vector<cex> candidates;
    // a complex quadratic with a real discriminant of known sign: the quadratic
    // formula over C (s^2 + 2 i |w| s + w0^2 of VI.2.93 has the roots
    // i(-|w| +- sqrt(|w|^2 + w0^2)), which p conj(p), irreducible of degree 4, hides; the
    // formulas of scalar/polynomial_roots.h are those of real factors over Q(atoms))
    int quadratic_sign = 2;
    bool complex_quadratic = false;  // complex coefficients: the quadratic formula over C
    cex D, sq;
    bool abbreviated = false;  // sq holds symbols: the two roots are distinct by assumption
    if (M == 2) {
        D = tidy_cex(a[1] * a[1] - cex(ex(4), ex(0)) * a[2] * a[0]);
        complex_quadratic = !is_zero_scalar(a[1].im) || !is_zero_scalar(a[2].im) || !is_zero_scalar(a[0].im);
        if (is_zero_scalar(D.im)) {
            quadratic_sign = discriminant_sign(D.re);
            // a real discriminant of unknown sign: sqrt(D) = i sqrt(-D); the impulse
            // response is even in sqrt(D), hence analytic in D, so the form holds for
            // either sign (cos(i x) = cosh(x)); the double root D = 0 is excluded
            if (quadratic_sign == 2 && complex_quadratic) sq = cex(ex(0), exact_sqrt(-D.re));
        } else {
            // a complex discriminant D = u + i v, v != 0 (the damped Foucault pendulum
            // s^2 + (c + 2 i |w|) s + w0^2): sqrt(D) = p + i q with
            //   q = sqrt((|D| - u)/2), p = v/(2 q)   or   p = sqrt((|D| + u)/2), q = v/(2 p),
            // |D| = sqrt(u^2 + v^2); both hold for v != 0 (p q = v/2, p^2 - q^2 = u).
            // The second where u > 0 is known, the first otherwise (it stays regular
            // as v -> 0 with u < 0, the weakly damped oscillator).
            const ex u = D.re, v = D.im, modulus = exact_sqrt(tidy(u * u + v * v));
            ex p, q;
            if (discriminant_sign(u) == 1) {
                p = exact_sqrt(tidy((modulus + u) / 2));
                q = tidy(v / (2 * p));
            } else {
                q = exact_sqrt(tidy((modulus - u) / 2));
                p = tidy(v / (2 * q));
            }
            if (abbreviations) {
                // written once: the coefficients stay rational in p and q
                const GiNaC::realsymbol ps("p"), qs("q");
                (*abbreviations)[ps] = p;
                (*abbreviations)[qs] = q;
                sq = cex(ps, qs);
                abbreviated = true;
            } else {
                sq = cex(p, q);
            }
        }
    }
    if (M == 1) {
        candidates.push_back(-1 * (a[0] * inverse_cex(a[1], "a characteristic root")));
    } else if (M == 2 && (!sq.re.is_zero() || !sq.im.is_zero())) {
        const cex inv2a = inverse_cex(cex(2 * a[2].re, 2 * a[2].im), "a characteristic root");
        candidates.push_back(tidy_cex((sq - a[1]) * inv2a));
        candidates.push_back(tidy_cex((cex(ex(0), ex(0)) - sq - a[1]) * inv2a));
        if (abbreviated) return {{candidates[0], 1}, {candidates[1], 1}};
    } else if (quadratic_sign != 2) {
        const cex real_sq = quadratic_sign >= 0 ? cex(exact_sqrt(D.re), ex(0)) : cex(ex(0), exact_sqrt(-D.re));
        const cex inv2a = inverse_cex(cex(2 * a[2].re, 2 * a[2].im), "a characteristic root");
        candidates.push_back(tidy_cex((real_sq - a[1]) * inv2a));
        if (quadratic_sign != 0) candidates.push_back(tidy_cex((cex(ex(0), ex(0)) - real_sq - a[1]) * inv2a));
    } else {
        const GiNaC::symbol s("s");
        ex Pr = 0, Pi = 0;
        bool real = true;
        for (std::size_t m = 0; m <= M; ++m) {
            Pr += a[m].re * GiNaC::pow(s, int(m));
            Pi += a[m].im * GiNaC::pow(s, int(m));
            if (!is_zero_scalar(a[m].im)) real = false;
        }
        const ex N = real ? Pr : Pr * Pr + Pi * Pi;
        // the roots of N's rational factors (scalar/polynomial_roots.h); an undecidable sign
        // (c^2 - 4 w0^2 of s^2 + c s + w0^2) takes the oscillating form e^(re t) (cos(r t),
        // sin(r t)/r), even in r and analytic in disc, so it holds for either sign
        for (const auto& g : rational_factors(N, s))
            for (const auto& r : factor_roots(g.f, s, g.multiplicity, "characteristic polynomial " + poly_text(a), true)) {
                candidates.push_back({r.re, r.im});
                if (!r.im.is_zero()) candidates.push_back({r.re, tidy(-r.im)});
            }
    }
    std::vector<characteristic_root> roots;
    unsigned total = 0;
    for (const cex& z : candidates) {
        bool dup = false;
        for (const auto& r : roots) dup = dup || is_zero_cex(r.z - z);
        if (dup) continue;
        unsigned m = 0;
        std::vector<cex> d = a;
        while (d.size() > 1 && is_zero_cex(eval_poly(d, z))) {
            ++m;
            d = derivative_poly(d);
        }
        if (m > 0) {
            roots.push_back({z, m});
            total += m;
        }
    }
    if (total != M)
        throw closed_form_error("characteristic polynomial " + poly_text(a) + ": found roots of total "
                                "multiplicity " + std::to_string(total) + " instead of " +
                                std::to_string(M));
    return roots;
}

quasi_polynomial impulse_response(const std::vector<cex>& a, const ex& t, GiNaC::exmap* abbreviations) {
    const std::vector<characteristic_root> roots = characteristic_roots(a, abbreviations);
    const std::size_t M = a.size() - 1;
    struct basis_fn { cex z; unsigned j; };
    std::vector<basis_fn> basis;
    for (const auto& r : roots)
        for (unsigned j = 0; j < r.multiplicity; ++j) basis.push_back({r.z, j});
    // real form of the complex system sum_b beta_b phi_b^{(i)}(0) = delta_{i,M-1} / a_M
    const std::size_t n = basis.size();
    std::vector<std::vector<ex>> A(2 * M, std::vector<ex>(2 * n, ex(0)));
    std::vector<ex> rhs(2 * M, ex(0));
    for (std::size_t i = 0; i < M; ++i)
        for (std::size_t b = 0; b < n; ++b) {
            if (i < basis[b].j) continue;
            cex zp(ex(1), ex(0));
            for (std::size_t p = 0; p < i - basis[b].j; ++p) zp = tidy_cex(zp * basis[b].z);
            const ex f = falling_factorial(long(i), long(basis[b].j));
            A[2 * i][b] = f * zp.re;
            A[2 * i][n + b] = -f * zp.im;
            A[2 * i + 1][b] = f * zp.im;
            A[2 * i + 1][n + b] = f * zp.re;
        }
    const cex lead = inverse_cex(a[M], "the impulse response");
    rhs[2 * (M - 1)] = lead.re;
    rhs[2 * (M - 1) + 1] = lead.im;
    const auto beta = solve_linear(std::move(A), std::move(rhs));
    if (!beta)
        throw closed_form_error("impulse response of " + poly_text(a) +
                                ": the initial-value system is singular (roots not distinct)");
    quasi_polynomial y = quasi_polynomial::constant(0, t);
    for (std::size_t b = 0; b < n; ++b)
        y = y + quasi_polynomial::monomial({(*beta)[b], (*beta)[n + b]}, basis[b].j, basis[b].z, t);
    return y;
}

operator_polynomial operator_polynomial_from(const ex& p, const GiNaC::symbol& K) {
    const ex e = GiNaC::expand(p);
    if (!e.is_polynomial(K))
        throw domain_error("operator polynomial: " + message_text(p) + " is not a polynomial in " + message_text(K));
    const int d = e.degree(K);
    operator_polynomial a;
    for (int j = 0; j <= d; ++j) a.push_back(tidy(e.coeff(K, j)));
    return a;
}

const placeholder_coefficients& operator_solution::of(const std::string& name) const {
    for (const auto& p : terms)
        if (p.vector == name) return p;
    throw domain_error("operator solution: no placeholder vector named '" + name + "'");
}

ex operator_solution::coefficient(const std::string& name, unsigned k) const {
    if (k > 2) throw domain_error("operator solution: coefficient index " + std::to_string(k) + " > 2");
    return of(name).c[k].to_ex().subs(abbreviations);
}

namespace {

void validate(const operator_ode& ode, const ex& t) {
    if (!GiNaC::is_a<GiNaC::symbol>(t)) throw domain_error("operator ODE: " + message_text(t) + " is not a symbol");
    if (ode.A.size() < 2)
        throw domain_error("operator ODE: order " + std::to_string(int(ode.A.size()) - 1) +
                           " < 1 (A must hold A_0 .. A_M, M >= 1)");
    const std::size_t M = ode.A.size() - 1;
    if (ode.initial.size() != M)
        throw domain_error("operator ODE of order " + std::to_string(M) + ": " +
                           std::to_string(ode.initial.size()) + " initial-value names given, " +
                           std::to_string(M) + " needed (x(0), ..., x^(M-1)(0))");
    for (const auto& Am : ode.A)
        for (const ex& c : Am)
            if (c.has(t))
                throw domain_error("operator ODE: coefficient " + message_text(c) + " depends on " + message_text(t) +
                                   " (only constant coefficients are solved here)");
    for (const auto& f : ode.forcing) {
        if (f.vector.empty()) throw domain_error("operator ODE: a forcing term has no vector name");
        if (!f.q.is_zero() && !f.q.variable().is_equal(t))
            throw domain_error("operator ODE: a forcing function is in " + message_text(f.q.variable()) + ", not in " +
                               message_text(t));
    }
}

struct accumulator {
    operator_solution sol;
    void add(const std::string& name, const std::array<quasi_polynomial, 3>& c) {
        for (auto& p : sol.terms)
            if (p.vector == name) {
                for (int k = 0; k < 3; ++k) p.c[k] = p.c[k] + c[k];
                return;
            }
        sol.terms.push_back({name, c});
    }
};

ex coeff_at(const operator_polynomial& A, std::size_t j) { return j < A.size() ? A[j] : ex(0); }

// response to x^{(i)}(0) = 1: sum_{m>i} a_m y^{(m-1-i)}
quasi_polynomial initial_response(const std::vector<cex>& a, const quasi_polynomial& y, std::size_t i) {
    quasi_polynomial r = quasi_polynomial::constant(0, y.variable());
    for (std::size_t m = i + 1; m < a.size(); ++m) r = r + a[m] * nth_derivative(y, unsigned(m - 1 - i));
    return r;
}

}  // namespace

operator_solution solve(const operator_ode& ode, const rotation_operator_algebra& R, const ex& t) {
    return solve(ode, R, t, placeholder_factors{});
}

operator_solution solve(const operator_ode& ode, const rotation_operator_algebra& R, const ex& t,
                        const placeholder_factors& factors) {
    validate(ode, t);
    const std::size_t M = ode.A.size() - 1;
    accumulator acc;
    acc.sol.t = t;
    acc.sol.Omega = R.omega();
    const quasi_polynomial zero = quasi_polynomial::constant(0, t);
    auto factors_of_name = [&](const std::string& name) {
        const auto it = factors.find(name);
        return it == factors.end() ? cyclic_factors{} : it->second;
    };
    // the scalar problems some placeholder needs (II.1.23-24: m_P decides)
    bool need_axial = false, need_planar = false;
    for (const std::string& nm : ode.initial) {
        need_axial = need_axial || factors_of_name(nm).axial;
        need_planar = need_planar || factors_of_name(nm).planar;
    }
    for (const auto& f : ode.forcing) {
        need_axial = need_axial || factors_of_name(f.vector).axial;
        need_planar = need_planar || factors_of_name(f.vector).planar;
    }
    std::vector<cex> a0(M + 1);
    for (std::size_t m = 0; m <= M; ++m) a0[m] = cex(tidy(coeff_at(ode.A[m], 0)), ex(0));
    if (is_zero_cex(a0[M]))
        throw algebra_error("operator ODE: the leading coefficient A_" + std::to_string(M) +
                            "(K) is a zero divisor in the algebra of K = w x (its value at K = 0 is "
                            "0), so x^(" + std::to_string(M) + ") cannot be solved for");
    // the degenerate algebra solves every placeholder from the axial impulse response
    const quasi_polynomial y0 = need_axial || R.degenerate() ? impulse_response(a0, t, &acc.sol.abbreviations) : zero;

    if (!R.degenerate()) {
        std::vector<cex> a1(M + 1);
        for (std::size_t m = 0; m <= M; ++m) a1[m] = R.at_i_omega(ode.A[m]);
        if (is_zero_cex(a1[M]))
            throw algebra_error("operator ODE: the leading coefficient A_" + std::to_string(M) +
                                "(K) is a zero divisor in the algebra of K = w x (it vanishes at K = i|w|)"
                                ", so x^(" + std::to_string(M) + ") cannot be solved for");
        const quasi_polynomial y1 = need_planar ? impulse_response(a1, t, &acc.sol.abbreviations) : zero;
        for (std::size_t i = 0; i < M; ++i) {
            const cyclic_factors m = factors_of_name(ode.initial[i]);
            if (!m.axial && !m.planar) continue;
            acc.add(ode.initial[i], R.recombine(m.axial ? initial_response(a0, y0, i) : zero,
                                                m.planar ? initial_response(a1, y1, i) : zero, m));
        }
        for (const auto& f : ode.forcing) {
            const cyclic_factors m = factors_of_name(f.vector);
            if (!m.axial && !m.planar) continue;
            const quasi_polynomial axial = m.axial && f.power == 0 ? convolution(y0, f.q) : zero;
            cex ip(ex(1), ex(0));
            for (unsigned k = 0; k < f.power; ++k) ip = tidy_cex(ip * cex(ex(0), R.omega()));
            acc.add(f.vector, R.recombine(axial, m.planar ? convolution(y1, ip * f.q) : zero, m));
        }
        return acc.sol;
    }

    // Omega = 0: K^3 = 0, triangular in the powers of K; a placeholder with K P = 0
    // (m_P = X) needs the K^0 part only
    std::vector<ex> beta(M + 1), gamma(M + 1);
    for (std::size_t m = 0; m <= M; ++m) {
        beta[m] = coeff_at(ode.A[m], 1);
        gamma[m] = coeff_at(ode.A[m], 2);
    }
    auto apply = [&](const std::vector<ex>& c, const quasi_polynomial& g) {
        quasi_polynomial r = zero;
        for (std::size_t m = 0; m <= M; ++m)
            if (!c[m].is_zero()) r = r + c[m] * nth_derivative(g, unsigned(m));
        return r;
    };
    auto triangular = [&](const quasi_polynomial& g0, const std::array<quasi_polynomial, 3>& s, cyclic_factors m) {
        if (m.axial && !m.planar) return std::array<quasi_polynomial, 3>{g0, zero, zero};
        const quasi_polynomial g1 = convolution(y0, s[1] - apply(beta, g0));
        const quasi_polynomial g2 = convolution(y0, s[2] - apply(beta, g1) - apply(gamma, g0));
        return std::array<quasi_polynomial, 3>{g0, g1, g2};
    };
    for (std::size_t i = 0; i < M; ++i) {
        const cyclic_factors m = factors_of_name(ode.initial[i]);
        if (!m.axial && !m.planar) continue;
        acc.add(ode.initial[i], triangular(initial_response(a0, y0, i), {zero, zero, zero}, m));
    }
    for (const auto& f : ode.forcing) {
        const cyclic_factors m = factors_of_name(f.vector);
        if (!m.axial && !m.planar) continue;
        std::array<quasi_polynomial, 3> s{zero, zero, zero};
        if (f.power < 3) s[f.power] = f.q;
        acc.add(f.vector, triangular(convolution(y0, s[0]), s, m));
    }
    return acc.sol;
}

verification verify(const operator_ode& ode, const rotation_operator_algebra& R,
                    const operator_solution& sol) {
    return verify(ode, R, sol, placeholder_factors{});
}

verification verify(const operator_ode& ode, const rotation_operator_algebra& R,
                    const operator_solution& sol, const placeholder_factors& factors) {
    validate(ode, sol.t);
    const GiNaC::symbol& t = GiNaC::ex_to<GiNaC::symbol>(sol.t);
    const std::size_t M = ode.A.size() - 1;
    verification v;
    auto fail = [&](bool& flag, const std::string& what) {
        flag = false;
        if (!v.detail.empty()) v.detail += "; ";
        v.detail += what;
    };
    auto factors_of_name = [&](const std::string& name) {
        const auto it = factors.find(name);
        return it == factors.end() ? cyclic_factors{} : it->second;
    };
    std::vector<std::string> names;
    for (const auto& p : sol.terms) names.push_back(p.vector);
    for (const auto& f : ode.forcing) {
        bool found = !factors_of_name(f.vector).axial && !factors_of_name(f.vector).planar;  // m = 1: no term
        for (const auto& n : names) found = found || n == f.vector;
        if (!found) fail(v.residual_zero, "forcing vector " + f.vector + " missing from the solution");
    }
    std::string culprit;
    auto is_zero_function = [&](const ex& x) {
        try {
            if (quasi_polynomial::from_ex(tidy(x), t).is_zero()) return true;
            culprit = message_text(tidy(x));
        } catch (const domain_error& e) {
            culprit = std::string("not a quasi-polynomial: ") + e.what();
        }
        return false;
    };
    for (const auto& p : sol.terms) {
        const cyclic_factors mp = factors_of_name(p.vector);
        const element G = R.make(sol.coefficient(p.vector, 0), sol.coefficient(p.vector, 1),
                                 sol.coefficient(p.vector, 2));
        element lhs = R.make(0, 0, 0);
        for (std::size_t m = 0; m <= M; ++m) {
            const element Gm = G.map_coeffs([&](const ex& x) { return GiNaC::diff(x, t, int(m)); });
            lhs = lhs + R.polynomial(ode.A[m]) * Gm;
            // initial data
            if (m < M) {
                const element g0 = Gm.map_coeffs([&](const ex& x) { return tidy(x.subs(t == 0)); });
                const element want = ode.initial[m] == p.vector ? R.one() : R.make(0, 0, 0);
                if (!R.vanishes_modulo((g0 - want).coefficients(), mp, [](const ex& x) { return is_zero_scalar(x); }))
                    fail(v.initial_ok, "x^(" + std::to_string(m) + ")(0) is wrong on " + p.vector);
            }
        }
        element rhs = R.make(0, 0, 0);
        for (const auto& f : ode.forcing)
            if (f.vector == p.vector) rhs = rhs + f.q.to_ex() * R.K().pow(long(f.power));
        const element res = lhs - rhs;
        if (!R.vanishes_modulo(res.coefficients(), mp, is_zero_function))
            fail(v.residual_zero,
                 "residual on " + p.vector + " modulo " + message_text(R.minimal_polynomial(mp)) + ": " + culprit);
    }
    return v;
}

}  // namespace symrep::mechanics
