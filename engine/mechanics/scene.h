// symrep/mechanics/scene.h -- a scene (a Cauchy problem plus values of its
// parameters) and the smallest exact model for it.
//
// The solver of cauchy_problem.h writes x(t) = sum_P G_P(K) P over the data
// vectors P (initial values, forcing vectors), G_P in the algebra of K = w x,
// R[X]/(X^3 + |w|^2 X) (VI.1.12, 15). For a given P only G_P modulo the local
// minimal polynomial m_P of K on span{P, K P, K^2 P} matters (Corollary II.1.1,
// II.1.23-24; IV.3.2 b and the remark after Thm IV.3.2.1): m_P = X when
// w x P = 0 (P along w, or w = 0), X^2 + |w|^2 when w . P = 0, X^3 + |w|^2 X
// otherwise, 1 when P = 0. The scene's algebra is R[X]/(m) with m the lcm of
// the m_P. classify() decides these relations for the values, exactly (the zero
// test of scalar/scalar.h by components; a floating-point residue counts as not
// 0, so floating-point data can only keep the general model), drops the terms of
// the equation that vanish for the values, and puts the exact values (no
// floating-point number in them) into the coefficients; floating-point values
// are put in at the end. solve() then derives the solution with only the scalar
// problems (axial K -> 0, planar K -> i|w|) and the coefficients each P needs.
//
// The result equals the general solution with the values put in (where that is
// defined; where the general form is singular at the values, its limit).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "symrep/mechanics/cauchy_problem.h"

namespace symrep::mechanics {

/// Values of a problem's parameters: vector symbols -> vectors (literals [x, y, z]
/// or vector expressions), scalar symbols -> expressions. Values are final (a
/// value does not refer to another one). Symbols without a value stay symbols.
struct parameter_values {
    std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less> vectors;
    GiNaC::exmap scalars;
};

/// e with the values put in: vector symbols with a value by it (the others stay
/// abstract), then the scalars. Throws domain_error when e is singular there.
GiNaC::ex put_values(const GiNaC::ex& e, const parameter_values& v);

/// P with the values put into its equation and initial values (for check()).
cauchy_problem with_values(const cauchy_problem& P, const parameter_values& v);

/// How a data vector P relates to the operator K = w x for the values.
enum class data_relation {
    zero,           ///< P = 0: no term (m_P = 1)
    along_axis,     ///< w x P = 0 (P along w, or w = 0): m_P = X
    perpendicular,  ///< w . P = 0: m_P = X^2 + |w|^2
    general,        ///< m_P = X^3 + |w|^2 X
    no_operator     ///< K does not occur in the equation (or a scalar problem): m_P = X
};

struct data_model {
    std::string name;        ///< "r(0)", "r'(0)", "F0", ... (the placeholder)
    GiNaC::ex vector;        ///< the data vector as in the problem
    data_relation relation = data_relation::general;
    cyclic_factors factors;  ///< m_P
    std::string reason;      ///< "w x g = 0", "w . r0 = 0", "v0 = 0" ...
};

/// The methods a scene can be solved by (the cheapest exact one is chosen).
enum class solution_method {
    closed_form  ///< impulse responses of the scalar problems, convolution with the forcing (VI.1.26-38)
};

struct scene_model {
    GiNaC::ex axis;          ///< w of K = w x; 0 without an operator term
    GiNaC::ex axis_value;    ///< w for the values
    bool axis_zero = false;  ///< w = 0 for the values (K = 0 on every data vector)
    GiNaC::ex Omega;         ///< |w| in the derivation: its exact value, or the positive symbol of operator_form
    bool operator_present = false;  ///< K occurs in the equation once vanishing terms are dropped
    operator_form form;      ///< the model: coefficients with exact values, vanishing terms dropped
    std::vector<data_model> data;
    std::vector<std::string> dropped;   ///< terms of the equation that vanish for the values
    std::vector<std::string> exact_values;     ///< "w0 = 1/2": put into the derivation
    std::vector<std::string> deferred_values;  ///< names of floating-point values, put in at the end
    /// Floating-point values that, put in at the end, made the solution singular (w0 = 2.0
    /// next to cos(2 t): a resonance the derivation did not see); solve() then derives again
    /// with them exact (the binary numbers they are) and evaluates the result in floats.
    std::vector<std::string> floats_made_exact;
    cyclic_factors algebra{false, false};      ///< m = lcm of the m_P: the scene's algebra R[X]/(m)
    std::string axial_problem, planar_problem; ///< characteristic polynomials solved ("" when not needed)
    solution_method method = solution_method::closed_form;
    std::string method_reason;
    /// A fixed-axis problem with a varying w (fixed_axis.h): the reduction used, then
    /// report() says only that (the fields above describe constant-operator scenes).
    std::string reduction;

    /// Per placeholder name, m_P (for solve(operator_ode, ..., factors)).
    placeholder_factors factors() const;
    /// A report of the model and the method, one statement per line, deterministic.
    std::string report() const;
};

/// Classifies the scene (P with the values v) and builds its smallest exact model.
/// Throws domain_error when a value is given for the unknown or for t, when a
/// coefficient is singular at the values, or when the leading coefficient
/// vanishes for them.
scene_model classify(const cauchy_problem& P, const parameter_values& v);

struct scene_solution {
    scene_model model;
    GiNaC::ex model_solution;  ///< coordinate-free: vectors symbolic, exact scalar values in
    GiNaC::ex x;               ///< with every value put in
};
/// The scene's exact solution derived in its smallest model (errors as classify()
/// and solve(cauchy_problem)).
scene_solution solve(const cauchy_problem& P, const parameter_values& v);

}  // namespace symrep::mechanics
