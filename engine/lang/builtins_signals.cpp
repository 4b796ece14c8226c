// symrep/lang/builtins_signals.cpp -- signals represented by algebra elements
// (thesis II.1-II.3): Psi and Psi^-1, the least equation of a quasi-polynomial,
// discrete signals and sampling (signals/representation.h).
#include <string>
#include <vector>

#include "symrep/algebra/polynomial_algebra.h"
#include "symrep/algebra/sobrero.h"
#include "symrep/lang/builtins.h"
#include "symrep/algebra/multicomplex.h"
#include "symrep/signals/modulation.h"
#include "symrep/signals/product.h"
#include "symrep/signals/multicomplex_signals.h"
#include "symrep/signals/representation.h"
#include "symrep/signals/response.h"
#include "symrep/signals/z_transform.h"

namespace symrep::lang {

namespace {

const multicomplex& multicomplex_of(const element& w, const builtin& b) {
    const auto* M = dynamic_cast<const multicomplex*>(&w.parent());
    if (!M)
        throw type_error(b.name + ": " + w.parent().name() + " is not a multicomplex" +
                         (b.name == "modulation" ? " or Sobrero" : "") + " algebra (usage: " + b.signature + ")");
    return *M;
}

const char* const section = "Signals (II.2-II.3)";

// The representation of w's algebra: with the operator d given (argument i), or the
// generator v of a polynomial algebra.
signals::representation representation_of(const std::vector<value>& a, std::size_t i, const algebra_ptr& A,
                                          const builtin& b) {
    if (a.size() > i) {
        const element& d = arg_element(a, i, b);
        if (d.parent_ptr() != A && d.parent().name() != A->name())
            throw type_error(b.name + ": the operator d is in " + d.parent().name() + ", the element in " +
                             A->name());
        return signals::represent_on(d.parent_ptr(), d.coefficients());
    }
    const auto P = std::dynamic_pointer_cast<const polynomial_algebra>(A);
    if (!P)
        throw type_error(b.name + ": " + A->name() +
                         " is not a polynomial algebra; give the operator d (usage: " + b.signature + ")");
    return signals::polynomial_representation(P->polynomial(), GiNaC::ex_to<GiNaC::symbol>(P->variable()));
}

// represent / represent_sequence: on d's algebra (argument 3), or on the least P_n of f.
value represent_signal(const std::vector<value>& a, context& ctx, const builtin& b, bool discrete) {
    const GiNaC::ex& f = arg_ex(a, 0, b);
    const GiNaC::symbol& t = arg_symbol(a, 1, b);
    const auto element_in = [&](const signals::representation& R) {
        return element(R.A, discrete ? signals::sequence_element(R, f, t) : signals::element_of(R, f, t));
    };
    if (a.size() == 3) {
        const element& d = arg_element(a, 2, b);
        return element_in(signals::represent_on(d.parent_ptr(), d.coefficients()));
    }
    const GiNaC::ex Xe = ctx.symbol("X");  // kept: X refers into it
    const GiNaC::symbol& X = GiNaC::ex_to<GiNaC::symbol>(Xe);
    const GiNaC::ex p = discrete ? signals::sequence_annihilator(f, t, X) : signals::annihilator(f, t, X);
    return element_in(signals::polynomial_representation(p, X));
}

// [particular, zero_state, report] of response and sequence_response.
value response_list(const signals::system_response& x) {
    return list{value(x.particular),
                x.has_zero_state ? value(x.zero_state) : value(std::string("not derived")),
                value(x.report)};
}

value builtin_represent(const builtin& b, const std::vector<value>& a, context& ctx) {
    return represent_signal(a, ctx, b, false);
}

value builtin_represent_product(const builtin& b, const std::vector<value>& a, context&) {
    const GiNaC::ex& f = arg_ex(a, 0, b);
    const GiNaC::ex& g = arg_ex(a, 1, b);
    const GiNaC::symbol& t = arg_symbol(a, 2, b);
    const GiNaC::symbol X("X");
    const auto RA = signals::polynomial_representation(signals::annihilator(f, t, X), X);
    const auto RB = signals::polynomial_representation(signals::annihilator(g, t, X), X);
    const auto R = signals::product_representation(RA, RB);
    const coeffs w = signals::tensor(signals::element_of(RA, f, t), signals::element_of(RB, g, t));
    return list{value(element(R.A, w)), value(element(R.A, R.d))};
}

value builtin_signal(const builtin& b, const std::vector<value>& a, context&) {
    const element& w = arg_element(a, 0, b);
    const GiNaC::symbol& t = arg_symbol(a, 1, b);
    const auto R = representation_of(a, 2, w.parent_ptr(), b);
    return signals::signal_of(R, w.coefficients(), t);
}

value builtin_annihilator(const builtin& b, const std::vector<value>& a, context&) {
    return signals::annihilator(arg_ex(a, 0, b), arg_symbol(a, 1, b), arg_symbol(a, 2, b));
}

value builtin_sequence(const builtin& b, const std::vector<value>& a, context&) {
    const element& w = arg_element(a, 0, b);
    const long k0 = arg_int(a, 1, b, -100000, 100000);
    const long count = arg_int(a, 2, b, 0, 10000);
    const auto R = representation_of(a, 3, w.parent_ptr(), b);
    const auto v = signals::sequence_of(R, w.coefficients(), k0, static_cast<std::size_t>(count));
    return list(v.begin(), v.end());
}

value builtin_sampling(const builtin& b, const std::vector<value>& a, context&) {
    const element& d = arg_element(a, 0, b);
    const GiNaC::ex& h = arg_ex(a, 1, b);
    const GiNaC::symbol& l = arg_symbol(a, 2, b);
    const auto R = signals::represent_on(d.parent_ptr(), d.coefficients());
    const auto s = signals::sample(R, h, l);
    return list{value(element(d.parent_ptr(), s.shift)), value(s.q), value(s.report)};
}

value builtin_transmittance(const builtin& b, const std::vector<value>& a, context&) {
    const std::vector<GiNaC::ex> as = arg_ex_list(a, 0, b), bs = arg_ex_list(a, 1, b);
    const element& d = arg_element(a, 2, b);
    if (as.empty() || bs.empty())
        throw type_error(b.name + ": the lists a and b must not be empty (usage: " + b.signature + ")");
    return element(d.parent_ptr(), signals::transmittance(d.parent(), d.coefficients(), as, bs));
}

value builtin_response_over(const builtin& b, const std::vector<value>& a, context&) {
    const std::vector<GiNaC::ex> as = arg_ex_list(a, 0, b), bs = arg_ex_list(a, 1, b);
    const element& d = arg_element(a, 4, b);
    if (as.empty() || bs.empty())
        throw type_error(b.name + ": the lists a and b must not be empty (usage: " + b.signature + ")");
    const auto x = signals::respond_over(d.parent_ptr(), d.coefficients(), as, bs, arg_ex(a, 2, b),
                                         arg_symbol(a, 3, b));
    return list{value(x.particular), value(element(d.parent_ptr(), x.element)), value(x.report)};
}

value builtin_frequency_response(const builtin& b, const std::vector<value>& a, context&) {
    const auto fr = signals::frequency_response_of(arg_ex_list(a, 0, b), arg_ex_list(a, 1, b), arg_ex(a, 2, b));
    return list{value(fr.gain), value(fr.phase)};
}

value builtin_response(const builtin& b, const std::vector<value>& a, context&) {
    const std::vector<GiNaC::ex> as = arg_ex_list(a, 0, b), bs = arg_ex_list(a, 1, b);
    return response_list(signals::respond(as, bs, arg_ex(a, 2, b), arg_symbol(a, 3, b)));
}

value builtin_sequence_annihilator(const builtin& b, const std::vector<value>& a, context&) {
    return signals::sequence_annihilator(arg_ex(a, 0, b), arg_symbol(a, 1, b), arg_symbol(a, 2, b));
}

value builtin_represent_sequence(const builtin& b, const std::vector<value>& a, context& ctx) {
    return represent_signal(a, ctx, b, true);
}

// read as signal reads its arguments; the closed form is lambda(w d^k), not lambda(w exp(d t))
value builtin_sequence_formula(const builtin& b, const std::vector<value>& a, context&) {
    const element& w = arg_element(a, 0, b);
    const GiNaC::symbol& k = arg_symbol(a, 1, b);
    const auto R = representation_of(a, 2, w.parent_ptr(), b);
    return signals::sequence_formula(R, w.coefficients(), k);
}

value builtin_sequence_response(const builtin& b, const std::vector<value>& a, context&) {
    const std::vector<GiNaC::ex> as = arg_ex_list(a, 0, b), bs = arg_ex_list(a, 1, b);
    return response_list(signals::respond_discrete(as, bs, arg_ex(a, 2, b), arg_symbol(a, 3, b)));
}

value builtin_z_transform(const builtin& b, const std::vector<value>& a, context&) {
    return signals::z_transform(arg_ex(a, 0, b), arg_symbol(a, 1, b), arg_ex(a, 2, b));
}

value builtin_modulation(const builtin& b, const std::vector<value>& a, context&) {
    const element& w = arg_element(a, 0, b);
    const GiNaC::symbol& t = arg_symbol(a, 1, b);
    const element& d = arg_element(a, 2, b);
    if (d.parent().name() != w.parent().name())
        throw type_error(b.name + ": w and d must be elements of the same algebra");
    const auto R = signals::represent_on(d.parent_ptr(), d.coefficients());
    signals::modulation m;
    if (dynamic_cast<const sobrero*>(&w.parent())) {
        m = signals::sobrero_modulation(R, w.coefficients(), t);
    } else {
        const multicomplex& M = multicomplex_of(w, b);
        const auto c = signals::carriers_of(M, d.coefficients());
        if (!c)
            throw domain_error(b.name + ": d must be of the form sigma + omega_0 i0 + ... + omega_n in "
                                        "(IV.1.9); it has components on products of imaginary units");
        m = signals::modulation_of(R, *c, w.coefficients(), t);
    }
    return list{value(m.a), value(m.b), value(m.amplitude), value(m.phase)};
}

value builtin_amplitude_modulated(const builtin& b, const std::vector<value>& a, context&) {
    const element& w = arg_element(a, 0, b);
    const auto am = signals::amplitude_modulated(multicomplex_of(w, b), w.coefficients());
    if (am.holds == truth::unknown) throw domain_error(b.name + ": " + am.report);
    if (am.holds == truth::no) return list{value(false), value(GiNaC::ex(0)), value(list{}), value(am.report)};
    list phases;
    for (const GiNaC::ex& p : am.phases) phases.push_back(value(p));
    return list{value(true), value(am.amplitude), value(phases), value(am.report)};
}

}  // namespace

void register_signals_builtins(registry& r) {
    add_builtins(r, section, {
        {"represent", "represent(f, t [, d])",
         "Psi(f): the element representing the signal f(t). Without d: f is a quasi-polynomial (sums and "
         "products of t^k, exp(a t), cos(b t), sin(b t), cosh, sinh; parameters real) and the element lives in "
         "the smallest polynomial algebra P_n = R[X]/(p) that holds it (p = annihilator(f, t, X)), with "
         "d = v. With d: on d's algebra, where f must solve q(D) f = 0 for q the minimal polynomial of d. "
         "Psi(f') = d Psi(f); Psi^-1(w) = lambda(w exp(d t)), lambda the last coordinate in the power basis of d "
         "(on a multicomplex algebra the coordinate of 1, IV.1.16 corrected; on a Sobrero algebra Re of the "
         "coordinate of eps^n, IV.1.2.17-18 corrected).",
         "Thm II.1.1, Thm II.2.3", "represent(t*exp(-t), t)", 2, 3, builtin_represent},
        {"represent_product", "represent_product(f, g, t)",
         "The product f g of two quasi-polynomial signals on the tensor product of their least algebras: "
         "[w, d] with w = Psi(f) (x) Psi(g) on P_r (x) P_s and d = v (x) 1 + 1 (x) v, so that signal(w, t, d) = f g "
         "and signal(d*w, t, d) = (f g)' (Leibniz's rule as the product by d); lambda = lambda_A (x) lambda_B.",
         "Thm II.1.1, Thm II.2.3 (products)", "represent_product(exp(-t), cos(t), t)",
         3, 3, builtin_represent_product},
        {"signal", "signal(w, t [, d])",
         "Psi^-1(w): the signal lambda(w exp(d t)) represented by the element w, with the operator d (default: "
         "the generator v of a polynomial algebra). signal(d*w, t) = diff(signal(w, t), t). On a multicomplex "
         "algebra with d = omega_0 i0 + ... + omega_n in, exp(d t) is the product of the carriers (IV.1.15) and "
         "the signal a sum of products of their cosines and sines.",
         "Thm II.1.1, Thm II.2.3", "signal(represent(t*exp(-t), t), t)", 2, 3, builtin_signal},
        {"annihilator", "annihilator(f, t, X)",
         "The monic real polynomial p(X) of least degree with p(D) f = 0, for a quasi-polynomial f in t: each "
         "exponent a + I b of f with highest power t^k gives ((X - a)^2 + b^2)^(k+1) ((X - a)^(k+1) for b = 0).",
         "Thm II.1.1", "annihilator(t*cos(2*t) + exp(-t), t, X)", 3, 3, builtin_annihilator},
        {"sequence", "sequence(w, k0, count [, d])",
         "The discrete signal represented by w with the shift as multiplication by d (default: the generator "
         "v of a polynomial algebra): [lambda(w d^k) for k = k0 .. k0 + count - 1]. Negative k need d "
         "invertible.",
         "Thm II.3.1-II.3.3", "sequence(find_generator(polynomial_algebra(X^2 - X - 1, X)), 0, 10)",
         3, 4, builtin_sequence},
        {"sampling", "sampling(d, h, l)",
         "Sampling with step h of the signals represented with the operator d (an element of the algebra; for "
         "a polynomial algebra its generator v): [exp(h d), q(l), report]. The samples f(k h) of the signal "
         "Psi^-1(w) are the discrete signal of the same w with the shift exp(h d); q(l) = det(l I - exp(h [d])) "
         "is their characteristic polynomial. The report says whether the samples alias (two roots r, s of p "
         "with e^(h r) = e^(h s): they then span fewer dimensions than q's degree). q comes from the roots of p's "
         "rational factors (degree <= 3, Cardano for 3); with a factor of higher degree and numbers for p and h, "
         "exp(h d) and q are numeric (30 digits), marked as such in the report with a bound on q's coefficients.",
         "Thm II.3.4, Cor. II.3.5 (II.3.26-32)", "sampling(find_generator(polynomial_algebra(X^2 + pi^2, X)), 1, l)",
         3, 3, builtin_sampling},
        {"transmittance", "transmittance(a, b, d)",
         "H(d) = q(d)/p(d) of the system a_0 x^(m) + ... + a_m x = b_0 f^(p) + ... + b_p f (a, b: the lists "
         "a_0 .. a_m, b_0 .. b_p), on d's algebra. Refused (zero divisor) where p(d) is not invertible: a root of "
         "p is an eigenvalue of d, and an input on that mode resonates.",
         "(IV.3.7-15)", "transmittance([1, 3, 2], [1], find_generator(polynomial_algebra(X^2 + 1, X)))",
         3, 3, builtin_transmittance},
        {"response_over", "response_over(a, b, f, t, d)",
         "The particular response x = Psi^-1[H(d) Psi(f)] of a_0 x^(m) + ... + a_m x = b_0 f^(p) + ... + b_p f on the "
         "algebra of d (f must solve q(D) f = 0, q the minimal polynomial of d): [x, H(d) Psi(f), report], x "
         "substituted into the system. The report names the case of IV.3.2: filtered out (a), partially filtered "
         "(b), and on a multicomplex algebra not distorted (c: Psi(f) and H(d) of special type, the response "
         "amplitude-modulated like the input), corrected (d: the response of special type, the input not) or "
         "distorted; p(d) a zero divisor (e, resonance) is an error.",
         "(IV.3.13-16), IV.3.2 a-e", "response_over([1, 0, 10], [1], cos(3*t)*cos(t), t, 3*imag_unit(multicomplex(1), "
         "0) + imag_unit(multicomplex(1), 1))", 5, 5, builtin_response_over},
        {"frequency_response", "frequency_response(a, b, w)",
         "The transmittance of a_0 x^(m) + ... + a_m x = b_0 f^(p) + ... + b_p f on the imaginary axis, "
         "H(i w) = q(i w)/p(i w), as [gain, phase]: gain = |H(i w)|, phase = atan2(Im H, Re H), real expressions "
         "in the real frequency w (for plots of a filter).",
         "(IV.3.15)", "frequency_response([1, 1, 1], [1], w)", 3, 3, builtin_frequency_response},
        {"response", "response(a, b, f, t)",
         "The response of a_0 x^(m) + ... + a_m x = b_0 f^(p) + ... + b_p f (m > p) to the quasi-polynomial input "
         "f(t): [particular, zero_state, report]. particular = Psi^-1[H(d) Psi(f)] in the input's class (d = v on "
         "the input's least algebra); zero_state has x(0) = ... = x^(m-1)(0) = 0 and lives on the algebra of "
         "p r (Thm IV.3.2.1). The report names the case: passed, partially filtered, filtered out (q vanishes on the "
         "input's modes) or resonant (p shares a mode with the input that q does not cancel: secular terms; then "
         "particular is the zero-state response). Both are substituted into the system before they are returned. "
         "Where the roots of p r cannot be told real or complex (a symbolic discriminant), zero_state is \"not "
         "derived\" and the report says why.",
         "(IV.3.7-17), Thm IV.3.2.1", "response([1, 0, 1], [1], cos(t), t)", 4, 4, builtin_response},
        {"sequence_annihilator", "sequence_annihilator(f, k, X)",
         "The monic real polynomial p(X) of least degree with p(E) f = 0, E the shift f(k) -> f(k + 1), for a "
         "sequence in closed form (sums and products of k^j, a^k, exp(b k), cos(c k), sin(c k)): each ratio "
         "rho = a e^b e^(+-i c) with highest power k^j gives (X - rho)^(j+1), a conjugate pair "
         "(X^2 - 2 Re(rho) X + |rho|^2)^(j+1).",
         "Thm II.3.1", "sequence_annihilator(k*2^k + cos(pi*k/2), k, X)", 3, 3, builtin_sequence_annihilator},
        {"represent_sequence", "represent_sequence(f, k [, d])",
         "Psi_d(f): the element representing the sequence f(k) with the shift as multiplication by d. Without d: "
         "on the smallest polynomial algebra P_n (p = sequence_annihilator(f, k, X)), d = v; with d: on d's "
         "algebra, where f must solve q(E) f = 0 for q the minimal polynomial of d. lambda(w d^j) = f(j).",
         "Thm II.3.1-II.3.3", "represent_sequence(2^k + k, k)", 2, 3, builtin_represent_sequence},
        {"sequence_formula", "sequence_formula(w, k [, d])",
         "Psi_d^-1(w) in closed form: lambda(w d^k) as an expression in k (d^k by interpolation of z^k on the "
         "roots of d's minimal polynomial), d the generator v of a polynomial algebra by default.",
         "Thm II.3.3", "sequence_formula(represent_sequence(2^k + k, k), k)", 2, 3, builtin_sequence_formula},
        {"sequence_response", "sequence_response(a, b, f, k)",
         "The response of the digital system a_0 x(k+m) + ... + a_m x(k) = b_0 f(k+p) + ... + b_p f(k) (m > p) to "
         "the sequence f(k) in closed form: [particular, zero_state, report], as response() for analog systems; "
         "zero_state has x(0) = ... = x(m-1) = 0 (IV.3.19).",
         "(IV.3.7-19), Thm IV.3.2.1", "sequence_response([1, -1/2], [1], 1, k)", 4, 4, builtin_sequence_response},
        {"z_transform", "z_transform(f, k, z)",
         "Z{f}(z) = sum_(k >= 0) f(k) z^(-k) for a sequence f(k) in closed form (as sequence_annihilator reads it), "
         "derived from its representation: f(k) = lambda(w d^k) gives Z{f} = z lambda(w Q(z, d))/p(z), "
         "Q(z, X) = (p(z) - p(X))/(z - X), p the sequence's least equation; valid for |z| beyond every root of p. "
         "The Z transfer function of remark 4: the zero-state response x of sequence_response has "
         "p(z) Z{x} = q(z) Z{f} - sum_(i=1..p) q_i sum_(j<i) f(j) z^(i-j) (q_i the coefficient of z^i in q), "
         "so Z{x} = (q(z)/p(z)) Z{f} for an input side b = [b_0] (docs/signals.md).",
         "IV.3.2 remark 4, Thm II.3.3", "z_transform(k*2^k, k, z)", 3, 3, builtin_z_transform},
        {"modulation", "modulation(w, t, d)",
         "The signal represented by w as a carrier with amplitude and phase modulation: [a, b, A, theta] with "
         "signal(w, t, d) = a cos(omega t) + b sin(omega t) = A cos(omega t - theta), A = sqrt(a^2 + b^2), "
         "theta = atan2(b, a). On a multicomplex algebra d = omega_0 i0 + ... + omega_n in (+ a real part) and the "
         "carrier is omega_0 (a and b are modulated by omega_1 .. omega_n); on a Sobrero algebra "
         "d = delta + eps + j omega (any d with a j part omega) and a, b are polynomial-exponential.",
         "(IV.1.24-30, IV.1.2.20-25)", "modulation(one(multicomplex(1)), t, 3*imag_unit(multicomplex(1), 0) + "
         "imag_unit(multicomplex(1), 1))", 3, 3, builtin_modulation},
        {"amplitude_modulated", "amplitude_modulated(w)",
         "Does w (an element of a multicomplex algebra) represent a purely amplitude-modulated signal "
         "A cos(omega_0 t - phi_0) ... cos(omega_n t - phi_n), A > 0, for every d = omega_0 i0 + ... + omega_n in? "
         "[true, A, [phi_0, ..., phi_n], report] when w = A exp(-(phi_0 i0 + ... + phi_n in)) (phi_k, k >= 1, "
         "in [-pi/2, pi/2), phi_0 absorbing the sign); [false, 0, [], report] naming the condition that fails "
         "(equal moduli of the idempotent components, phases of the form phi_0 + sum +-phi_k, decided without "
         "choosing branches of arg). An equality that cannot be decided is an error, never a guess.",
         "(IV.1.50-57, IV.1.64-68)", "amplitude_modulated(2*exp(imag_unit(multicomplex(1), 0)))",
         1, 1, builtin_amplitude_modulated},
    });
}

}  // namespace symrep::lang
