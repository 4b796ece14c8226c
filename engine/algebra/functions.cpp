// symrep/algebra/functions.cpp -- functions of an element: exp(w t) and log(w)
// through the minimal polynomial (placeholder bodies; see issue 2, part 3).
#include "algebra/algebra.h"
#include "io/error.h"

namespace symrep {

coeffs algebra::apply_function(const coeffs&, const scalar_function& f) const {
    throw closed_form_error(f.name + " of an element of " + name() + " is not available yet");
}
coeffs algebra::exp(const coeffs&, const GiNaC::ex&) const {
    throw closed_form_error("exp in " + name() + " is not available yet");
}
coeffs algebra::log(const coeffs&) const {
    throw closed_form_error("log in " + name() + " is not available yet");
}

}  // namespace symrep
