// symrep/signals/response.h -- the transmittance and the response of a linear system
// to an input represented on an algebra (thesis IV.3.1-IV.3.2, Thm IV.3.2.1).
//
// The system a_0 x^(m) + ... + a_m x = b_0 f^(p) + ... + b_p f (IV.3.7), with
// p(l) = sum a_(m-k) l^k and q(l) = sum b_(p-k) l^k (IV.3.11-12). An input f with the
// representation Psi on A (operator d) gives p(d) Psi(x) = q(d) Psi(f) (IV.3.13), and
// where p(d) is invertible the transmittance H(d) = q(d)/p(d) (IV.3.15) gives the
// particular response x = Psi^-1[H(d) Psi(f)] (IV.3.16), in the input's class.
//
// The cases of IV.3.2, decided exactly (FORMULAS.md reads e) and remark 1 with care):
//   filtered out   q(d) Psi(f) = 0: the particular response is 0 (a);
//   partially filtered   the response's element has a minimal polynomial of lower
//                  degree than the input's (b);
//   passed         p(d) Psi(x) = q(d) Psi(f) solvable in A (also where p(d) is a zero
//                  divisor but the input has no component on the shared modes);
//   resonant       not solvable in A: the input holds a mode at a root of p that q does
//                  not cancel; the response has secular terms, and lives on the
//                  polynomial algebra of Pi = p r (Thm IV.3.2.1), r the input's least
//                  equation.
// The zero-state response (x(0) = ... = x^(m-1)(0) = 0; FORMULAS.md: "response" has
// two definitions in the thesis, this is the one with zero initial conditions) is
// always derived on the algebra of Pi. Every response is substituted into the system
// (residual proved 0) before it is returned.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "symrep/algebra/algebra.h"

namespace symrep::signals {

/// p(l) = a_0 l^m + ... + a_m from the list a_0 .. a_m (IV.3.11).
GiNaC::ex system_polynomial(const std::vector<GiNaC::ex>& a, const GiNaC::symbol& l);

/// (IV.3.15) H(d) = q(d)/p(d) on d's algebra; zero_divisor_error (naming resonance)
/// when p(d) is a zero divisor.
coeffs transmittance(const algebra& A, const coeffs& d, const std::vector<GiNaC::ex>& a,
                     const std::vector<GiNaC::ex>& b);

/// (IV.3.15 on the imaginary axis) H(i w) = q(i w)/p(i w) of the analog system as a gain and a
/// phase, real expressions in the real frequency w: gain = |H(i w)| = sqrt(|q|^2/|p|^2),
/// phase = atan2(Im H, Re H). For plots of the filter along the frequency axis.
struct frequency_response {
    GiNaC::ex gain, phase;
};
frequency_response frequency_response_of(const std::vector<GiNaC::ex>& a, const std::vector<GiNaC::ex>& b,
                                         const GiNaC::ex& w);

/// The cases of IV.3.2 a response falls in (respond: the first four; respond_over: all but resonant).
enum class response_kind {
    passed,              ///< x = Psi^-1[H(d) Psi(f)] in the input's class (IV.3.16)
    partially_filtered,  ///< b: the response's least equation has lower order than the input's
    filtered_out,        ///< a: q(d) Psi(f) = 0, the particular response is 0
    resonant,            ///< e: not solvable in the input's class (secular terms, Thm IV.3.2.1)
    not_distorted,       ///< c: Psi(f) and H(d) of special type (IV.1.57)
    corrected,           ///< d: Psi(f) not of special type, H(d) Psi(f) of special type
    distorted,           ///< the input of special type, the response not
};
/// The name of the case as reports print it: "passed", "partially filtered", "filtered out",
/// "resonant", "not distorted", "corrected", "distorted".
std::string kind_text(response_kind k);
std::ostream& operator<<(std::ostream& os, response_kind k);

struct system_response {
    response_kind kind = response_kind::passed;  ///< passed, partially filtered, filtered out or resonant
    GiNaC::ex particular;   ///< in the input's class (IV.3.16); resonant: the zero-state response
    GiNaC::ex zero_state;   ///< x^(k)(0) = 0, k < m
    bool has_zero_state = true;  ///< false where the roots of p r are not decided (then `report` says why)
    GiNaC::ex input_equation;  ///< r(X): the input's least equation
    std::string report;     ///< one or two sentences naming the case and why
};

/// The response of a_0 x^(m) + ... + a_m x = b_0 f^(p) + ... + b_p f (m > p, a_0 != 0) to a
/// quasi-polynomial input f(t).
system_response respond(const std::vector<GiNaC::ex>& a, const std::vector<GiNaC::ex>& b, const GiNaC::ex& f,
                        const GiNaC::symbol& t);

/// (IV.3.13-16, cases a-e of IV.3.2 on any algebra) The particular response x = Psi^-1[H(d) Psi(f)]
/// on the algebra of d (a multicomplex algebra for cases c-d), the input f solving q(D) f = 0 for q the
/// minimal polynomial of d. kind: filtered out (a: H(d) Psi(f) = 0), partially filtered (b: the
/// response's least equation has lower order than the input's), not distorted (c: Psi(f) and H(d)
/// of special type, IV.1.57, so the response is amplitude-modulated like the input), corrected (d:
/// Psi(f) not of special type, H(d) Psi(f) of special type), distorted (the input of special type,
/// the response not), or passed. p(d) a zero divisor (case e) is a zero_divisor_error from
/// transmittance(). The response is substituted into the system before it is returned.
struct algebra_response {
    coeffs element;        ///< H(d) Psi(f)
    GiNaC::ex particular;  ///< its signal
    response_kind kind = response_kind::passed;
    std::string report;
};
algebra_response respond_over(const algebra_ptr& A, const coeffs& d, const std::vector<GiNaC::ex>& a,
                              const std::vector<GiNaC::ex>& b, const GiNaC::ex& f, const GiNaC::symbol& t);

/// The same for a digital system (IV.3.7 with the shift: a_0 x(k+m) + ... + a_m x(k) =
/// b_0 f(k+p) + ... + b_p f(k)) and a sequence f(k) in closed form (sequence_annihilator):
/// the same algebra, Psi_d^-1(w) = lambda(w v^k), zero state x(0) = ... = x(m-1) = 0 (IV.3.19).
system_response respond_discrete(const std::vector<GiNaC::ex>& a, const std::vector<GiNaC::ex>& b,
                                 const GiNaC::ex& f, const GiNaC::symbol& k);

}  // namespace symrep::signals
