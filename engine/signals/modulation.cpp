// symrep/signals/modulation.cpp -- see modulation.h.
#include "symrep/signals/modulation.h"

#include "symrep/algebra/sobrero.h"
#include "symrep/core/error.h"
#include "symrep/scalar/scalar.h"

namespace symrep::signals {

using GiNaC::ex;

modulation carrier_modulation(const representation& R, const coeffs& J, const coeffs& E, const coeffs& w) {
    R.A->check_size(w, "modulation");
    const coeffs wE = R.A->multiply(w, E);
    modulation m;
    m.a = tidy(functional(R.lambda, wE));
    m.b = tidy(functional(R.lambda, R.A->multiply(J, wE)));
    m.amplitude = GiNaC::sqrt(tidy((m.a * m.a + m.b * m.b).expand()));
    m.phase = GiNaC::atan2(m.b, m.a);
    return m;
}

modulation sobrero_modulation(const representation& R, const coeffs& w, const ex& t) {
    const auto* S = dynamic_cast<const sobrero*>(R.A.get());
    if (!S) throw type_error("modulation: " + R.A->name() + " is not a Sobrero algebra");
    const std::size_t j = S->n() + 1;  // the coordinate of j (sobrero.h)
    const ex omega = R.d[j];
    coeffs J(S->dim(), ex(0));
    J[j] = 1;
    coeffs rest = R.d;
    rest[j] = 0;
    return carrier_modulation(R, J, S->exp(rest, t), w);
}

}  // namespace symrep::signals
