// symrep/signals/z_transform.cpp -- see z_transform.h.
#include "symrep/signals/z_transform.h"

#include "symrep/scalar/scalar.h"
#include "symrep/signals/representation.h"

namespace symrep::signals {

GiNaC::ex z_transform(const GiNaC::ex& f, const GiNaC::symbol& k, const GiNaC::ex& z) {
    const GiNaC::symbol X("X");
    const representation R = polynomial_representation(sequence_annihilator(f, k, X), X);
    const coeffs w = sequence_element(R, f, k);
    const GiNaC::ex p = GiNaC::expand(R.p.subs(R.X == X));
    // (p(z) - p(X))/(z - X) = sum_i c_i (z^(i-1) + z^(i-2) X + ... + X^(i-1)), coefficients of any kind
    GiNaC::ex Q = 0;
    for (int i = 1; i <= p.degree(X); ++i)
        for (int j = 0; j < i; ++j) Q += p.coeff(X, i) * GiNaC::pow(z, i - 1 - j) * GiNaC::pow(X, j);
    const coeffs qd = R.A->evaluate_polynomial(Q.subs(X == R.X), R.X, R.d);
    return GiNaC::normal(tidy(z * functional(R.lambda, R.A->multiply(w, qd))) / p.subs(X == z));
}

}  // namespace symrep::signals
