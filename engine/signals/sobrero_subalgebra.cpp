// symrep/signals/sobrero_subalgebra.cpp -- see sobrero_subalgebra.h.
#include "symrep/signals/sobrero_subalgebra.h"

#include "symrep/algebra/sobrero.h"
#include "symrep/core/error.h"
#include "symrep/scalar/equality.h"
#include "symrep/scalar/scalar.h"

namespace symrep::signals {

sobrero_place sobrero_subalgebra(const algebra& A, const coeffs& w) {
    const auto* S = dynamic_cast<const sobrero*>(&A);
    if (!S) throw type_error("sobrero_subalgebra: " + A.name() + " is not a Sobrero algebra");
    S->check_size(w, "sobrero_subalgebra");
    const long n = S->n();
    // coordinates [a_0..a_n, b_0..b_n]
    std::vector<bool> zero(w.size());
    for (std::size_t i = 0; i < w.size(); ++i) {
        const zero_decision z = decide_zero(tidy(w[i]));
        if (z.is_zero == truth::unknown)
            throw domain_error("sobrero_subalgebra: cannot decide whether the coordinate " + S->basis_name(i) + " = " +
                               message_text(w[i], text_limit::report) + " is 0");
        zero[i] = z.is_zero == truth::yes;
    }
    const auto a0 = [&](long k) { return zero[std::size_t(k)]; };
    const auto b0 = [&](long k) { return zero[std::size_t(n + 1 + k)]; };
    sobrero_place out;
    for (long k = 0; k <= n; ++k)
        if (!a0(k) || !b0(k)) {
            out.first_power = k;
            break;
        }
    bool higher_zero = true, b_zero = true, lower_zero = true;
    for (long k = 0; k <= n; ++k) {
        if (k >= 1 && (!a0(k) || !b0(k))) higher_zero = false;
        if (!b0(k)) b_zero = false;
        if (k < n && (!a0(k) || !b0(k))) lower_zero = false;
    }
    if (higher_zero && b_zero) out.subalgebras.push_back("R");
    if (higher_zero) out.subalgebras.push_back("C");
    if (b_zero) out.subalgebras.push_back("P");
    if (lower_zero) out.subalgebras.push_back("eps^" + std::to_string(n) + " C");
    out.signal_order = out.first_power < 0 ? 0 : 2 * (n + 1 - out.first_power);
    std::string in;
    for (const auto& s : out.subalgebras) in += (in.empty() ? "" : ", ") + s;
    out.report = out.first_power < 0
                     ? "w = 0 represents the zero signal"
                     : "w lies in eps^" + std::to_string(out.first_power) + " S" +
                           (in.empty() ? "" : " and in " + in) +
                           "; with d = delta + eps + j omega (omega != 0) it represents a signal of order " +
                           std::to_string(out.signal_order) + " (least equation ((D - delta)^2 + omega^2)^" +
                           std::to_string(n + 1 - out.first_power) +
                           "); the second-order signals A e^(delta t) cos(omega t - phi) are exactly those in eps^" +
                           std::to_string(n) + " C (IV.1.2.31-35 corrected)";
    return out;
}

}  // namespace symrep::signals
