// symrep/numeric/verify.cpp -- see verify.h.
#include "symrep/numeric/verify.h"

#include <chrono>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "symrep/core/error.h"
#include "symrep/core/progress.h"

namespace symrep::num {

namespace {
double seconds_since(std::chrono::steady_clock::time_point s) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - s).count();
}

/// The comparison, for any evaluator of the closed form: eval_all(times, n,
/// values) fills n rows of m values.
template <class EvalAll>
verify_result compare(std::size_t n_inputs, std::size_t m, EvalAll eval_all, const rhs_function& rhs,
                      const std::vector<double>& initial_state, double t0, double t1, std::size_t n_points,
                      const integration_options& options) {
    if (n_inputs != 1)
        throw type_error("verify: the closed form must be a function of t alone (it takes " +
                         std::to_string(n_inputs) + " inputs)");
    if (m == 0) throw type_error("verify: the closed form has no components");
    if (m > initial_state.size())
        throw type_error("verify: the closed form has " + std::to_string(m) + " components but the state only " +
                         std::to_string(initial_state.size()));
    if (n_points < 2) throw type_error("verify: at least 2 sample points are needed");
    if (!std::isfinite(t0) || !std::isfinite(t1) || !(t1 > t0))
        throw type_error("verify: the time span must be finite with t1 > t0");

    verify_result res;
    res.n_points = n_points;
    res.times = linspace(t0, t1, n_points);

    // progress: n_points units for the closed form, n_points for the integration
    progress_task task("verify", 2.0 * double(n_points));
    task.nest(0, double(n_points));
    auto s = std::chrono::steady_clock::now();
    res.closed_form.resize(static_cast<Eigen::Index>(n_points), static_cast<Eigen::Index>(m));
    // Row-major block of n_points x m values, then into the (column-major) matrix.
    std::vector<double> values(n_points * m);
    eval_all(res, values.data());
    for (std::size_t k = 0; k < n_points; ++k)
        for (std::size_t i = 0; i < m; ++i)
            res.closed_form(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(i)) = values[k * m + i];
    res.closed_form_seconds = seconds_since(s);
    task.report(double(n_points));

    task.nest(double(n_points), 2.0 * double(n_points));
    integration_result ir = integrate(rhs, t0, initial_state, res.times, options);
    res.integration_seconds = ir.wall_seconds;
    res.rhs_evaluations = ir.rhs_evaluations;
    res.steps = ir.steps;
    res.integrated = std::move(ir.states);

    double worst = -1.0;
    for (std::size_t i = 0; i < m; ++i) {
        const auto c = static_cast<Eigen::Index>(i);
        double scale = 0.0, max_diff = 0.0;
        std::size_t k_max = 0;
        bool nan = false;
        for (std::size_t k = 0; k < n_points; ++k) {
            const auto r = static_cast<Eigen::Index>(k);
            const double d = std::fabs(res.closed_form(r, c) - res.integrated(r, c));
            if (std::isnan(d)) {
                if (!nan) k_max = k;
                nan = true;
            } else if (d > max_diff && !nan) {
                max_diff = d;
                k_max = k;
            }
            scale = std::max(scale, std::fabs(res.integrated(r, c)));
        }
        double rel = scale > 0 ? max_diff / scale : max_diff;
        if (nan) {
            // A closed form that is NaN or inf somewhere is as wrong as it gets.
            rel = std::numeric_limits<double>::infinity();
            max_diff = rel;
        }
        res.max_absolute_difference = std::max(res.max_absolute_difference, max_diff);
        if (rel > worst) {
            worst = rel;
            res.max_relative_difference = rel;
            res.component_of_max = i;
            res.time_of_max = res.times[k_max];
        }
    }
    task.finish();
    return res;
}

}  // namespace

verify_result verify(const compiled_function& closed_form, const rhs_function& rhs,
                     const std::vector<double>& initial_state, double t0, double t1, std::size_t n_points,
                     const integration_options& options) {
    auto all = [&](verify_result& res, double* values) {
        closed_form.eval_many(res.times.data(), values, res.times.size());
    };
    return compare(closed_form.n_inputs(), closed_form.n_outputs(), all, rhs, initial_state, t0, t1, n_points,
                   options);
}

verify_result verify(const sampled_function& closed_form, std::size_t m, const rhs_function& rhs,
                     const std::vector<double>& initial_state, double t0, double t1, std::size_t n_points,
                     const integration_options& options) {
    auto all = [&](verify_result& res, double* values) { closed_form(res.times, values); };
    return compare(1, m, all, rhs, initial_state, t0, t1, n_points, options);
}

verify_result verify(const stable_function& closed_form, const rhs_function& rhs,
                     const std::vector<double>& initial_state, double t0, double t1, std::size_t n_points,
                     const integration_options& options) {
    auto all = [&](verify_result& res, double* values) {
        const std::size_t m = closed_form.n_outputs();
        for (std::size_t k = 0; k < res.times.size(); ++k) {
            ++res.closed_form_tiers[static_cast<std::size_t>(closed_form.eval(&res.times[k], values + k * m))];
            report_progress("closed form", double(k + 1), double(res.times.size()));
        }
    };
    return compare(closed_form.n_inputs(), closed_form.n_outputs(), all, rhs, initial_state, t0, t1, n_points,
                   options);
}

verify_result verify(const std::vector<GiNaC::ex>& closed_form, const GiNaC::symbol& t,
                     const std::vector<GiNaC::ex>& ode_rhs, const std::vector<GiNaC::ex>& state,
                     const std::vector<double>& initial_state, const parameter_values& params, double t0,
                     double t1, std::size_t n_points, const integration_options& options) {
    auto s = std::chrono::steady_clock::now();
    // The closed form is a function of t; parameters are substituted as exact
    // numbers so that the compiler folds every parameter-only subexpression.
    GiNaC::exmap values;
    for (const auto& [p, v] : params) values[p] = GiNaC::numeric(v);
    std::vector<GiNaC::ex> cf;
    cf.reserve(closed_form.size());
    for (const auto& e : closed_form) cf.push_back(e.subs(values));
    const stable_function f(cf, {t});
    symbolic_system sys(ode_rhs, t, state, params);
    const double compile_seconds = seconds_since(s);

    std::vector<double> y0 = initial_state;
    if (y0.empty()) {
        if (cf.size() != state.size())
            throw type_error("verify: no initial state given and the closed form has " + std::to_string(cf.size()) +
                             " components for " + std::to_string(state.size()) + " state variables");
        y0.resize(cf.size());
        f.eval(&t0, y0.data());
    }
    if (y0.size() != state.size())
        throw type_error("verify: initial state has " + std::to_string(y0.size()) + " components for " +
                         std::to_string(state.size()) + " state variables");
    verify_result res = verify(f, sys.function(), y0, t0, t1, n_points, options);
    res.compile_seconds = compile_seconds;
    return res;
}

}  // namespace symrep::num
