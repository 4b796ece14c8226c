// symrep/signals/multicomplex_signals.cpp -- see multicomplex_signals.h.
#include "symrep/signals/multicomplex_signals.h"

#include <map>

#include "symrep/core/error.h"
#include "symrep/scalar/scalar.h"

namespace symrep::signals {

using GiNaC::ex;
using namespace GiNaC;

namespace {

std::size_t index_of_unit(const coeffs& u) {
    for (std::size_t i = 0; i < u.size(); ++i)
        if (!u[i].is_zero()) return i;
    throw algebra_error("signals: an imaginary unit with no coordinate");
}

coeffs carrier_factor(const multicomplex& A, unsigned k, const ex& omega, const ex& t) {
    coeffs f = A.unit();
    f[0] = GiNaC::cos(omega * t);
    const coeffs ik = A.imag_unit(k);
    f[index_of_unit(ik)] += GiNaC::sin(omega * t) * ik[index_of_unit(ik)];
    return f;
}

/// cos, sin of t-free arguments written with exp(I x), so that a component r (cos x - I sin x)
/// reads as one term r exp(-I x).
struct exponential_form : GiNaC::map_function {
    ex operator()(const ex& e) override {
        using GiNaC::I;
        if (is_ex_the_function(e, cos)) {
            const ex x = (*this)(e.op(0));
            return (GiNaC::exp(I * x) + GiNaC::exp(-I * x)) / 2;
        }
        if (is_ex_the_function(e, sin)) {
            const ex x = (*this)(e.op(0));
            return (GiNaC::exp(I * x) - GiNaC::exp(-I * x)) / (2 * I);
        }
        return e.map(*this);
    }
};

/// z = r e^(I theta): from the exponential form when z is one term c exp(S) (c a real number of
/// known sign, or a complex number), else r = sqrt(z conj(z)), theta = atan2(Im z, Re z).
struct polar {
    ex r, theta;
};
polar polar_of(const ex& z) {
    exponential_form to_exp;
    const ex e = to_exp(z).expand();
    if (!GiNaC::is_a<GiNaC::add>(e) && !e.is_zero()) {
        ex c = 1, S = 0;
        const auto factor = [&](const ex& f) {
            if (is_ex_the_function(f, exp))
                S += f.op(0);
            else if (GiNaC::is_a<GiNaC::power>(f) && is_ex_the_function(f.op(0), exp) &&
                     f.op(1).info(GiNaC::info_flags::integer))
                S += f.op(1) * f.op(0).op(0);
            else
                c *= f;
        };
        if (GiNaC::is_a<GiNaC::mul>(e))
            for (const ex& f : e) factor(f);
        else
            factor(e);
        S = S.expand();
        const ex re_s = tidy(GiNaC::real_part(S)), im_s = tidy(GiNaC::imag_part(S));
        const ex scale = re_s.is_zero() ? ex(1) : GiNaC::exp(re_s);
        if (GiNaC::is_a<GiNaC::numeric>(c)) {
            const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(c);
            if (n.is_real()) return {tidy(GiNaC::abs(n) * scale), tidy(n < 0 ? im_s + GiNaC::Pi : im_s)};
            return {tidy(GiNaC::sqrt(ex(n.real() * n.real() + n.imag() * n.imag())) * scale),
                    tidy(GiNaC::atan2(n.imag(), n.real()) + im_s)};
        }
        if (c.info(GiNaC::info_flags::positive)) return {tidy(c * scale), im_s};
    }
    const ex x = tidy(z.expand());
    const ex re = tidy(GiNaC::real_part(x)), im = tidy(GiNaC::imag_part(x));
    return {GiNaC::sqrt(tidy((re * re + im * im).expand())), GiNaC::atan2(im, re)};
}

}  // namespace

std::optional<carriers> carriers_of(const multicomplex& A, const coeffs& d) {
    A.check_size(d, "carriers");
    carriers c;
    c.sigma = d[0];
    std::vector<bool> used(A.dim(), false);
    used[0] = true;
    for (unsigned k = 0; k <= A.order(); ++k) {
        const coeffs ik = A.imag_unit(k);
        const std::size_t i = index_of_unit(ik);
        used[i] = true;
        c.omega.push_back(d[i] * ik[i]);  // ik[i] = 1
    }
    for (std::size_t i = 0; i < A.dim(); ++i)
        if (!used[i] && !is_zero_scalar(d[i])) return std::nullopt;
    return c;
}

// (IV.1.15) the product of the carriers' exponentials, multiplied out by the algebra
coeffs exp_product_form(const multicomplex& A, const carriers& c, const ex& t) {
    coeffs e = A.unit();
    e[0] = c.sigma.is_zero() ? ex(1) : GiNaC::exp(c.sigma * t);
    for (unsigned k = 0; k <= A.order(); ++k) e = A.multiply(e, carrier_factor(A, k, c.omega[k], t));
    return e;
}

// (IV.1.26-30) phi = scal(w exp(d t)) = cos(omega_0 t) scal(w E) + sin(omega_0 t) scal(w i0 E)
modulation modulation_of(const representation& R, const carriers& c, const coeffs& w, const ex& t) {
    const auto* M = dynamic_cast<const multicomplex*>(R.A.get());
    if (!M) throw type_error("modulation: " + R.A->name() + " is not a multicomplex algebra");
    const multicomplex& A = *M;
    coeffs E = A.unit();
    E[0] = c.sigma.is_zero() ? ex(1) : GiNaC::exp(c.sigma * t);
    for (unsigned k = 1; k <= A.order(); ++k) E = A.multiply(E, carrier_factor(A, k, c.omega[k], t));
    return carrier_modulation(R, A.imag_unit(0), E, w);
}

// (IV.1.50-57, 64-68) w = A exp(-(phi_0 i_0 + ... + phi_n i_n)), decided without branches
amplitude_modulation amplitude_modulated(const multicomplex& A, const coeffs& w) {
    A.check_size(w, "amplitude_modulated");
    const unsigned n = A.order();
    const std::size_t P = A.half_dim();
    const std::vector<ex> z = A.idempotent_components(w);
    // the sign vector of each component: i_k has component s_k(p) I (i_0: I everywhere)
    std::vector<std::vector<int>> sign(P, std::vector<int>(n + 1, 1));
    std::map<std::vector<int>, std::size_t> index;
    for (unsigned k = 1; k <= n; ++k) {
        const std::vector<ex> ck = A.idempotent_components(A.imag_unit(k));
        for (std::size_t p = 0; p < P; ++p) sign[p][k] = (ck[p] / GiNaC::I).is_equal(1) ? 1 : -1;
    }
    for (std::size_t p = 0; p < P; ++p) index[sign[p]] = p;
    amplitude_modulation r;
    const auto decide = [&](const ex& x, const std::string& what, bool show_difference = true) -> bool {
        const ex e = tidy(x.expand());
        // without I the expression itself (its real part taken by GiNaC would write cos(u) of a real
        // u as cos(real_part(u)) cosh(imag_part(u)), which the zero test cannot read): 0 proved is
        // both parts 0, seen nonzero is one part nonzero
        const std::vector<ex> parts = e.has(GiNaC::I) ? std::vector<ex>{tidy(GiNaC::real_part(e)),
                                                                          tidy(GiNaC::imag_part(e))}
                                                        : std::vector<ex>{e};
        for (const ex& part : parts) {
            const zero_decision d = decide_zero(part);
            if (d.is_zero == truth::no) {
                r.holds = truth::no;
                const std::string at = witness_text(d);
                r.report = what;
                if (show_difference)
                    r.report += " (" + message_text(part, text_limit::report) + " is not 0" +
                                (at.empty() ? "" : " " + at) + ")";
                return false;
            }
            if (d.is_zero == truth::unknown) {
                r.holds = truth::unknown;
                r.report = "cannot decide whether w is amplitude-modulated: " + message_text(part, text_limit::report) +
                           " is neither proved 0 nor seen nonzero (the test: " + what + ")";
                return false;
            }
        }
        return true;
    };
    // moduli: all equal to the first, and not 0
    std::vector<polar> pz;
    for (const ex& zp : z) pz.push_back(polar_of(zp));
    const ex m0 = pz[0].r;
    {
        const zero_decision d = decide_zero(m0);
        if (d.is_zero == truth::yes) {
            r.holds = truth::no;
            r.report = "not amplitude-modulated: w is a zero divisor (its idempotent component 0 is 0), "
                       "so it represents a degenerate signal (IV.1.43-48)";
            return r;
        }
    }
    for (std::size_t p = 1; p < P; ++p)
        if (!decide(pz[p].r - m0,
                    "not amplitude-modulated: the idempotent components 0 and " + std::to_string(p) +
                        " have different moduli, " + message_text(m0, text_limit::report) + " and " +
                        message_text(pz[p].r, text_limit::report) + " (IV.1.66)",
                    false))
            return r;
    // the phases affine in the signs: z_(++) z_(--) = z_(+-) z_(-+) on every face k < l
    for (unsigned k = 1; k <= n; ++k)
        for (unsigned l = k + 1; l <= n; ++l)
            for (std::size_t p = 0; p < P; ++p) {
                if (sign[p][k] != 1 || sign[p][l] != 1) continue;
                std::vector<int> s = sign[p];
                const std::size_t pp = p;
                s[k] = -1;
                s[l] = -1;
                const std::size_t mm = index.at(s);
                s[l] = 1;
                const std::size_t mp = index.at(s);
                s[k] = 1;
                s[l] = -1;
                const std::size_t pm = index.at(s);
                if (!decide(z[pp] * z[mm] - z[mp] * z[pm],
                            "not amplitude-modulated: the phases of the idempotent components are not of the form "
                            "phi_0 + sum_k (+-phi_k): z_" + std::to_string(pp) + " z_" + std::to_string(mm) +
                                " != z_" + std::to_string(mp) + " z_" + std::to_string(pm) + " (IV.1.68)"))
                    return r;
            }
    // the form: z_p = A e^(-I Phi_p): phi_k = (Phi_+ - Phi_k-)/2 = (theta_k- - theta_+)/2,
    // phi_0 = Phi_+ - sum phi_k = -theta_+ - sum phi_k
    r.holds = truth::yes;
    r.amplitude = m0;
    const std::size_t all_plus = index.at(std::vector<int>(n + 1, 1));
    r.phases.assign(n + 1, ex(0));
    ex rest = 0;
    for (unsigned k = 1; k <= n; ++k) {
        std::vector<int> s(n + 1, 1);
        s[k] = -1;
        r.phases[k] = tidy((pz[index.at(s)].theta - pz[all_plus].theta) / 2);
        rest += r.phases[k];
    }
    r.phases[0] = tidy(-pz[all_plus].theta - rest);
    // the form checked: A exp(-(phi_0 i0 + ... + phi_n in)) == w
    coeffs theta(A.dim(), ex(0));
    for (unsigned k = 0; k <= n; ++k) {
        const coeffs ik = A.imag_unit(k);
        theta[index_of_unit(ik)] -= r.phases[k];
    }
    coeffs back = A.exp(theta, ex(1));
    for (std::size_t i = 0; i < back.size(); ++i)
        if (!decide(back[i] * r.amplitude - w[i],
                    "not amplitude-modulated: the form found does not give w back at coordinate " +
                        std::to_string(i)))
            throw algebra_error("amplitude_modulated: internal check failed (" + r.report + ")");
    r.report = "amplitude-modulated: w = A exp(-(phi_0 i0 + ... + phi_n in)) represents "
               "A prod_k cos(omega_k t - phi_k) for every d = sum_k omega_k i_k (IV.1.57)";
    return r;
}

}  // namespace symrep::signals
