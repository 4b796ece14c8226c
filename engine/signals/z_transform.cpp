// symrep/signals/z_transform.cpp -- see z_transform.h.
#include "signals/z_transform.h"

#include "scalar/scalar.h"
#include "signals/representation.h"

namespace symrep::signals {

GiNaC::ex z_transform(const GiNaC::ex& f, const GiNaC::symbol& k, const GiNaC::ex& z) {
    const GiNaC::symbol X("X");
    const representation R = polynomial_representation(sequence_annihilator(f, k, X), X);
    const coeffs w = sequence_element(R, f, k);
    const GiNaC::ex p = GiNaC::expand(R.p.subs(R.X == X));
    const GiNaC::ex Q = GiNaC::quo(GiNaC::expand(p.subs(X == z) - p), z - X, X);  // (p(z) - p(X))/(z - X)
    const coeffs qd = R.A->evaluate_polynomial(Q.subs(X == R.X), R.X, R.d);
    return GiNaC::normal(tidy(z * functional(R.lambda, R.A->multiply(w, qd))) / p.subs(X == z));
}

}  // namespace symrep::signals
