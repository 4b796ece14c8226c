// examples/cpp/foucault.cpp -- the Foucault pendulum through symrep's C++ API (docs/library.md).
//
// The problem (thesis VI.1.68), for ANY axis of rotation w:
//     r'' + 2 w x r' + w x (w x r) + w0^2 r = 0,   r(0) = r0,   r'(0) = v0.
// The program
//   1. states it as a mechanics::cauchy_problem with abstract vectors w, r0, v0;
//   2. derives the exact, coordinate-free solution (mechanics::solve);
//   3. checks it exactly: the residual and the initial differences are 0 (mechanics::check),
//      and it equals the thesis's form (VI.1.79) (symrep::equal);
//   4. puts in the values of a 67 m pendulum at Paris and compares r and r' with Boost.Odeint
//      (num::verify) over one day.
// It prints what it finds and exits with 1 when a check fails (2 on an error of the engine).
//
// Build: see CMakeLists.txt next to this file (find_package(symrep), symrep::engine).
#include <cstddef>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include <symrep/core/error.h>                // symrep::error and its subclasses
#include <symrep/mechanics/cauchy_problem.h>  // cauchy_problem, solve, check
#include <symrep/mechanics/scene.h>           // parameter_values, put_values
#include <symrep/numeric/verify.h>            // num::verify (Boost.Odeint against a closed form)
#include <symrep/output/printer.h>            // output::print_ex: canonical, deterministic text
#include <symrep/vector/vector.h>             // vector symbols, cross, dot, norm, equal

using GiNaC::ex;
namespace mech = symrep::mechanics;
namespace num = symrep::num;

namespace {

int failures = 0;

void report(const std::string& what, bool ok) {
    std::cout << (ok ? "ok    " : "FAILED") << "  " << what << "\n";
    if (!ok) ++failures;
}

}  // namespace

