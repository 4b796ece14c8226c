// symrep/numeric/integrate.cpp -- see integrate.h.
#include "symrep/numeric/integrate.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include <boost/numeric/odeint.hpp>

#include "symrep/core/error.h"
#include "symrep/core/interrupt.h"
#include "symrep/core/progress.h"

namespace symrep::num {

namespace odeint = boost::numeric::odeint;

const char* stepper_name(stepper_kind k) {
    switch (k) {
        case stepper_kind::rkf78: return "rkf78";
        case stepper_kind::bulirsch_stoer: return "bulirsch_stoer";
        case stepper_kind::dopri5: return "dopri5";
        case stepper_kind::rk4: return "rk4";
    }
    return "?";
}

stepper_kind stepper_from_name(const std::string& name) {
    if (name == "rkf78" || name == "rk78") return stepper_kind::rkf78;
    if (name == "bulirsch_stoer" || name == "bs") return stepper_kind::bulirsch_stoer;
    if (name == "dopri5") return stepper_kind::dopri5;
    if (name == "rk4") return stepper_kind::rk4;
    throw type_error("unknown integrator '" + name + "' (known: rkf78, bulirsch_stoer, dopri5, rk4)");
}

std::vector<double> linspace(double t0, double t1, std::size_t n_points) {
    std::vector<double> t;
    if (n_points == 0) return t;
    if (n_points == 1) return {t1};
    t.reserve(n_points);
    const double h = (t1 - t0) / static_cast<double>(n_points - 1);
    for (std::size_t k = 0; k + 1 < n_points; ++k) t.push_back(t0 + h * static_cast<double>(k));
    t.push_back(t1);
    return t;
}

namespace {

using state_type = std::vector<double>;

void check_arguments(double t0, std::size_t dim, const std::vector<double>& times, const integration_options& o) {
    if (dim == 0) throw type_error("integrate: the state is empty");
    if (times.empty()) throw type_error("integrate: no output times");
    if (!std::isfinite(t0)) throw type_error("integrate: the initial time is not finite");
    for (std::size_t k = 0; k < times.size(); ++k) {
        if (!std::isfinite(times[k])) throw type_error("integrate: output time " + std::to_string(k) + " is not finite");
        if (times[k] < t0)
            throw type_error("integrate: output time " + std::to_string(times[k]) + " lies before the initial time " +
                             std::to_string(t0) + " (only forward integration is supported)");
        if (k > 0 && !(times[k] > times[k - 1]))
            throw type_error("integrate: output times must be strictly increasing (time " + std::to_string(k) + ")");
    }
    if (!(o.abs_tol > 0) || !(o.rel_tol >= 0) || !std::isfinite(o.abs_tol) || !std::isfinite(o.rel_tol))
        throw type_error("integrate: tolerances must be finite, abs_tol > 0 and rel_tol >= 0");
    if (o.max_steps_between_outputs == 0) throw type_error("integrate: max_steps_between_outputs must be positive");
    if (o.stepper == stepper_kind::rk4 && !(o.fixed_step > 0 && std::isfinite(o.fixed_step)))
        throw type_error("integrate: the fixed-step stepper rk4 needs a step (fixed_step > 0)");
}

}  // namespace

integration_result integrate(const rhs_function& f, double t0, const std::vector<double>& y0,
                             const std::vector<double>& output_times, const integration_options& options) {
    const std::size_t dim = y0.size();
    check_arguments(t0, dim, output_times, options);
    for (std::size_t i = 0; i < dim; ++i)
        if (!std::isfinite(y0[i]))
            throw type_error("integrate: initial state component " + std::to_string(i) + " is not finite");

    integration_result res;
    res.stepper = options.stepper;
    res.times = output_times;
    res.states.resize(static_cast<Eigen::Index>(output_times.size()), static_cast<Eigen::Index>(dim));

    // All times handed to odeint: the initial time first.
    std::vector<double> all;
    all.reserve(output_times.size() + 1);
    const bool prepend = output_times.front() != t0;
    if (prepend) all.push_back(t0);
    all.insert(all.end(), output_times.begin(), output_times.end());
    const std::size_t skip = prepend ? 1 : 0;

    std::size_t evaluations = 0;
    const std::size_t max_eval = options.max_rhs_evaluations;
    // progress in time: t - t0 of the span (from the evaluations, every 64th: a
    // bit test per evaluation; trial times behind an earlier report are ignored)
    progress_task task("integrate", all.back() - t0);
    auto system = [&](const state_type& y, state_type& dydt, double t) {
        check_interrupt();
        if ((evaluations & 63) == 0) task.report(t - t0);
        if (++evaluations > max_eval)
            throw error("integrate: more than " + std::to_string(max_eval) +
                        " evaluations of the right-hand side (raise max_rhs_evaluations, or the system is stiff)");
        f(t, y.data(), dydt.data());
    };
    std::size_t observed = 0;
    auto observer = [&](const state_type& y, double t) {
        if (observed >= skip) {
            const auto row = static_cast<Eigen::Index>(observed - skip);
            for (std::size_t i = 0; i < dim; ++i) {
                if (!std::isfinite(y[i]))
                    throw error("integrate: the solution is not finite at t = " + std::to_string(t) +
                                " (component " + std::to_string(i) + ")");
                res.states(row, static_cast<Eigen::Index>(i)) = y[i];
            }
        }
        ++observed;
        task.report(t - t0);
    };

    const double span = all.back() - t0;
    double dt = options.initial_step > 0 ? options.initial_step : (span > 0 ? 1e-3 * span : 1e-3);
    constexpr auto int_max = static_cast<std::size_t>(std::numeric_limits<int>::max());
    const int max_steps = static_cast<int>(std::min(options.max_steps_between_outputs, int_max));
    state_type y = y0;
    const auto start = std::chrono::steady_clock::now();
    try {
        switch (options.stepper) {
            case stepper_kind::rkf78: {
                auto stepper = odeint::make_controlled(options.abs_tol, options.rel_tol,
                                                       odeint::runge_kutta_fehlberg78<state_type>());
                res.steps = odeint::integrate_times(stepper, system, y, all.begin(), all.end(), dt, observer,
                                                    odeint::max_step_checker(max_steps));
                break;
            }
            case stepper_kind::bulirsch_stoer: {
                odeint::bulirsch_stoer<state_type> stepper(options.abs_tol, options.rel_tol);
                res.steps = odeint::integrate_times(stepper, system, y, all.begin(), all.end(), dt, observer,
                                                    odeint::max_step_checker(max_steps));
                break;
            }
            case stepper_kind::dopri5: {
                auto stepper = odeint::make_dense_output(options.abs_tol, options.rel_tol,
                                                         odeint::runge_kutta_dopri5<state_type>());
                res.steps = odeint::integrate_times(stepper, system, y, all.begin(), all.end(), dt, observer,
                                                    odeint::max_step_checker(max_steps));
                break;
            }
            case stepper_kind::rk4: {
                odeint::runge_kutta4<state_type> stepper;
                res.steps = odeint::integrate_times(stepper, system, y, all.begin(), all.end(), options.fixed_step,
                                                    observer, odeint::max_step_checker(max_steps));
                break;
            }
        }
    } catch (const symrep::error&) {
        throw;
    } catch (const std::exception& e) {
        throw error(std::string("integrate (") + stepper_name(options.stepper) + "): " + e.what());
    }
    res.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    res.rhs_evaluations = evaluations;
    if (observed != all.size())
        throw error("integrate: the integrator stopped early (" + std::to_string(observed) + " of " +
                    std::to_string(all.size()) + " output times reached)");
    task.finish();
    return res;
}

symbolic_system::symbolic_system(const std::vector<GiNaC::ex>& rhs, const GiNaC::symbol& t,
                                 const std::vector<GiNaC::ex>& state, const parameter_values& params)
    : dim_(state.size()) {
    if (rhs.size() != state.size())
        throw type_error("ode system: " + std::to_string(rhs.size()) + " right-hand side(s) for " +
                         std::to_string(state.size()) + " state variable(s)");
    if (state.empty()) throw type_error("ode system: no state variables");
    std::vector<GiNaC::ex> inputs;
    inputs.reserve(1 + state.size() + params.size());
    inputs.push_back(t);
    inputs.insert(inputs.end(), state.begin(), state.end());
    for (const auto& [p, v] : params) {
        inputs.push_back(p);
        params_.push_back(p);
        param_values_.push_back(v);
    }
    f_ = compile(rhs, inputs);  // type_error on a symbol without value, repeated symbols, ...
}

void symbolic_system::set_parameter(const GiNaC::ex& p, double value) {
    for (std::size_t i = 0; i < params_.size(); ++i) {
        if (params_[i].is_equal(p)) {
            param_values_[i] = value;
            return;
        }
    }
    throw type_error("ode system: '" + symbol_name(p) + "' is not a parameter of the system");
}

rhs_function symbolic_system::function() const {
    const std::size_t dim = dim_;
    std::vector<double> buffer(1 + dim + param_values_.size());
    std::copy(param_values_.begin(), param_values_.end(), buffer.begin() + static_cast<std::ptrdiff_t>(1 + dim));
    return [f = f_, dim, buffer = std::move(buffer)](double t, const double* y, double* dydt) mutable {
        buffer[0] = t;
        std::copy(y, y + dim, buffer.begin() + 1);
        f.eval(buffer.data(), dydt);
    };
}

}  // namespace symrep::num
