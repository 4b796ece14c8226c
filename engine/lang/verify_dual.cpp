// symrep/lang/verify_dual.cpp -- verify() for a dual problem (verify_dual.h).
#include "symrep/lang/verify_dual.h"

#include <chrono>
#include <iomanip>

#include "symrep/core/error.h"
#include "symrep/dual/dual.h"
#include "symrep/numeric/reference.h"
#include "symrep/numeric/verify.h"
#include "symrep/vector/vector.h"

namespace symrep::lang {

using GiNaC::ex;

value verify_dual(const mechanics::cauchy_problem& P, const ex& s, const data_values& d, double T, std::size_t n,
                  const num::integration_options& opt, const builtin& b, context& c) {
    if (!P.is_vector || P.order() != 1)
        throw type_error(b.name + ": a dual problem is verified for a first-order vector problem only");
    const auto t0 = std::chrono::steady_clock::now();
    const GiNaC::symbol& t = GiNaC::ex_to<GiNaC::symbol>(P.t);
    data_values dv = d;
    dv.scalars.erase(P.t);
    // a vector expression by components (a 3x1 matrix), the vectors of `with` put in
    const auto by_components = [](const ex& e, const vmap& with) {
        const ex comp = vector_symbols(e).empty() ? e : subs_components(e, with);
        if (GiNaC::is_a<GiNaC::matrix>(comp)) return comp;
        const ex k = canonical(comp);
        return k.is_zero() ? vector_literal(0, 0, 0) : k.evalm();
    };
    // the closed form's parts, six components
    const dual::dual_parts sp = dual::parts(s);
    std::vector<ex> cf;
    for (const ex& part : {sp.primal, sp.dual})
        for (const ex& x : components(put_values_limit(by_components(part, dv.vectors), dv))) cf.push_back(x);
    // the state x (y0..y2) and y (y3..y5); x^' = a + eps b solved from E reduced modulo eps^2
    std::vector<ex> state, acc;
    for (int i = 0; i < 6; ++i) state.push_back(GiNaC::symbol("y" + std::to_string(i)));
    for (int i = 0; i < 6; ++i) acc.push_back(GiNaC::symbol("a" + std::to_string(i)));
    const ex eps = dual::dual_unit();
    vmap with = dv.vectors;
    with[P.unknowns[0]] = vector_literal(state[0] + eps * state[3], state[1] + eps * state[4], state[2] + eps * state[5]);
    with[P.unknowns[1]] = vector_literal(acc[0] + eps * acc[3], acc[1] + eps * acc[4], acc[2] + eps * acc[5]);
    const dual::dual_parts E = dual::parts(put_values(by_components(P.expression, with), dv));
    GiNaC::lst eqs, unk;
    for (const ex& part : {E.primal, E.dual})
        for (const ex& x : components(part)) eqs.append(GiNaC::expand(x) == 0);
    for (const ex& a : acc) unk.append(a);
    const ex sol = GiNaC::lsolve(eqs, unk);
    if (sol.nops() != 6)
        throw domain_error(b.name + ": the dual problem cannot be solved for " + P.unknown_name(1) +
                           " at these values (its leading coefficient is singular)");
    std::vector<ex> rhs;
    for (std::size_t i = 0; i < 6; ++i) rhs.push_back(GiNaC::expand(sol.op(i).rhs()));
    std::vector<double> initial;
    const dual::dual_parts x0 = dual::parts(P.initial[0]);
    for (const ex& part : {x0.primal, x0.dual})
        for (const ex& x : components(put_values_limit(by_components(part, dv.vectors), dv)))
            initial.push_back(to_double(x, b, "the initial value of " + P.name));
    const double prep = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const num::verify_result v = num::verify(cf, t, rhs, state, initial, {}, 0.0, T, n, opt);
    static const char* axes[] = {"x", "y", "z", "eps x", "eps y", "eps z"};
    c.out() << "verify: max relative difference " << std::setprecision(3) << v.max_relative_difference
            << " (component " << axes[v.component_of_max] << " of " << P.name << ", t = " << std::setprecision(6)
            << v.time_of_max << ") over " << v.n_points << " points in [0, " << T << "]; the dual problem as six "
            << "real equations, " << num::stepper_name(opt.stepper) << " (" << v.rhs_evaluations
            << " right-hand sides), setup " << std::setprecision(3) << prep + v.compile_seconds << " s\n";
    return value(ex(num::from_double(v.max_relative_difference)));
}

}  // namespace symrep::lang
