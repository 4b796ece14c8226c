// symrep/lang/builtins_transforms.cpp -- the integral transforms of Ch. V
// (transforms/laplace.h): laplace, inverse_laplace, transform.
#include <numbers>
#include <string>
#include <vector>

#include "lang/builtins.h"
#include "lang/values.h"
#include "core/error.h"
#include "transforms/laplace.h"
#include "transforms/inversion.h"
#include "transforms/sampled.h"

namespace symrep::lang {

namespace {

const char* const section = "Transforms (V)";

value builtin_laplace(const builtin& b, const std::vector<value>& a, context&) {
    return transforms::laplace(arg_ex(a, 0, b), arg_symbol(a, 1, b), arg_ex(a, 2, b));
}

value builtin_inverse_laplace(const builtin& b, const std::vector<value>& a, context&) {
    return transforms::inverse_laplace(arg_ex(a, 0, b), arg_symbol(a, 1, b), arg_symbol(a, 2, b));
}

value builtin_sampled_fourier(const builtin& b, const std::vector<value>& a, context&) {
    const std::vector<GiNaC::ex> xs = arg_ex_list(a, 0, b);
    const double h = to_double(arg_ex(a, 1, b), b, "the step h");
    std::vector<double> samples;
    for (std::size_t k = 0; k < xs.size(); ++k)
        samples.push_back(to_double(xs[k], b, "sample " + std::to_string(k + 1)));
    const auto F = transforms::sampled_fourier(samples, h);
    list out;
    for (std::size_t m = 0; m <= samples.size() / 2; ++m) {
        const double omega = 2 * std::numbers::pi * double(m) / (double(samples.size()) * h);
        out.push_back(value(list{value(GiNaC::ex(GiNaC::numeric(omega))),
                                 value(GiNaC::ex(GiNaC::numeric(F[m].real()) +
                                                 GiNaC::I * GiNaC::numeric(F[m].imag())))}));
    }
    return out;
}

value builtin_fourier_inversion(const builtin& b, const std::vector<value>& a, context&) {
    const auto inv = transforms::fourier_inversion(arg_ex(a, 0, b), arg_symbol(a, 1, b),
                                                   to_double(arg_ex(a, 2, b), b, "the time t0"));
    return list{value(GiNaC::ex(GiNaC::numeric(inv.value))), value(GiNaC::ex(GiNaC::numeric(inv.error_estimate)))};
}

value builtin_energy(const builtin& b, const std::vector<value>& a, context&) {
    return transforms::energy(arg_ex(a, 0, b), arg_symbol(a, 1, b));
}

value builtin_transform(const builtin& b, const std::vector<value>& a, context&) {
    const GiNaC::ex& f = arg_ex(a, 0, b);
    const GiNaC::symbol& t = arg_symbol(a, 1, b);
    const element& d = arg_element(a, 2, b);
    const auto x = a.size() > 3
                       ? transforms::transform_two_sided(d.parent_ptr(), d.coefficients(), f, arg_ex(a, 3, b), t)
                       : transforms::transform(d.parent_ptr(), d.coefficients(), f, t);
    return list{value(element(d.parent_ptr(), x.value)), value(x.report)};
}

}  // namespace

void register_transforms_builtins(registry& r) {
    add_builtins(r, section, {
        {"laplace", "laplace(f, t, s)",
         "Lf(s) = int_0^oo f(t) e^(-s t) dt of a quasi-polynomial f (taken as 0 for t < 0), derived without an "
         "integral: f = Psi^-1(w) on the polynomial algebra of its least equation p, and Lf = q(s)/p(s) with q the "
         "polynomial of w's coordinates (the impulse response has transform 1/p). Checked by the inverse transform.",
         "(V.1.3), Thm II.1.1", "laplace(t*exp(-2*t), t, s)", 3, 3, builtin_laplace},
        {"inverse_laplace", "inverse_laplace(F, s, t)",
         "The causal signal f(t) whose Laplace transform is the proper rational function F(s): f = Psi^-1(q(v)) on "
         "the polynomial algebra of F's denominator p (F = q/p, p monic). Checked by laplace(f, t, s) = F. The roots of "
         "p come from its rational factors of degree 1, 2 and 3 (Cardano; then the check is numeric, at 50 digits); a "
         "factor of degree 4 or more is refused, naming its degree. An improper F (a polynomial part: derivatives of "
         "the Dirac delta) or a non-rational F is refused.",
         "(V.1.4), Thm II.1.1", "inverse_laplace(1/(s^2 + 2*s + 5), s, t)", 3, 3, builtin_inverse_laplace},
        {"sampled_fourier", "sampled_fourier(samples, h)",
         "The Fourier transform of a causal signal from its samples f(k h), k = 0 .. N-1, by one FFT (Eigen): the "
         "list of [omega_m, F(i omega_m)] for omega_m = 2 pi m / (N h), m = 0 .. floor(N/2) (the trapezoid rule "
         "h (sum_k f_k e^(-i omega_m k h) - f_0/2); error O(h^2) plus the signal beyond N h). Compare with "
         "laplace(f, t, I*omega) for a signal in closed form.",
         "(V.1.1, V.2.26)", "sampled_fourier([1, 0.5, 0.25, 0.125], 1)", 2, 2, builtin_sampled_fourier},
        {"fourier_inversion", "fourier_inversion(F, s, t0)",
         "The inversion integral (1/2 pi) int F(i w) e^(i w t0) dw of a transform F(s) = L f(s) (a proper rational "
         "function with numeric coefficients and its poles left of the imaginary axis), evaluated as an integral "
         "(Boost.Math: Ooura-Mori for t0 != 0, exp-sinh at t0 = 0): f~(t0) = (f(t0+) + f(t0-))/2, so 1/2 of the "
         "jump at t0 = 0 and 0 for t0 < 0 for a causal f. Over the multicomplex algebra (V.2.36-39) it is this "
         "integral on every idempotent component. Returns [f~(t0), the quadrature's error estimate].",
         "(V.2.36-39), Thm V.2.3", "fourier_inversion(1/(s + 1), s, 1)", 3, 3, builtin_fourier_inversion},
        {"energy", "energy(f, t)",
         "The energy int_0^oo f(t)^2 dt of a causal quasi-polynomial signal, exact: L[f^2](0). By Parseval (Thm "
         "V.2.4) it equals (1/2 pi) int |F(i w)|^2 dw, and over the multicomplex algebra the norm of the transform "
         "(V.2.42, V.2.49). An error when the integral diverges.",
         "(V.2.42), Thm V.2.4", "energy(exp(-t)*cos(3*t), t)", 2, 2, builtin_energy},
        {"transform", "transform(f, t, d [, g])",
         "T f(d) = int_0^oo f(t) e^(-d t) dt for a causal quasi-polynomial f and an element d of any algebra: "
         "[q(d) p(d)^-1, report], Lf = q/p. Over multicomplex(n) with d = omega_0 i0 + ... + omega_n in it is the "
         "Fourier-type transform of V.2 (idempotent components F(i Omega_p), V.2.27); over sobrero(n) with "
         "d = s + eps it is the Laplace-type transform sum_k eps^k/k! d^k/ds^k Lf(s) of V.3. The report says whether "
         "the integral converges (Re r < Re mu for the exponents r of f and the eigenvalues mu of d), does not (the "
         "value is then the analytic continuation), or under which condition on the parameters. With g: the "
         "two-sided transform int_-oo^oo of the signal that is f for t >= 0 and g for t < 0 (V.2.11 over the whole "
         "line): T f(d) + T[g(-u)](-d); e^(-|t|) is f = exp(-t), g = exp(t).",
         "(V.1.5, V.2.11, V.2.27-29, V.3)", "transform(exp(-t), t, 2*imag_unit(multicomplex(1), 0) + "
         "imag_unit(multicomplex(1), 1))", 3, 4, builtin_transform},
    });
}

}  // namespace symrep::lang
