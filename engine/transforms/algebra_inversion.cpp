// symrep/transforms/algebra_inversion.cpp -- see algebra_inversion.h.
#include "symrep/transforms/algebra_inversion.h"

#include <algorithm>

#include "symrep/algebra/multicomplex.h"
#include "symrep/algebra/sobrero.h"
#include "symrep/core/error.h"
#include "symrep/scalar/equality.h"
#include "symrep/scalar/scalar.h"
#include "symrep/signals/representation.h"
#include "symrep/transforms/distribution.h"
#include "symrep/transforms/laplace.h"

namespace symrep::transforms {

using GiNaC::ex;

namespace {

/// x proved 0 after expanding and tidying it (scalar/equality.h).
bool proved_zero_tidy(const ex& x) { return proved_zero(tidy(GiNaC::expand(x))); }


// F(s) = P(s) + R(s): P the polynomial part (impulses sum c_k dirac(t, k)), R proper.
struct split_rational {
    ex impulses = 0, proper = 0;
};
split_rational split_polynomial_part(const ex& F, const GiNaC::symbol& s, const GiNaC::symbol& t) {
    split_rational out;
    const ex nd = GiNaC::normal(F).numer_denom();
    const ex num = nd.op(0).expand(), den = nd.op(1).expand();
    if (!num.is_polynomial(s) || !den.is_polynomial(s))
        throw domain_error("inverse_transform: the component " + message_text(F, text_limit::report) +
                           " is not a rational function of s (only transforms of quasi-polynomials and impulses "
                           "are inverted in closed form)");
    const ex q = GiNaC::quo(num, den, s), r = GiNaC::rem(num, den, s);
    for (int k = 0; k <= q.degree(s); ++k) {
        const ex c = tidy(q.coeff(s, k));
        if (!c.is_zero()) out.impulses += c * dirac(t, k);
    }
    out.proper = tidy(r / den);
    return out;
}

}  // namespace

algebra_inverse inverse_transform(const algebra_ptr& A, const coeffs& T, const coeffs& d, const GiNaC::symbol& t) {
    A->check_size(T, "inverse_transform");
    A->check_size(d, "inverse_transform");
    const GiNaC::symbol s("s");
    algebra_inverse out;
    const std::vector<ex> vars = symbols_by_name(d);
    if (vars.empty())
        throw domain_error("inverse_transform: d has no symbol; the transform must be given as a function of the "
                           "algebra variable d (e.g. d = w0*i0 + w1*i1 over multicomplex(1), d = x + eps over sobrero(n))");
    if (dynamic_cast<const multicomplex*>(A.get()) != nullptr) {
        const auto Dc = A->idempotent_components(d);
        const auto Tc = A->idempotent_components(T);
        // the variable solved from i Omega_p = s: the first symbol of d (by name) on which every
        // component of d depends linearly
        const ex* x = nullptr;
        for (const auto& v : vars) {
            bool ok = true;
            for (const ex& c : Dc) {
                const ex e = c.expand();
                ok = ok && e.is_polynomial(v) && e.degree(v) == 1 && !tidy(e.coeff(v, 1)).is_zero();
            }
            if (ok) {
                x = &v;
                break;
            }
        }
        if (x == nullptr)
            throw domain_error("inverse_transform: no symbol of d enters every idempotent component i Omega_p of d "
                               "linearly (write d = omega0*i0 + ... + omegan*in)");
        ex f0, g0;
        for (std::size_t p = 0; p < Dc.size(); ++p) {
            const ex e = Dc[p].expand();
            const ex xs = (s - e.coeff(*x, 0)) / e.coeff(*x, 1);
            const ex Fp = tidy(GiNaC::normal(Tc[p].subs(*x == xs)));
            for (const auto& v : vars)
                if (Fp.has(v))
                    throw domain_error("inverse_transform: the idempotent component " + std::to_string(p) +
                                       " of T is not a function of i Omega_p alone (it still holds " +
                                       GiNaC::ex_to<GiNaC::symbol>(v).get_name() + " when i Omega_p = s): T is not a transform over this d");
            const split_rational sr = split_polynomial_part(Fp, s, t);
            ex fp = sr.impulses, gp = 0;
            if (!sr.proper.is_zero()) {
                const ex raw = GiNaC::expand(inverse_laplace(sr.proper, s, t));
                const auto one = [&](const ex& term) {
                    int side = 0;  // -1 causal, +1 anti-causal
                    // the poles of the term named in sorted order (the message does not depend on GiNaC's)
                    std::vector<std::string> names;
                    for (const auto& e2 : signals::exponents_of(term, t))
                        names.push_back(message_text(e2.lambda, text_limit::fragment));
                    std::sort(names.begin(), names.end());
                    std::string poles;
                    for (const auto& nm : names) poles += (poles.empty() ? "" : ", ") + nm;
                    for (const auto& e2 : signals::exponents_of(term, t)) {
                        const ex re = tidy(GiNaC::real_part(e2.lambda.expand()));
                        GiNaC::numeric v;
                        if (!evaluate_numeric(re, 30, v) || !v.is_real())
                            throw domain_error("inverse_transform: cannot decide the sign of the real part of the poles " +
                                               poles +
                                               " (it says whether its term lies before or after t = 0)");
                        if (v.is_zero())
                            throw domain_error("inverse_transform: the component " + std::to_string(p) +
                                               " has the poles " + poles +
                                               " on the imaginary axis: it is not the Fourier transform of an L1 "
                                               "signal (V.2.36 needs f in L1)");
                        const int sd = v.is_negative() ? -1 : 1;
                        if (side != 0 && side != sd)
                            throw domain_error("inverse_transform: the term " + message_text(term, text_limit::report) +
                                               " mixes poles on both sides of the imaginary axis");
                        side = sd;
                    }
                    if (side < 0) fp += term;
                    else gp -= term;
                };
                if (GiNaC::is_a<GiNaC::add>(raw))
                    for (std::size_t i = 0; i < raw.nops(); ++i) one(raw.op(i));
                else
                    one(raw);
            }
            fp = tidy(fp);
            gp = tidy(gp);
            if (p == 0) {
                f0 = fp;
                g0 = gp;
            } else if (!proved_zero_tidy(fp - f0) || !proved_zero_tidy(gp - g0)) {
                throw domain_error("inverse_transform: the idempotent components 0 and " + std::to_string(p) +
                                   " give different signals (" + message_text(f0, text_limit::fragment) + " and " +
                                   message_text(fp, text_limit::fragment) + "): T is not a transform (V.2.39)");
            }
        }
        out.f = f0;
        out.g = g0;
        out.report = "every idempotent component F(i Omega_p), p = 0.." + std::to_string(Dc.size() - 1) +
                     ", inverted along the imaginary axis gives the same signal (V.2.37-39): the sum over the "
                     "idempotents is f~ times the unit";
        return out;
    }
    const auto* S = dynamic_cast<const sobrero*>(A.get());
    if (S == nullptr)
        throw algebra_error("inverse_transform: the inversion is stated over multicomplex(n) (Thm V.2.3) and "
                            "sobrero(n) (Thm V.3.3), not over " + A->name());
    const unsigned n = S->n();
    // d = sigma + eps (+ j omega): coordinate 0 a symbol, coordinate 1 (eps) = 1, n+1 (j) a symbol or 0
    const ex sigma = d[0];
    if (!GiNaC::is_a<GiNaC::symbol>(sigma) || (n >= 1 && !(d[1] - 1).is_zero()))
        throw domain_error("inverse_transform: over sobrero(n) write d = x + eps (+ j*w) with x (and w) symbols (V.3.7)");
    for (std::size_t k = 2; k < d.size(); ++k)
        if (k != n + 1 && !d[k].is_zero())
            throw domain_error("inverse_transform: over sobrero(n) write d = x + eps (+ j*w) (V.3.7): the coordinate of " +
                               A->basis_name(k) + " must be 0");
    const ex omega = d[n + 1];
    GiNaC::exmap at_s;
    at_s[sigma] = s;
    if (GiNaC::is_a<GiNaC::symbol>(omega)) at_s[omega] = 0;
    else if (!omega.is_zero())
        throw domain_error("inverse_transform: the coordinate of j in d must be a symbol or 0");
    std::vector<ex> F(n + 1);
    for (unsigned k = 0; k <= n; ++k) F[k] = tidy(GiNaC::normal((T[k] + GiNaC::I * T[n + 1 + k]).subs(at_s)));
    const split_rational s0 = split_polynomial_part(F[0], s, t);
    const ex regular = s0.proper.is_zero() ? ex(0) : inverse_laplace(s0.proper, s, t);
    // V.3.40 for each k, then V.3.41
    std::vector<ex> inv(n + 1);
    inv[0] = regular;
    for (unsigned k = 1; k <= n; ++k) {
        const split_rational sk = split_polynomial_part(F[k], s, t);
        inv[k] = sk.proper.is_zero() ? ex(0) : inverse_laplace(sk.proper, s, t);
        if (!proved_zero_tidy(inv[k] - GiNaC::pow(-t, k) * regular / GiNaC::factorial(k)))
            throw domain_error("inverse_transform: the eps^" + std::to_string(k) + " coefficient of T is not " +
                               "L[(-t)^k f / k!] (V.3.40): T is not a transform over sobrero(" + std::to_string(n) + ")");
    }
    for (unsigned m = 1; m <= n; ++m) {
        ex c = 0;
        for (unsigned k = 0; k <= m; ++k) c += inv[k] * GiNaC::pow(t, m - k) / GiNaC::factorial(m - k);
        if (!proved_zero_tidy(c))
            throw internal_error("inverse_transform: the eps^" + std::to_string(m) + " term of V.3.41 is not 0");
    }
    out.f = tidy(s0.impulses + regular);
    out.report = "the eps^0 coefficient inverted (V.3.38); L^-1 of the eps^k coefficient is (-t)^k f/k! for k = 1.." +
                 std::to_string(n) + " (V.3.40), so every nilpotent term of V.3.39 is 0 (V.3.41)";
    return out;
}

}  // namespace symrep::transforms
