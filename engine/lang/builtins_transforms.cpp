// symrep/lang/builtins_transforms.cpp -- the integral transforms of Ch. V
// (transforms/laplace.h): laplace, inverse_laplace, transform.
#include <numbers>
#include <string>
#include <vector>

#include "symrep/lang/builtins.h"
#include "symrep/lang/values.h"
#include "symrep/core/error.h"
#include "symrep/transforms/laplace.h"
#include "symrep/transforms/inversion.h"
#include "symrep/transforms/sampled.h"
#include "symrep/transforms/algebra_inversion.h"
#include "symrep/transforms/distribution.h"
#include "symrep/transforms/monogenic.h"
#include "symrep/transforms/parseval.h"
#include "symrep/transforms/signal_transform.h"

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
                       ? transforms::transform_signal(d.parent_ptr(), d.coefficients(), f, t, &arg_ex(a, 3, b))
                       : transforms::transform_signal(d.parent_ptr(), d.coefficients(), f, t);
    return list{value(element(d.parent_ptr(), x.value)), value(x.report)};
}

value builtin_dirac(const builtin& b, const std::vector<value>& a, context&) {
    const GiNaC::ex k = a.size() > 1 ? GiNaC::ex(arg_int(a, 1, b, 0, 1000)) : GiNaC::ex(0);
    return GiNaC::ex(transforms::dirac(arg_ex(a, 0, b), k));
}

value builtin_inner_product(const builtin& b, const std::vector<value>& a, context&) {
    return transforms::inner_product(arg_ex(a, 0, b), arg_ex(a, 1, b), arg_symbol(a, 2, b));
}

value builtin_parseval(const builtin& b, const std::vector<value>& a, context&) {
    const algebra_ptr& A = arg_algebra(a, 3, b);
    const auto r = transforms::parseval(A, arg_ex(a, 0, b), arg_ex(a, 1, b), arg_symbol(a, 2, b));
    if (r.proved != truth::yes) throw domain_error(b.name + ": " + r.report);
    list out{value(r.time_side), value(element(A, r.element))};
    if (r.has_quadrature)
        out.push_back(value(list{value(GiNaC::ex(GiNaC::numeric(r.quadrature))),
                                 value(GiNaC::ex(GiNaC::numeric(r.quadrature_error)))}));
    out.push_back(value(r.report));
    return out;
}

value builtin_hypercomplex_conjugate(const builtin& b, const std::vector<value>& a, context&) {
    const element& x = arg_element(a, 0, b);
    return element(x.parent_ptr(), transforms::hypercomplex_conjugate(x.parent_ptr(), x.coefficients()));
}

value builtin_inverse_transform(const builtin& b, const std::vector<value>& a, context&) {
    const element& T = arg_element(a, 0, b);
    const element& d = arg_element(a, 1, b);
    if (T.parent().name() != d.parent().name()) throw type_error(b.name + ": T and d belong to different algebras");
    const auto r = transforms::inverse_transform(T.parent_ptr(), T.coefficients(), d.coefficients(), arg_symbol(a, 2, b));
    return list{value(r.f), value(r.g), value(r.report)};
}

