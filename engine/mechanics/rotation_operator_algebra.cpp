// symrep/mechanics/rotation_operator_algebra.cpp -- K = w x as P(X^3 + Omega^2 X).
#include "symrep/mechanics/rotation_operator_algebra.h"

#include "symrep/scalar/scalar.h"
#include "symrep/core/error.h"

namespace symrep::mechanics {

using GiNaC::ex;

rotation_operator_algebra::rotation_operator_algebra(const ex& Omega) : Omega_(tidy(Omega)) {
    degenerate_ = Omega_.is_zero();
    if (!degenerate_ && !Omega_.info(GiNaC::info_flags::positive)) {
        const ex v = GiNaC::evalf(Omega_);
        const bool num_pos = GiNaC::is_a<GiNaC::numeric>(v) &&
                             GiNaC::ex_to<GiNaC::numeric>(v).is_real() &&
                             GiNaC::ex_to<GiNaC::numeric>(v).is_positive();
        if (!num_pos)
            throw domain_error("rotation operator algebra: Omega = |w| = " + message_text(Omega_) +
                               " is not known to be positive (use a possymbol for |w|) nor exactly 0");
    }
    P_ = polynomial_algebra::make(GiNaC::pow(X_, 3) + Omega_ * Omega_ * X_, X_);
}

element rotation_operator_algebra::one() const { return element::one(P_); }
element rotation_operator_algebra::K() const { return element::basis(P_, 1); }

element rotation_operator_algebra::make(const ex& c0, const ex& c1, const ex& c2) const {
    return element(P_, {c0, c1, c2});
}

element rotation_operator_algebra::polynomial(const std::vector<ex>& a) const {
    ex p = 0;
    for (std::size_t j = 0; j < a.size(); ++j) p += a[j] * GiNaC::pow(X_, int(j));
    return K().evaluate(p, X_);
}

void rotation_operator_algebra::require_split(const char* what) const {
    if (degenerate_)
        throw domain_error(std::string(what) +
                           ": Omega = |w| is 0, so K = w x is nilpotent (K^3 = 0) and the "
                           "algebra has no idempotent splitting R + C");
}

element rotation_operator_algebra::P0() const {
    require_split("P0");
    return make(1, 0, 1 / (Omega_ * Omega_));
}
element rotation_operator_algebra::P1() const {
    require_split("P1");
    return make(0, 0, -1 / (Omega_ * Omega_));
}
element rotation_operator_algebra::J() const {
    require_split("J");
    return make(0, 1 / Omega_, 0);
}

element rotation_operator_algebra::exp_minus_Kt(const ex& t) const { return (-K()).exp(t); }

rotation_operator_algebra::components rotation_operator_algebra::decompose(const coeffs& a) const {
    require_split("decompose");
    P_->check_size(a, "decompose");
    const ex W2 = Omega_ * Omega_;
    return {tidy(a[0]), cex(tidy(a[0] - W2 * a[2]), tidy(Omega_ * a[1]))};
}

coeffs rotation_operator_algebra::recombine(const ex& axial, const cex& planar) const {
    require_split("recombine");
    return {tidy(axial), tidy(planar.im / Omega_), tidy((axial - planar.re) / (Omega_ * Omega_))};
}

std::array<quasi_polynomial, 3> rotation_operator_algebra::recombine(const quasi_polynomial& axial,
                                                                      const quasi_polynomial& planar) const {
    require_split("recombine");
    return {axial, (1 / Omega_) * planar.imag(), (1 / (Omega_ * Omega_)) * (axial - planar.real())};
}

// II.1.23-24: G(K) P only needs G modulo the local minimal polynomial m of P.
std::array<quasi_polynomial, 3> rotation_operator_algebra::recombine(const quasi_polynomial& axial,
                                                                      const quasi_polynomial& planar,
                                                                      cyclic_factors m) const {
    const quasi_polynomial zero = quasi_polynomial::constant(0, axial.is_zero() ? planar.variable() : axial.variable());
    if (m.axial && !m.planar) return {axial, zero, zero};
    if (!m.axial && !m.planar) return {zero, zero, zero};
    require_split("recombine modulo X^2 + Omega^2");
    if (!m.axial) return {planar.real(), (1 / Omega_) * planar.imag(), zero};
    return recombine(axial, planar);
}

ex rotation_operator_algebra::minimal_polynomial(cyclic_factors m) const {
    if (degenerate_ && !(m.axial && !m.planar) && (m.axial || m.planar)) m = {true, true};
    return (m.axial ? ex(X_) : ex(1)) * (m.planar ? GiNaC::pow(X_, 2) + Omega_ * Omega_ : ex(1));
}

std::array<quasi_polynomial, 3> rotation_operator_algebra::projector_form(
    const std::array<quasi_polynomial, 3>& c) const {
    require_split("projector_form");
    return {c[0], c[1], c[0] - (Omega_ * Omega_) * c[2]};
}

cex rotation_operator_algebra::at_i_omega(const std::vector<ex>& a) const {
    cex r(ex(0), ex(0)), p(ex(1), ex(0));
    const cex iw(ex(0), Omega_);
    for (const ex& c : a) {
        r += c * p;
        p = tidy_cex(p * iw);
    }
    return tidy_cex(r);
}

}  // namespace symrep::mechanics
