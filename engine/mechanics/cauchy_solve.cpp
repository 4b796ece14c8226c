// symrep/mechanics/cauchy_solve.cpp -- solving a Cauchy problem (cauchy_problem.h): the
// operator form of reduce() solved in the algebra of K (operator_ode.h, thesis VI.1.26-38,
// 47-57, 62-67, 68-86) and recombined coordinate-free, x = sum_P c_0 P + c_1 w x P +
// c_2 w x (w x P) (vector_solution); the fixed-axis (VI.2), turning-frame (VI.3) and velocity
// (VI.2.50-52) readings handed to their solvers; solve()'s witness (solution_witness.h).
#include "symrep/mechanics/cauchy_problem.h"
#include "symrep/mechanics/dual_darboux.h"
#include "symrep/mechanics/fixed_axis.h"
#include "symrep/mechanics/moving_frame.h"
#include "symrep/mechanics/turning_frame.h"
#include "symrep/mechanics/solution_witness.h"

#include <algorithm>
#include <map>

#include "symrep/dual/dual.h"
#include "symrep/scalar/scalar.h"
#include "symrep/core/error.h"
#include "symrep/vector/vector.h"

namespace symrep::mechanics {

using GiNaC::ex;

namespace {

// sin(u), cos(u) with the sign of u chosen by the printed text of u (no leading
// '-'): sin(-(w0 - |w|) t) -> -sin((w0 - |w|) t). GiNaC's own choice of the sign
// of w0 - |w| follows its term order, which varies from run to run.
ex positive_trig_arguments(const ex& e, const ex& t) {
    struct fix : GiNaC::map_function {
        ex t;
        ex operator()(const ex& x) override {
            const ex y = x.map(*this);
            const bool s = GiNaC::is_the_function<GiNaC::sin_SERIAL>(y);
            if (s || GiNaC::is_the_function<GiNaC::cos_SERIAL>(y)) {
                const ex u = GiNaC::collect(GiNaC::expand(y.op(0)), t);  // one form: (w0 - |w|)*t
                if (to_string(u).rfind('-', 0) == 0) return s ? -GiNaC::sin(-u) : GiNaC::cos(-u);
                return s ? GiNaC::sin(u) : GiNaC::cos(u);
            }
            return y;
        }
    } f;
    f.t = t;
    return f(e);
}

}  // namespace

// (VI.1.26-38: r = F_(-w t) r0 + int_0^t exp(-W (t - tau)) f(tau) dtau, for every f) the response
// with zero initial values to each term c(t) V of F.general: int_0^t Y(t - tau) V c(tau) dtau
// with Y(t) V = d/dt (S(t) V), S(t) V the response to the constant force V (S(0) = 0, so that
// d/dt int_0^t S(t - tau) V c(tau) dtau is that integral), S from the operator solver in the
// algebra of K and read coordinate-free: Y(t) V = sum_j g_j(t) V_j (V, w x V, w x (w x V)),
// each int_0^t g_j(t - tau) c(tau) dtau by duhamel() (fixed_axis.h).
ex general_response(const cauchy_problem& P, const operator_form& F) {
    const rotation_operator_algebra R(F.Omega);
    ex x = 0;
    for (const auto& [c, V] : F.general) {
        operator_form S = F;
        S.general.clear();
        S.ode.forcing = {{quasi_polynomial::from_ex(ex(1), P.t), 0, "G"}};
        S.data = {{"G", V}};
        operator_solution sol = solve(S.ode, R, P.t);
        sol.terms.erase(std::remove_if(sol.terms.begin(), sol.terms.end(),
                                       [](const placeholder_coefficients& pc) { return pc.vector != "G"; }),
                        sol.terms.end());
        const ex step = vector_solution(P, S, sol);
        if (!P.is_vector) {
            x += duhamel(GiNaC::diff(step, GiNaC::ex_to<GiNaC::symbol>(P.t)), c, P.t);
            continue;
        }
        // by functions of t times constant vectors (a literal axis leaves t inside a literal)
        const auto terms = terms_in_time(diff_t(step, P.t), P.t);
        if (!terms) throw algebra_error("internal: the impulse response of " + P.name + " is not read by terms in t");
        for (const auto& [g, Vj] : *terms) x += duhamel(g, c, P.t) * Vj;
    }
    return x;
}

ex vector_solution(const cauchy_problem& P, const operator_form& F, const operator_solution& S) {
    std::map<std::string, ex> data(F.data.begin(), F.data.end());
    const bool omega_symbol = GiNaC::is_a<GiNaC::symbol>(F.Omega);
    const ex norm_w = F.axis.is_zero() ? ex(0) : norm(F.axis);
    // each coefficient of a function of t once, in the field of its square root (sin(-u t) and
    // sin(u t) met as one after the signs are fixed)
    auto back = [&](const ex& c) {
        const ex x = positive_trig_arguments(normalize_trig_signs(c), P.t);
        return omega_symbol ? simplified_square_roots(x, P.t).subs(S.abbreviations).subs(F.Omega == norm_w)
                            : simplified_square_roots(x.subs(S.abbreviations), P.t);
    };
    ex x = 0;
    for (const placeholder_coefficients& pc : S.terms) {
        const ex v = data.at(pc.vector);
        const ex c0 = back(pc.c[0].to_ex_untidied()), c1 = back(pc.c[1].to_ex_untidied()),
                 c2 = back(pc.c[2].to_ex_untidied());
        if (!P.is_vector || F.axis.is_zero()) {
            if (!is_zero_scalar(c1) || !is_zero_scalar(c2))
                throw algebra_error("internal: K terms without an axis in the solution of " + P.name);
            x += c0 * v;
            continue;
        }
        x += c0 * v + c1 * cross(F.axis, v) + c2 * cross(F.axis, cross(F.axis, v));
    }
    return x;
}

ex solve(const cauchy_problem& P) {
    if (P.dual_darboux) {  // (issue 31 item 3) witnessed part by part: the primal and the dual problem
        const ex x = solve_unwitnessed(P);
        const auto [A, B] = dual_darboux_parts(P, *P.dual_darboux, x);
        require_witness(A, dual::primal(x));
        require_witness(B, dual::dual_part(x));
        return x;
    }
    const ex x = solve_unwitnessed(P);
    require_witness(P, x);  // (issue 27) never a result that its residual at a point sees wrong
    return x;
}

ex solve_unwitnessed(const cauchy_problem& P) {
    if (P.dual_darboux) {  // x^ = Q^ x^0 by transference (dual_darboux.h)
        const ex x = solve_dual_darboux(P, *P.dual_darboux);
        return problem_has_float(P) ? dual::reduce(GiNaC::evalf(x)) : x;
    }
    if (is_dual_problem(P))
        throw closed_form_error("the problem " + to_string(P.expression) + " = 0 holds the dual unit eps: with dual data "
                                "symrep solves the dual Poisson-Darboux problem m (" + P.unknown_name(1) +
                                " + Omega x " + P.name + ") = 0, " + P.name +
                                "(0) = x0 only (docs/rigid_body.md section 3)");
    if (const auto F = moving_frame_of(P)) return solve_moving_frame(P, *F);  // ([CS21] Thm 12) r = R (psi - o)
    if (!P.reduced && P.velocity) {  // (VI.2.51) x = x(0) + int_0^t x'
        const ex v = solve_unwitnessed(*P.velocity);
        try {
            return P.initial[0] + integral_in_t(v, P.t);
        } catch (const domain_error& e) {
            throw closed_form_error("the position " + P.name + " = " + P.name + "(0) + int_0^t " + P.velocity->name +
                                    " of the velocity " + P.velocity->name + " = " + to_string(v) + ": " + e.what());
        }
    }
    if (!P.reduced && P.fixed_axis) return solve_fixed_axis(P, *P.fixed_axis);
    if (!P.reduced && P.turning)
        if (const auto x = closed_solution(P, *P.turning)) return *x;
    if (!P.reduced && P.turning)
        throw closed_form_error("the solution " + describe_reduction(P, *P.turning) +
                                "\nhas no closed form in t (reduced_solution.h evaluates it)");
    const operator_form F = P.reduced ? *P.reduced : reduce(P);
    const rotation_operator_algebra R(F.Omega);
    ex x = vector_solution(P, F, solve(F.ode, R, P.t));
    if (!F.general.empty()) x += general_response(P, F);
    // derived exactly from the rationals the floats denote (reduce), rounded once here
    return problem_has_float(P) ? GiNaC::evalf(x) : x;
}

}  // namespace symrep::mechanics