value builtin_monogenic(const builtin& b, const std::vector<value>& a, context&) {
    const element& F = arg_element(a, 0, b);
    const element& d = arg_element(a, 1, b);
    if (F.parent().name() != d.parent().name()) throw type_error(b.name + ": F and d belong to different algebras");
    const auto r = transforms::monogenic(F.parent_ptr(), F.coefficients(), d.coefficients());
    if (r.holds == truth::unknown) throw domain_error(b.name + ": not decided: " + r.report);
    return list{value(r.holds == truth::yes), value(r.report)};
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
         "line): T f(d) + T[g(-u)](-d); e^(-|t|) is f = exp(-t), g = exp(t). Signals that are not quasi-polynomials: "
         "impulses dirac(t - a, k) give d^k e^(-a d); pieces cut by step(alpha*t + beta) are exact (the shift of the "
         "representation); a Gaussian on the whole line (g = f) is exact; anything else is integrated by quadrature "
         "for numeric d, the report giving the error estimate. A divergent integral of such a signal is refused by "
         "name; an undecided convergence says \"cannot decide\".",
         "(V.1.5, V.2.11, V.2.27-29, V.3)", "transform(exp(-t), t, 2*imag_unit(multicomplex(1), 0) + "
         "imag_unit(multicomplex(1), 1))", 3, 4, builtin_transform},
        {"dirac", "dirac(x [, k])",
         "The Dirac impulse delta^(k)(x) (k = 0 by default) as a signal term: c(t)*dirac(alpha*t + beta, k) with alpha "
         "a nonzero number. diff(dirac(x, k), x) = dirac(x, k + 1); dirac(x) = 0 at a number x != 0. Its transform over "
         "any algebra is T delta^(k)(t - a) = d^k e^(-a d): T delta = 1 and T delta^(k) = d^k, the powers of the "
         "representation operator (V.2.32-35, V.3.33-36).",
         "(V.2.32-35, V.3.33-36)", "transform(dirac(t, 2), t, 2 + basis(sobrero(1), 1))", 1, 2, builtin_dirac},
        {"inner_product", "inner_product(f, g, t)",
         "The inner product int_0^oo f(t) g(t) dt of two causal quasi-polynomials, exact: L[f g](0). An error names a "
         "divergent integral (f g has an exponent with real part >= 0) or says that convergence cannot be decided.",
         "(V.2.43-46)", "inner_product(exp(-t), exp(-2*t)*cos(t), t)", 3, 3, builtin_inner_product},
        {"parseval", "parseval(f, g, t, M)",
         "The hypercomplex Parseval relation over M = multicomplex(n) for causal quasi-polynomials f, g in L2 (V.2.44-49): "
         "[int_0^oo f g dt, (1/2 pi i0) int_A T f (T g)^* dd, [the frequency integral by quadrature, its error "
         "estimate] (numeric data only), report]. Proved: the frequency side (1/2 pi) int F(i w) conj G(i w) dw by "
         "residues equals the time side; (T g)^* = T g(-d); the components of T f (T g)^* are F(i Omega_p) "
         "conj G(i Omega_p), so the algebra integral is the inner product times the unit. The conjugate of V.2.41 is "
         "read in the idempotent basis B* (hypercomplex_conjugate). parseval(f, f, t, M) is the energy (V.2.49).",
         "Thm V.2.4, (V.2.44-49)", "parseval(exp(-t), exp(-2*t), t, multicomplex(1))", 4, 4, builtin_parseval},
        {"hypercomplex_conjugate", "hypercomplex_conjugate(x)",
         "The conjugate of V.2.40-41 of a multicomplex element: the complex conjugate of every idempotent component "
         "(V.2.41 read in the basis B* = {e_p, i0 e_p}); in the basis of products of i0..in every generator changes "
         "sign, i_k -> -i_k. For a real signal (T f)^* = T f(-d).",
         "(V.2.40-41)", "hypercomplex_conjugate(1 + 2*imag_unit(multicomplex(1), 0) + 3*imag_unit(multicomplex(1), 0)*"
         "imag_unit(multicomplex(1), 1))", 1, 1, builtin_hypercomplex_conjugate},
        {"inverse_transform", "inverse_transform(T, d, t)",
         "The inversion of an algebra-valued transform T(d) (Thm V.2.3, Thm V.3.3), d the algebra variable with symbols. "
         "Over multicomplex(n) (d = w0*i0 + ... + wn*in): every idempotent component is a function F(i Omega_p) (checked), "
         "inverted along the imaginary axis (poles left: the signal for t >= 0; right: for t < 0; a polynomial part: "
         "impulses dirac(t, k)); all components give the same signal (V.2.39). Over sobrero(n) (d = x + eps): the eps^0 "
         "coefficient is inverted and L^-1 of the eps^k coefficient checked to be (-t)^k f/k! (V.3.40-41). Returns "
         "[f for t >= 0, g for t < 0, report].",
         "Thm V.2.3, Thm V.3.3", "inverse_transform(transform(exp(-t), t, w*imag_unit(multicomplex(0), 0))[0], "
         "w*imag_unit(multicomplex(0), 0), t)", 3, 3, builtin_inverse_transform},
        {"monogenic", "monogenic(F, d)",
         "Whether F, an element whose coordinates are functions of the symbols of d (d affine in them), is monogenic in "
         "d: the generalized Cauchy-Riemann conditions b_r dF/dx = b_x dF/dr (b_x = dd/dx, r the first symbol with b_r "
         "invertible), e.g. i0 dF/domega_k = i_k dF/domega_0 over multicomplex(n) (V.2.21), j dF/dx = dF/dw over "
         "sobrero(n) (V.3.19). Each coordinate is proved 0 or shown nonzero at a point: [true/false, report]; an "
         "error when a condition is not decided.",
         "Thm V.2.1 (V.2.18-21), Thm V.3.1 (V.3.19)", "monogenic(transform(exp(-t), t, u*imag_unit(multicomplex(1), 0) + "
         "v*imag_unit(multicomplex(1), 1))[0], u*imag_unit(multicomplex(1), 0) + v*imag_unit(multicomplex(1), 1))",
         2, 2, builtin_monogenic},
    });
}

}  // namespace symrep::lang
