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

namespace {

// a vector expression by components (a 3x1 matrix), the vectors of `with` put in
ex by_components(const ex& e, const vmap& with) {
    const ex comp = vector_symbols(e).empty() ? e : subs_components(e, with);
    if (GiNaC::is_a<GiNaC::matrix>(comp)) return comp;
    const ex k = canonical(comp);
    return k.is_zero() ? vector_literal(0, 0, 0) : k.evalm();
}

// P as six real first-order equations: the state x (y0..y2) and y (y3..y5) of x^ = x + eps y,
// x^' = a + eps b solved from E reduced modulo eps^2, and the initial values.
struct dual_system {
    std::vector<ex> rhs, state;
    std::vector<double> initial;
};

dual_system six_real_equations(const mechanics::cauchy_problem& P, const data_values& dv, const builtin& b) {
    if (!P.is_vector || P.order() != 1)
        throw type_error(b.name + ": a dual problem is verified for a first-order vector problem only");
    dual_system out;
    std::vector<ex> acc;
    for (int i = 0; i < 6; ++i) out.state.push_back(GiNaC::symbol("y" + std::to_string(i)));
    for (int i = 0; i < 6; ++i) acc.push_back(GiNaC::symbol("a" + std::to_string(i)));
    const ex eps = dual::dual_unit();
    const std::vector<ex>& y = out.state;
    vmap with = dv.vectors;
    with[P.unknowns[0]] = vector_literal(y[0] + eps * y[3], y[1] + eps * y[4], y[2] + eps * y[5]);
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
    for (std::size_t i = 0; i < 6; ++i) out.rhs.push_back(GiNaC::expand(sol.op(i).rhs()));
    const dual::dual_parts x0 = dual::parts(P.initial[0]);
    for (const ex& part : {x0.primal, x0.dual})
        for (const ex& x : components(put_values_limit(by_components(part, dv.vectors), dv)))
            out.initial.push_back(to_double(x, b, "the initial value of " + P.name));
    return out;
}

value report(const mechanics::cauchy_problem& P, const num::verify_result& v, double T, const char* what,
             const num::integration_options& opt, double prep, context& c) {
    static const char* axes[] = {"x", "y", "z", "eps x", "eps y", "eps z"};
    c.out() << "verify: max relative difference " << std::setprecision(3) << v.max_relative_difference
            << " (component " << axes[v.component_of_max] << " of " << P.name << ", t = " << std::setprecision(6)
            << v.time_of_max << ") over " << v.n_points << " points in [0, " << T << "]; " << what
            << "the dual problem as six real equations, " << num::stepper_name(opt.stepper) << " ("
            << v.rhs_evaluations << " right-hand sides), setup " << std::setprecision(3) << prep + v.compile_seconds
            << " s\n";
    return value(ex(num::from_double(v.max_relative_difference)));
}

data_values without_time(const mechanics::cauchy_problem& P, const data_values& d) {
    data_values dv = d;
    dv.scalars.erase(P.t);
    return dv;
}

}  // namespace

value verify_dual(const mechanics::cauchy_problem& P, const ex& s, const data_values& d, double T, std::size_t n,
                  const num::integration_options& opt, const builtin& b, context& c) {
    const auto t0 = std::chrono::steady_clock::now();
    const GiNaC::symbol& t = GiNaC::ex_to<GiNaC::symbol>(P.t);
    const data_values dv = without_time(P, d);
    const dual_system sys = six_real_equations(P, dv, b);
    // the closed form's parts, six components
    const dual::dual_parts sp = dual::parts(s);
    std::vector<ex> cf;
    for (const ex& part : {sp.primal, sp.dual})
        for (const ex& x : components(put_values_limit(by_components(part, dv.vectors), dv))) cf.push_back(x);
    const double prep = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const num::verify_result v = num::verify(cf, t, sys.rhs, sys.state, sys.initial, {}, 0.0, T, n, opt);
    return report(P, v, T, "", opt, prep, c);
}

value verify_dual(const mechanics::cauchy_problem& P, const num::sampled_function& s, const data_values& d, double T,
                  std::size_t n, const num::integration_options& opt, const builtin& b, context& c) {
    const auto t0 = std::chrono::steady_clock::now();
    const dual_system sys = six_real_equations(P, without_time(P, d), b);
    num::symbolic_system rhs(sys.rhs, GiNaC::ex_to<GiNaC::symbol>(P.t), sys.state, {});
    const double prep = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const num::verify_result v = num::verify(s, 6, rhs.function(), sys.initial, 0.0, T, n, opt);
    return report(P, v, T, "Magnus on SE(3) against ", opt, prep, c);
}

}  // namespace symrep::lang
