// symrep/mechanics/cauchy_problem.h -- a linear Cauchy problem for a vector
// (or scalar) function of t, as a user writes it, and its exact solution by
// the operator solver (thesis VI.1.26-38, 47-57, 62-67, 68-86).
//
// mechanics/ solves the rotating-frame problems of Ch. VI: the rotation
// operator algebra, quasi-polynomial forcing, operator ODEs, the Cauchy problem
// (this header) and scenes with values. It includes core/, scalar/, algebra/,
// vector/ and numeric/ (docs/architecture.md).
//
// The problem is   E(x, x', ..., x^(M), t) = 0,   x^(m)(0) = X_m  (m < M),
// with E linear in the unknowns x^(m). Its operator part must be a polynomial
// in one operator K = w x (w a constant vector symbol, the same in every term):
// each term is a scalar times x^(m), w x x^(m), w x (w x x^(m)) or w (w . x^(m))
// (= K^2 x^(m) + |w|^2 x^(m)). Its free part (the terms without an unknown)
// is a sum of functions of t times constant vectors: quasi-polynomials (t^k e^(a t) cos(b t),
// sin(b t)) solved in closed form by convolution, any other function finite for t >= 0
// (a/(1 + t^2), exp(-t^2)) by its Duhamel integral object (operator_form::general, VI.1.26-38);
// a function singular at some t >= 0 (1/(t - 1)) is refused by name. Nothing else is assumed: the orders, the
// coefficients (symbolic or numeric) and the forcing are read from E.
//
// reduce() reads E into the operator form of operator_ode.h (the algebra of K,
// R + C, thesis Ch. II-III applied to Ch. VI); solve() solves it there and
// recombines   x(t) = sum_P c_0(t) P + c_1(t) w x P + c_2(t) w x (w x P)
// over the data vectors P (initial values, forcing vectors) in coordinate-free
// form, with |w| for Omega. check() substitutes a solution back: the residual
// and the initial differences, each exactly 0 for a solution.
//
// This header declares; the work is in three files:
//   problem_reading.cpp  reduce(), and read_problem(): the reading made once when a problem
//                        is posed (the operator form, else fixed_axis.h, turning_frame.h or
//                        the velocity problem)
//   cauchy_solve.cpp     solve(), solve_unwitnessed(), vector_solution()
//   solution_check.cpp   check() (its zero proofs: residual_proof.h)
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "symrep/mechanics/operator_ode.h"
#include "symrep/scalar/floats.h"

namespace symrep::mechanics {

struct operator_form;
struct fixed_axis_form;
struct turning_frame_form;
struct dual_darboux_form;

struct cauchy_problem {
    std::string name;                  ///< the unknown's name, e.g. "r"
    GiNaC::ex t;                       ///< the independent variable (a symbol)
    GiNaC::ex expression;              ///< E = lhs - rhs
    std::vector<GiNaC::ex> unknowns;   ///< x, x', ..., x^(M) as symbols (vector symbols for a vector x)
    std::vector<GiNaC::ex> initial;    ///< x(0), ..., x^(M-1)(0)
    bool is_vector = true;
    /// reduce(*this), kept by whoever made the problem so that solve() does not read it again.
    std::shared_ptr<const operator_form> reduced;
    /// When the operator is not constant but the problem is a fixed-axis rotating-frame
    /// problem (fixed_axis.h, VI.2): its reading, and solve() reduces it to the inertial one.
    std::shared_ptr<const fixed_axis_form> fixed_axis;
    /// A rotating-frame problem with a turning w(t) or a central field (turning_frame.h, VI.3):
    /// its reading; solve() refuses it (Q or psi has no closed form), reduced_solution evaluates it.
    std::shared_ptr<const turning_frame_form> turning;
    /// A second-order problem in which x itself does not appear (only x', x''), whose
    /// first-order problem for v = x' is a rotating-frame one (a charge in B(t), VI.2.50):
    /// that problem (unknowns x', x''); solve() gives x = x(0) + int_0^t v (VI.2.51-52).
    std::shared_ptr<const cauchy_problem> velocity;
    /// A problem in the dual unit eps of the form m (x' + Omega x x) = 0 (the dual Poisson-Darboux
    /// problem, dual_darboux.h): its reading; solve() gives the closed form by transference.
    std::shared_ptr<const dual_darboux_form> dual_darboux;

