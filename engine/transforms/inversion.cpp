// symrep/transforms/inversion.cpp -- the inversion integral (V.2.36-39) by Ooura-Mori quadrature.
#include "symrep/transforms/inversion.h"

#include <cmath>
#include <complex>
#include <numbers>
#include <string>
#include <vector>

#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/quadrature/ooura_fourier_integrals.hpp>

#include "symrep/core/error.h"
#include "symrep/scalar/scalar.h"

namespace symrep::transforms {

namespace {

// The real coefficients c_0 .. c_n of a polynomial in s with numeric coefficients (exact where
// they are rational).
std::vector<GiNaC::numeric> coefficients(const GiNaC::ex& p, const GiNaC::symbol& s, const char* what) {
    const GiNaC::ex e = GiNaC::expand(p);
    if (!e.is_polynomial(s))
        throw domain_error(std::string("fourier_inversion: the ") + what + " is not a polynomial in " + s.get_name());
    std::vector<GiNaC::numeric> c;
    for (int k = 0; k <= e.degree(s); ++k) {
        const GiNaC::ex ck = e.coeff(s, k);
        const GiNaC::ex v = GiNaC::is_a<GiNaC::numeric>(ck) ? ck : GiNaC::evalf(ck);
        if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real())
            throw domain_error(std::string("fourier_inversion: the transform has a coefficient that is not a real "
                                           "number (") + message_text(e.coeff(s, k), text_limit::fragment) +
                               "): give every parameter a value");
        c.push_back(GiNaC::ex_to<GiNaC::numeric>(v));
    }
    return c;
}

std::vector<double> doubles(const std::vector<GiNaC::numeric>& c) {
    std::vector<double> out;
    for (const auto& x : c) out.push_back(x.to_double());
    return out;
}

std::complex<double> horner(const std::vector<double>& c, std::complex<double> z) {
    std::complex<double> v = 0;
    for (std::size_t k = c.size(); k-- > 0;) v = v * z + c[k];
    return v;
}

// Every root of sum_k D_k s^k in Re s < 0: the Routh-Hurwitz table, in exact arithmetic for
// rational coefficients (a root on the axis gives a zero in the first column: not stable).
bool hurwitz_stable(const std::vector<GiNaC::numeric>& D) {
    const long n = long(D.size()) - 1;
    if (D[std::size_t(n)].is_zero()) return false;
    std::vector<std::vector<GiNaC::numeric>> rows(std::size_t(n + 1));
    for (long k = n; k >= 0; k -= 2) rows[0].push_back(D[std::size_t(k)]);
    for (long k = n - 1; k >= 0; k -= 2) rows[1].push_back(D[std::size_t(k)]);
    const bool positive = D[std::size_t(n)].is_positive();
    for (std::size_t r = 0; r < rows.size(); ++r) {
        if (r >= 2) {
            const auto& a = rows[r - 2];
            const auto& b = rows[r - 1];
            for (std::size_t j = 0; j + 1 < a.size(); ++j) {
                const GiNaC::numeric next = j + 1 < b.size() ? b[j + 1] : GiNaC::numeric(0);
                rows[r].push_back((b[0] * a[j + 1] - a[0] * next) / b[0]);
            }
        }
        if (rows[r].empty() || rows[r][0].is_zero() || rows[r][0].is_positive() != positive) return false;
    }
    return true;
}

// F as numeric polynomials N/D, proper and stable (the checks of fourier_inversion).
std::pair<std::vector<double>, std::vector<double>> stable_proper(const GiNaC::ex& F, const GiNaC::symbol& s) {
    const GiNaC::ex nd = GiNaC::normal(F).numer_denom();
    const std::vector<GiNaC::numeric> Nx = coefficients(nd.op(0), s, "numerator"),
                                      Dx = coefficients(nd.op(1), s, "denominator");
    if (Nx.size() >= Dx.size())
        throw domain_error("fourier_inversion: the transform is not proper (degree of the numerator >= degree of the "
                           "denominator): the signal has a Dirac part at 0 (V.2.33-35)");
    if (!hurwitz_stable(Dx))
        throw domain_error("fourier_inversion: the transform has a pole with real part >= 0 (Routh-Hurwitz): the "
                           "signal does not decay, its Fourier transform is not F(i w) and (V.2.36) does not apply");
    return {doubles(Nx), doubles(Dx)};
}

}  // namespace

inversion_value fourier_inversion(const GiNaC::ex& F, const GiNaC::symbol& s, double t0) {
    const auto ND = stable_proper(F, s);
    const std::vector<double>&N = ND.first, &D = ND.second;
    const auto Fiw = [&](double w) { return horner(N, {0, w}) / horner(D, {0, w}); };
    inversion_value out;
    if (t0 == 0) {  // f~(0) = (1/pi) int_0^oo Re F(i w) dw (Ooura's sine/cosine need a frequency > 0)
        boost::math::quadrature::exp_sinh<double> half_line;
        double err = 0;
        const double I = half_line.integrate([&](double w) { return Fiw(w).real(); }, 1e-10, &err);
        out.value = I / std::numbers::pi;
        out.error_estimate = err / std::numbers::pi;
        return out;
    }
    const double t = std::abs(t0);
    boost::math::quadrature::ooura_fourier_cos<double> cosine;
    boost::math::quadrature::ooura_fourier_sin<double> sine;
    const auto c = cosine.integrate([&](double w) { return Fiw(w).real(); }, t);
    const auto sn = sine.integrate([&](double w) { return Fiw(w).imag(); }, t);
    // sin(w t0) = sign(t0) sin(w |t0|)
    out.value = (c.first - (t0 > 0 ? 1 : -1) * sn.first) / std::numbers::pi;
    out.error_estimate = (c.second + sn.second) / std::numbers::pi;
    return out;
}

inversion_value parseval_integral(const GiNaC::ex& F, const GiNaC::ex& G, const GiNaC::symbol& s) {
    const auto PF = stable_proper(F, s), PG = stable_proper(G, s);
    const std::vector<double>&NF = PF.first, &DF = PF.second, &NG = PG.first, &DG = PG.second;
    const auto at = [&](double w) {
        const std::complex<double> z(0, w);
        return (horner(NF, z) / horner(DF, z) * std::conj(horner(NG, z) / horner(DG, z))).real();
    };
    boost::math::quadrature::exp_sinh<double> half_line;
    double err = 0;
    const double I = half_line.integrate(at, 1e-12, &err);
    inversion_value out;
    out.value = I / std::numbers::pi;
    out.error_estimate = err / std::numbers::pi;
    return out;
}

}  // namespace symrep::transforms