int main() {
    try {
        // --- 1. the problem -----------------------------------------------------------------
        // Scalars are GiNaC symbols: t real, w0 positive (so that sqrt(w0^2) = w0). Vectors are
        // real symbols registered as vectors (vector.h); r is a vector function of t, and
        // derivative() gives the symbols r', r''.
        const GiNaC::realsymbol t("t");
        const GiNaC::possymbol w0("w0");
        const ex w = symrep::vector_symbol("w");
        const ex r0 = symrep::vector_symbol("r0");
        const ex v0 = symrep::vector_symbol("v0");
        const ex r = symrep::vector_function("r", t);
        const ex r1 = symrep::derivative(r);   // r'
        const ex r2 = symrep::derivative(r1);  // r''

        mech::cauchy_problem P;
        P.name = "r";
        P.t = t;
        P.expression = r2 + 2 * symrep::cross(w, r1) + symrep::cross(w, symrep::cross(w, r)) + GiNaC::pow(w0, 2) * r;
        P.unknowns = {r, r1, r2};  // x, x', x'': the order is 2
        P.initial = {r0, v0};      // r(0), r'(0)
        P.is_vector = true;
        std::cout << "problem: " << symrep::output::print_ex(P.expression) << " = 0, r(0) = r0, r'(0) = v0\n";

        // --- 2. the exact solution ------------------------------------------------------------
        // solve() reads the equation in the algebra of K = w x (R[X]/(X^3 + |w|^2 X)), solves it
        // there and recombines r(t) = sum_P c0(t) P + c1(t) w x P + c2(t) w x (w x P).
        const ex s = mech::solve(P);
        std::cout << "r(t) = " << symrep::output::print_ex(s) << "\n";

        // --- 3. exact checks ------------------------------------------------------------------
        const mech::solution_check c = mech::check(P, s);
        report("check(P, s): residual " + symrep::output::print_ex(c.residual) + ", initial values " +
                   (c.initial_ok ? "met" : "not met"),
               bool(c));

        // (VI.1.79) r = psi0 - sin(|w| t)/|w| w x psi0 + (1 - cos(|w| t))/|w|^2 w x (w x psi0),
        // psi0 = r0 cos(w0 t) + (v0 + w x r0)/w0 sin(w0 t): the solution without rotation, turned.
        const ex W = symrep::norm(w);
        const ex psi0 = r0 * GiNaC::cos(w0 * t) + (v0 + symrep::cross(w, r0)) / w0 * GiNaC::sin(w0 * t);
        const ex thesis = psi0 - GiNaC::sin(W * t) / W * symrep::cross(w, psi0) +
                          (1 - GiNaC::cos(W * t)) / GiNaC::pow(W, 2) * symrep::cross(w, symrep::cross(w, psi0));
        report("s equals the thesis's form (VI.1.79)", symrep::equal(s, thesis));

        // --- 4. Paris, against Boost.Odeint ---------------------------------------------------
        // Exact values (rationals, pi): the closed form is evaluated by the stable evaluator
        // (numeric/stable_evaluator.h), which keeps 1e-14 where |w| t is small.
        // |w| = 7.2921e-5 rad/s at latitude 48.85 deg, a 67 m pendulum released 3 m from rest.
        const ex phi = GiNaC::numeric(4885, 100) * GiNaC::Pi / 180;
        const ex Omega = GiNaC::numeric(72921, 1000000000);
        mech::parameter_values paris;
        paris.vectors[w] = symrep::vector_literal(Omega * GiNaC::cos(phi), 0, Omega * GiNaC::sin(phi));
        paris.vectors[r0] = symrep::vector_literal(3, 0, 0);
        paris.vectors[v0] = symrep::vector_literal(0, 0, 0);
        paris.scalars[w0] = GiNaC::sqrt(GiNaC::numeric(981, 100) / 67);

        // the closed form: r and r' in components (3x1 matrices once the values are in)
        const ex r_at = mech::put_values(s, paris);
        const ex v_at = mech::put_values(symrep::diff_t(s, t), paris);
        std::vector<ex> closed_form = num::flatten_outputs(r_at);
        for (const ex& x : num::flatten_outputs(v_at)) closed_form.push_back(x);

        // the first-order system y = (r, r'), y' = (r', r'') with r'' solved from the equation
        // (its leading coefficient is 1: r'' = -(the other terms))
        std::vector<ex> state;
        for (int i = 0; i < 6; ++i) state.push_back(GiNaC::symbol("y" + std::to_string(i)));
        mech::parameter_values at_state = paris;
        at_state.vectors[r] = symrep::vector_literal(state[0], state[1], state[2]);
        at_state.vectors[r1] = symrep::vector_literal(state[3], state[4], state[5]);
        at_state.vectors[r2] = symrep::vector_literal(0, 0, 0);
        const ex others = mech::put_values(P.expression, at_state);
        std::vector<ex> rhs{state[3], state[4], state[5]};
        for (const ex& x : num::flatten_outputs(others)) rhs.push_back(GiNaC::expand(-x));

        // one day, sampled every 300 s (289 points: 1 h is sample 12, 6 h sample 72, 1 day 288)
        num::integration_options opt;   // rkf78
        opt.abs_tol = opt.rel_tol = 1e-12;
        const std::size_t n = 289;
        const num::verify_result v =
            num::verify(closed_form, t, rhs, state, {3, 0, 0, 0, 0, 0}, {}, 0.0, 86400.0, n, opt);
        char line[200];
        std::snprintf(line, sizeof line,
                      "Boost.Odeint (rkf78, tolerance 1e-12) against the closed form over one day: "
                      "max relative difference %.2e at t = %.0f s",
                      v.max_relative_difference, v.time_of_max);
        report(line, v.max_relative_difference < 1e-5);

        std::cout << "position (m) at Paris, closed form | integrated:\n";
        for (std::size_t k : {std::size_t(12), std::size_t(72), std::size_t(288)}) {
            std::snprintf(line, sizeof line, "  t = %6.0f s: [%9.6f, %9.6f, %9.6f] | [%9.6f, %9.6f, %9.6f]",
                          v.times[k], v.closed_form(k, 0), v.closed_form(k, 1), v.closed_form(k, 2),
                          v.integrated(k, 0), v.integrated(k, 1), v.integrated(k, 2));
            std::cout << line << "\n";
        }
    } catch (const symrep::error& e) {
        // every failure the engine reports is a symrep::error with a complete message
        std::cerr << "foucault: error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "foucault: " << e.what() << "\n";
        return 2;
    }
    std::cout << (failures == 0 ? "all checks passed\n" : std::to_string(failures) + " check(s) FAILED\n");
    return failures == 0 ? 0 : 1;
}