    /// M, the order.
    std::size_t order() const { return unknowns.size() - 1; }
    /// "r", "r'", "r''" ...
    std::string unknown_name(std::size_t m) const { return name + std::string(m, '\''); }
};

/// The problem in the operator form of operator_ode.h, with the data vectors
/// that the placeholder names stand for.
struct operator_form {
    operator_ode ode;
    std::vector<std::pair<std::string, GiNaC::ex>> data;  ///< placeholder name -> vector (or scalar)
    GiNaC::ex axis;    ///< w of K = w x; 0 when no term has an operator (then K = 0)
    GiNaC::ex Omega;   ///< the positive symbol standing for |w| in ode (0 without axis)
    /// The terms c(t) V of the right side whose c is not a quasi-polynomial (VI.1.26-38 hold for
    /// every f): not in ode; solve() adds their Duhamel integrals int_0^t Y(t - tau) c(tau) V dtau,
    /// Y the impulse response in the algebra of K (cauchy_solve.cpp). Each c is finite for t >= 0
    /// (num::require_finite_on_half_line).
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> general;
};

/// Reads E as sum_m A_m(K) x^(m) = sum_j q_j(t) F_j. Throws domain_error naming
/// the offending term when E is not linear in the unknowns, when two different
/// vectors act on x by x (the operators do not commute), when a coefficient
/// depends on t, or when a free term that is not a quasi-polynomial in t may be singular at
/// some t >= 0 (such terms otherwise go into operator_form::general).
operator_form reduce(const cauchy_problem& P);

/// Reads P once, for solve() and the solvers after it, and keeps the reading in P: the
/// operator form (P.reduced) when reduce() takes P; otherwise a rotating frame about a fixed
/// axis (P.fixed_axis, VI.2), a turning frame or central field (P.turning, VI.3), or, for a
/// second-order vector problem without x itself, the first-order problem for v = x' when one of
/// those readings takes it (P.velocity, VI.2.50-52). When none does: domain_error with the
/// fixed-axis reading's reason, else the turning-frame reading's, else reduce()'s error.
void read_problem(cauchy_problem& P);

/// Floating-point numbers (scalar/floats.h) in E or in an initial value of P.
bool problem_has_float(const cauchy_problem& P);

/// The exact solution x(t), coordinate-free (vector symbols, cross, dot, |w|).
/// Errors as reduce() and solve(operator_ode, ...) (closed_form_error when a
/// characteristic root has no closed form, algebra_error for a singular leading
/// coefficient).
/// Before it returns, the solution's residual and initial values are evaluated at one point
/// (solution_witness.h): a result seen wrong there is withheld, internal_error naming P.
GiNaC::ex solve(const cauchy_problem& P);

/// solve() without the witness: for the solvers that call it on their sub-problems (the
/// inertial problem, the impulse response, the velocity), whose result the outer witness tests.
GiNaC::ex solve_unwitnessed(const cauchy_problem& P);

/// x = sum_P c_0(t) P + c_1(t) w x P + c_2(t) w x (w x P) over the placeholders
/// of S (VI.1.21-22, 28, 31), with F's data vectors for the names and |w| for
/// F.Omega when that is a symbol. Used by solve() and by the scene solver.
GiNaC::ex vector_solution(const cauchy_problem& P, const operator_form& F, const operator_solution& S);

/// Result of substituting a candidate solution into the problem.
struct solution_check {
    GiNaC::ex residual;                   ///< E(s, s', ...), simplified
    std::vector<GiNaC::ex> initial_differences;  ///< s^(m)(0) - X_m
    bool residual_zero = false;
    /// The residual was seen nonzero at a point (numbers for every symbol, 40 digits): not 0.
    bool residual_seen_nonzero = false;
    bool initial_ok = false;
    /// With floating-point numbers in P or s, what is not exactly 0 may be rounding:
    /// it is taken as 0 when every coefficient of it is at most rounding_tolerance()
    /// times the largest coefficient of the terms it is the sum of; `rounding` is then
    /// the largest such ratio met (0 when everything was exactly 0).
    double rounding = 0;
    explicit operator bool() const { return residual_zero && initial_ok; }
};
/// Exact check. First in the algebra of K (issue 15.2): s read as sum_P c0 P + c1 K P + c2 K^2 P
/// over the data vectors, residual and initial values computed on the quasi-polynomial
/// coefficients, each decided by the scalar zero test; what that does not prove is decided
/// coordinate-free, at a point (seen nonzero) or by components (vector equality, see
/// vector.h). With floating-point numbers, exact up to rounding (solution_check::rounding).
solution_check check(const cauchy_problem& P, const GiNaC::ex& s);
/// has_float (a value read as 9.81 or 1e-3): scalar/floats.h.
using symrep::has_float;

/// The relative size taken as rounding by check(): 10^(5 - Digits) (1e-12 at
/// GiNaC's default of 17 digits: floats carry ~16, a few are lost in the sums).
double rounding_tolerance();

}  // namespace symrep::mechanics
