// symrep_work_precision: speed against accuracy for the scenes of thesis Ch. VI
// (docs/performance.md, "Work-precision"). Every closed form is derived by
// symrep itself (solve(ode(...)) in a lang::session); the numbers go in as the
// exact binary values of the doubles below, so the closed form, the integrators
// and the reference all see the same problem.
//
//   wp_scenes.csv       per scene: error and cost of the closed form (each
//                       evaluator of `closed_form_evaluators`) and of the
//                       Boost.Odeint steppers (rk4 over a range of fixed steps;
//                       dopri5, rkf78, bulirsch_stoer at tolerances 1e-3 .. 1e-14)
//   wp_derivation.csv   time for symrep to derive each closed form
//   wp_omega.csv        error at a fixed time against |w| (1e-12 .. 1e3) for
//                       gravity in a rotating frame: where each method breaks
//   wp_long_time.csv    error against t for the Foucault pendulum over 30 days
//
// Error: the reference is num::reference_eval, the closed form at the same
// binary inputs evaluated by CLN (60 digits; 100 in the |w| sweep, whose
// cancellations reach (|w| t)^4). A trajectory's error is measured like
// num::verify: per component i, max_k |y_i(t_k) - ref_i(t_k)| divided by
// max_k |ref_i(t_k)| (the component's largest magnitude over the trajectory),
// then the max over i; positions only (the integrators' velocities are not
// compared). Cost: the median wall time of repeated runs (one trajectory: all
// output times) and, for the integrators, the evaluations of the right-hand side.
//
// usage: symrep_work_precision [--quick] [--out DIR] [--part work|derivation|omega|time]... [--scene ID]
// (--scene: one scene of the work part; bench/work_precision.sh runs everything
// and draws the charts). Not a test; not run by CI.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "core/progress.h"
#include "lang/interpreter.h"
#include "lang/values.h"
#include "numeric/evaluator.h"
#include "numeric/integrate.h"
#include "numeric/reference.h"
#include "vector/vector.h"

#include "numeric/spectral_evaluator.h"
#if __has_include("numeric/stable_evaluator.h")
#include "numeric/stable_evaluator.h"
#define SYMREP_WP_HAVE_STABLE 1
#endif

using namespace symrep;
using GiNaC::ex;
using clock_type = std::chrono::steady_clock;

namespace {

double seconds_since(clock_type::time_point start) {
    return std::chrono::duration<double>(clock_type::now() - start).count();
}

// ------------------------------------------------------------ closed-form evaluators
// The symrep curve is drawn for every evaluator listed here. An adapter turns
// (outputs, input t) into a function that evaluates n times at once (row k of
// `out` = the outputs at t[k]) and a note on how it evaluated (for the CSV).
struct evaluation {
    std::function<void(const double* t, double* out, std::size_t n)> run;
    std::function<std::string()> note;
};

struct closed_form_evaluator {
    const char* method;  ///< the method name in the CSV files and the charts' legends
    evaluation (*make)(const std::vector<ex>& outputs, const ex& t);
};

evaluation make_compiled(const std::vector<ex>& outputs, const ex& t) {
    auto f = std::make_shared<const num::compiled_function>(num::compile(outputs, {t}));
    return {[f](const double* in, double* out, std::size_t n) { f->eval_many(in, out, n); },
            [f] { return std::to_string(f->n_instructions()) + " instructions"; }};
}

evaluation make_spectral(const std::vector<ex>& outputs, const ex& t) {
    auto f = std::make_shared<const num::spectral_function>(outputs, t);
    return {[f](const double* in, double* out, std::size_t n) { f->eval_many(in, out, n); },
            [f] { return std::to_string(f->n_exponents()) + " exponents / " + std::to_string(f->n_levels()) + " levels"; }};
}

#ifdef SYMREP_WP_HAVE_STABLE
evaluation make_stable(const std::vector<ex>& outputs, const ex& t) {
    auto f = std::make_shared<const num::stable_function>(outputs, std::vector<ex>{t});
    auto tiers = std::make_shared<std::array<std::size_t, 3>>();  // points per tier, last call
    const std::size_t m = f->n_outputs();
    return {[f, m, tiers](const double* in, double* out, std::size_t n) {
                tiers->fill(0);
                for (std::size_t k = 0; k < n; ++k) ++(*tiers)[static_cast<std::size_t>(f->eval(in + k, out + k * m))];
            },
            [tiers] {
                const auto& c = *tiers;
                return "points: " + std::to_string(c[0]) + " binary64 / " + std::to_string(c[1]) + " binary128 / " +
                       std::to_string(c[2]) + " multiprecision";
            }};
}
#endif

const closed_form_evaluator closed_form_evaluators[] = {
    {"symrep compiled", make_compiled},
    {"symrep spectral", make_spectral},
#ifdef SYMREP_WP_HAVE_STABLE
    {"symrep stable", make_stable},
#endif
};

// ------------------------------------------------------------ scenes
struct datum {
    const char* name;
    std::vector<double> x;  ///< 3 values for a vector, 1 for a scalar
};

struct problem_text {
    const char* id;            ///< as in bench/bench_mechanics.cpp and the SymPy script
    const char* declarations;
    const char* ode;
};

const problem_text foucault_problem{"VI.1.68_foucault", "vector w, r0, v0; positive w0",
                                    "ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0)"};
const problem_text reduced_problem{"VI.2.93_reduced_foucault", "vector w, r0, v0; positive w0",
                                   "ode(r'' + 2*w x r' + w0^2*r = 0, r(0) = r0, r'(0) = v0)"};
const problem_text charge_problem{"VI.1.58_charge_position", "vector E, B, v0, r0; positive m",
                                  "ode(m*r'' = q*(r' x B + E), r(0) = r0, r'(0) = v0)"};
const problem_text coriolis_problem{"VI.1.50_coriolis", "vector w, g, r0, v0",
                                    "ode(r'' + 2*w x r' = g, r(0) = r0, r'(0) = v0)"};
const problem_text centrifugal_problem{"VI.1.56_centrifugal", "vector w, g, r0, v0",
                                       "ode(r'' + 2*w x r' + w x (w x r) = g, r(0) = r0, r'(0) = v0)"};
// Derived for the table only (first-order problems, no scene of their own).
const problem_text velocity_problem{"VI.1.41_velocity", "vector w, g, v0", "ode(v' + 2*w x v = g, v(0) = v0)"};
const problem_text charge_velocity_problem{"VI.1.58_charge_velocity", "vector E, B, v0; positive m",
                                           "ode(m*v' = q*(v x B + E), v(0) = v0)"};

constexpr double earth_rate = 7.2921e-5;  // rad/s
const double paris = 48.85 * std::numbers::pi / 180;
const double lab = std::numbers::pi / 4;
const double proton_q = 1.602176634e-19, proton_m = 1.67262192e-27;
const double gyration_period = 2 * std::numbers::pi * proton_m / proton_q;  // B = 1 T

std::vector<datum> paris_data() {
    return {{"w", {earth_rate * std::cos(paris), 0, earth_rate * std::sin(paris)}},
            {"w0", {std::sqrt(9.81 / 67)}},
            {"r0", {3, 0, 0}},
            {"v0", {0, 0, 0}}};
}
std::vector<datum> lab_data(double omega) {
    return {{"w", {omega * std::cos(lab), 0, omega * std::sin(lab)}},
            {"g", {0, 0, -9.81}},
            {"r0", {0, 0, 100}},
            {"v0", {10, 5, 20}}};
}
std::vector<datum> proton_data() {
    return {{"q", {proton_q}},
            {"m", {proton_m}},
            {"B", {0, 0, 1}},
            {"E", {1000 * std::sin(std::numbers::pi / 3), 0, 1000 * std::cos(std::numbers::pi / 3)}},
            {"v0", {1e5, 0, 0}},
            {"r0", {0, 0, 0}}};
}

struct scene {
    const char* id;
    const char* title;
    const problem_text* problem;
    std::vector<datum> data;
    double span;    ///< trajectory [0, span]
    double period;  ///< the fastest natural period (rk4 steps are fractions of it)
    /// Long scenes: the right-hand-side budget times this, every tol_stride-th tolerance only.
    double budget_factor = 1;
    int tol_stride = 1;
};

std::vector<scene> scenes() {
    const double pendulum = 2 * std::numbers::pi / std::sqrt(9.81 / 67);
    return {
        {"foucault_1d", "Foucault pendulum, Paris, 1 day", &foucault_problem, paris_data(), 86400, pendulum},
        {"foucault_30d", "Foucault pendulum, Paris, 30 days", &foucault_problem, paris_data(), 30 * 86400.0,
         pendulum, 6, 2},
        {"reduced_foucault_1d", "reduced Foucault r'' + 2w x r' + w0^2 r = 0, 1 day", &reduced_problem, paris_data(),
         86400, pendulum},
        {"charge_1000", "proton in E, B at 60 deg, 1000 gyrations", &charge_problem, proton_data(),
         1000 * gyration_period, gyration_period},
        {"coriolis_60s", "gravity, rotating frame (Coriolis only), 60 s", &coriolis_problem, lab_data(earth_rate), 60,
         60},
        {"centrifugal_60s", "gravity, rotating frame (Coriolis + centrifugal), 60 s", &centrifugal_problem,
         lab_data(earth_rate), 60, 60},
    };
}

// ------------------------------------------------------------ a problem with numbers in
struct derived {
    std::unique_ptr<lang::session> session;
    mechanics::cauchy_problem problem;
    ex solution;
};

derived derive(const problem_text& p) {
    derived d;
    static std::ostream discard(nullptr);
    d.session = std::make_unique<lang::session>(discard, discard);
    d.session->evaluate(p.declarations);
    d.problem = d.session->evaluate(p.ode).as_problem();
    d.solution = d.session->evaluate(std::string("solve(") + p.ode + ")").as_ex();
    return d;
}

struct instance {
    std::vector<ex> closed_form;  ///< components, in t only
    num::rhs_function rhs;
    std::vector<double> initial;
};

instance put_in(derived& d, const std::vector<datum>& data) {
    lang::data_values values;
    for (const datum& v : data) {
        const ex s = d.session->symbol(v.name);
        if (v.x.size() == 3)
            values.vectors[s] = vector_literal(num::exact_rational(v.x[0]), num::exact_rational(v.x[1]),
                                               num::exact_rational(v.x[2]));
        else
            values.scalars[s] = num::exact_rational(v.x[0]);
    }
    const lang::builtin& verify = *d.session->builtins().find("verify");
    instance in;
    in.closed_form = lang::components(lang::put_values_limit(d.solution, values));
    const lang::first_order_system sys = lang::first_order(d.problem, values, verify);
    in.rhs = num::symbolic_system(sys.rhs, GiNaC::ex_to<GiNaC::symbol>(d.problem.t), sys.state).function();
    in.initial = sys.initial;
    return in;
}

// ------------------------------------------------------------ reference and error
struct reference {
    std::vector<double> times;
    std::vector<std::vector<long double>> value;  ///< value[k][i] = component i at times[k]
    std::vector<long double> scale;               ///< max_k |value[k][i]|
};

reference reference_at(const instance& in, const ex& t, const std::vector<double>& times, int digits) {
    reference r;
    r.times = times;
    r.scale.assign(in.closed_form.size(), 0.0L);
    for (double tk : times) {
        r.value.push_back(num::reference_eval(in.closed_form, {t}, {tk}, digits));
        for (std::size_t i = 0; i < r.scale.size(); ++i)
            r.scale[i] = std::max(r.scale[i], std::fabs(r.value.back()[i]));
    }
    return r;
}

/// |y_i(t_k) - ref_i(t_k)| / scale_i; row k of y starts at y + k * stride.
double component_error(const reference& r, std::size_t k, std::size_t i, const double* y, std::size_t stride) {
    const long double d = std::fabs(static_cast<long double>(y[k * stride + i]) - r.value[k][i]);
    if (!std::isfinite(static_cast<double>(d))) return INFINITY;
    return static_cast<double>(r.scale[i] > 0 ? d / r.scale[i] : d);
}

/// The trajectory error defined at the top of this file.
double trajectory_error(const reference& r, const double* y, std::size_t stride) {
    double e = 0;
    for (std::size_t k = 0; k < r.times.size(); ++k)
        for (std::size_t i = 0; i < r.scale.size(); ++i) e = std::max(e, component_error(r, k, i, y, stride));
    return e;
}

/// n output times in (0, span], the last one span: one in each of n equal
/// intervals at a random place (fixed seed), so that no sampling is in step
/// with a period of the motion (200 equal steps over 1000 gyrations would see
/// every gyration at the same phase).
std::vector<double> output_times(double span, std::size_t n) {
    std::mt19937_64 rng(20240605);
    std::uniform_real_distribution<double> u(0.05, 0.95);
    std::vector<double> t;
    for (std::size_t k = 0; k + 1 < n; ++k)
        t.push_back(span * (static_cast<double>(k) + u(rng)) / static_cast<double>(n));
    t.push_back(span);
    return t;
}

// ------------------------------------------------------------ timing and runs
struct settings {
    bool quick = false;
    std::string out = ".";
    std::string only;
    /// Repeat a run until this much time is spent (at least 3 runs, at most max_repeats), take the median.
    double time_per_point = 1.0;
    int max_repeats = 15;
    /// An integration is stopped after this many right-hand sides (recorded as over_budget; the
    /// tighter tolerances of that stepper are then skipped).
    std::size_t rhs_budget = 20'000'000;
};

double thread_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct timing {
    double wall = NAN, cpu = NAN;  ///< medians over the repeats, seconds
};

double median(std::vector<double> x) {
    std::sort(x.begin(), x.end());
    const std::size_t n = x.size();
    return n % 2 ? x[n / 2] : (x[n / 2 - 1] + x[n / 2]) / 2;
}

/// Wall and CPU time of run(), repeated as `s` says (medians).
template <class Run>
timing median_time(const settings& s, Run&& run) {
    std::vector<double> wall, cpu;
    double total = 0;
    while (wall.size() < static_cast<std::size_t>(s.max_repeats) && (wall.size() < 3 || total < s.time_per_point)) {
        const auto w0 = clock_type::now();
        const double c0 = thread_cpu_seconds();
        run();
        cpu.push_back(thread_cpu_seconds() - c0);
        wall.push_back(seconds_since(w0));
        total += wall.back();
        if (wall.size() == 1 && wall[0] > s.time_per_point / 2) break;  // long runs once
    }
    return {median(wall), median(cpu)};
}

struct measurement {
    std::string method, parameter, status = "ok";
    double error = NAN, setup_seconds = NAN;
    timing cost;
    std::size_t rhs = 0, steps = 0;
};

measurement run_closed_form(const settings& s, const closed_form_evaluator& e, const instance& in, const ex& t,
                            const reference& r) {
    measurement m;
    m.method = e.method;
    const auto start = clock_type::now();
    const evaluation f = e.make(in.closed_form, t);
    m.setup_seconds = seconds_since(start);
    const std::size_t n = r.times.size(), dim = in.closed_form.size();
    std::vector<double> y(n * dim);
    m.cost = median_time(s, [&] { f.run(r.times.data(), y.data(), n); });
    m.parameter = f.note();
    m.error = trajectory_error(r, y.data(), dim);
    return m;
}

/// The states of an integration, row k = state at times[k], as one row-major array.
std::vector<double> row_major(const Eigen::MatrixXd& m) {
    std::vector<double> y(static_cast<std::size_t>(m.size()));
    using row_major_matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    Eigen::Map<row_major_matrix>(y.data(), m.rows(), m.cols()) = m;
    return y;
}

std::string number(double x) {
    std::ostringstream os;
    os << x;
    return os.str();
}

measurement run_integrator(const settings& s, const instance& in, const reference& r, num::integration_options o,
                           std::size_t budget) {
    measurement m;
    m.method = num::stepper_name(o.stepper);
    m.parameter = number(o.stepper == num::stepper_kind::rk4 ? o.fixed_step : o.rel_tol);
    o.max_rhs_evaluations = budget;
    o.max_steps_between_outputs = budget;
    num::integration_result res;
    try {
        m.cost = median_time(s, [&] { res = num::integrate(in.rhs, 0.0, in.initial, r.times, o); });
    } catch (const symrep::error& e) {
        const std::string what = e.what();
        m.status = what.find("evaluations of the right-hand side") != std::string::npos ? "over_budget" : "failed";
        return m;
    }
    m.rhs = res.rhs_evaluations;
    m.steps = res.steps;
    m.error = trajectory_error(r, row_major(res.states).data(), static_cast<std::size_t>(res.states.cols()));
    return m;
}

// ------------------------------------------------------------ CSV
struct csv {
    std::ofstream f;
    explicit csv(const std::string& path, const char* header) : f(path) {
        if (!f) throw std::runtime_error("cannot write " + path);
        f << header << "\n";
    }
};

std::string scientific(double x) {
    if (std::isnan(x)) return "";
    char b[32];
    std::snprintf(b, sizeof b, "%.4g", x);
    return b;
}

// ------------------------------------------------------------ the four parts
const num::stepper_kind adaptive[] = {num::stepper_kind::dopri5, num::stepper_kind::rkf78,
                                      num::stepper_kind::bulirsch_stoer};

void work_precision(const settings& s) {
    csv out(s.out + "/wp_scenes.csv",
            "scene,method,parameter,error,seconds,cpu_seconds,setup_seconds,rhs_evaluations,steps,status");
    const std::size_t n_out = 200;
    for (const scene& sc : scenes()) {
        if (!s.only.empty() && s.only != sc.id) continue;
        std::cerr << sc.id << " (" << sc.title << "): deriving, reference at " << n_out << " times ...\n";
        derived d = derive(*sc.problem);
        const instance in = put_in(d, sc.data);
        const reference r = reference_at(in, d.problem.t, output_times(sc.span, n_out), 60);
        std::vector<measurement> rows;
        for (const closed_form_evaluator& e : closed_form_evaluators)
            rows.push_back(run_closed_form(s, e, in, d.problem.t, r));
        const auto budget = static_cast<std::size_t>(sc.budget_factor * static_cast<double>(s.rhs_budget));
        const int stride = (s.quick ? 2 : 1) * sc.tol_stride;
        // rk4: 2^k steps per natural period while the budget allows
        for (int k = s.quick ? 3 : 2; k <= 14; k += stride) {
            num::integration_options o;
            o.stepper = num::stepper_kind::rk4;
            o.fixed_step = sc.period / std::ldexp(1.0, k);
            if (4 * (sc.span / o.fixed_step + n_out) > static_cast<double>(budget)) break;
            rows.push_back(run_integrator(s, in, r, o, budget));
        }
        for (num::stepper_kind k : adaptive) {
            for (int p = 3; p <= 14; p += stride) {
                num::integration_options o;
                o.stepper = k;
                o.abs_tol = o.rel_tol = std::pow(10.0, -p);
                rows.push_back(run_integrator(s, in, r, o, budget));
                if (rows.back().status != "ok") break;  // tighter tolerances cost more
            }
        }
        for (const measurement& m : rows) {
            out.f << sc.id << "," << m.method << "," << m.parameter << "," << scientific(m.error)
                  << "," << scientific(m.cost.wall) << "," << scientific(m.cost.cpu) << ","
                  << scientific(m.setup_seconds) << "," << m.rhs << ","
                  << m.steps << "," << m.status << "\n";
            std::cerr << "  " << m.method << " " << m.parameter << ": error " << scientific(m.error) << ", "
                      << scientific(m.cost.wall) << " s, " << m.rhs << " rhs (" << m.status << ")\n";
        }
        out.f.flush();
    }
}

void derivation(const settings& s) {
    csv out(s.out + "/wp_derivation.csv", "problem,tool,seconds,cpu_seconds,status");
    const problem_text* problems[] = {&velocity_problem,        &coriolis_problem,        &centrifugal_problem,
                                      &charge_velocity_problem, &charge_problem,          &foucault_problem,
                                      &reduced_problem};
    for (const problem_text* p : problems) {
        std::ostringstream o, e;
        lang::session session(o, e);
        session.evaluate(p->declarations);
        const std::string statement = std::string("solve(") + p->ode + ")";
        const timing t = median_time(s, [&] { session.evaluate(statement); });
        out.f << p->id << ",symrep," << scientific(t.wall) << "," << scientific(t.cpu) << ",ok\n";
        std::cerr << "derive " << p->id << ": " << scientific(t.wall) << " s\n";
    }
}

/// Error at one time against |w|: per component |y_i - ref_i| / |ref_i|, max over i.
void omega_sweep(const settings& s) {
    csv out(s.out + "/wp_omega.csv", "scene,omega,omega_t,method,error");
    std::vector<std::pair<std::string, std::string>> lines;  // (method, row), written grouped by method
    const double T = 10;
    const int per_decade = s.quick ? 2 : 4;
    progress_task task("omega sweep", 2.0 * (15 * per_decade + 1));
    double done = 0;
    for (const problem_text* p : {&coriolis_problem, &centrifugal_problem}) {
        derived d = derive(*p);
        const char* id = p == &coriolis_problem ? "coriolis" : "centrifugal";
        for (int j = -12 * per_decade; j <= 3 * per_decade; ++j) {
            const double omega = std::pow(10.0, double(j) / per_decade);
            const instance in = put_in(d, lab_data(omega));
            const reference r = reference_at(in, d.problem.t, {T}, 100);
            auto row = [&](const std::string& method, const double* y) {
                double e = 0;
                for (std::size_t i = 0; i < 3; ++i) {
                    const long double ref = std::fabs(r.value[0][i]);
                    const long double diff = std::fabs(static_cast<long double>(y[i]) - r.value[0][i]);
                    e = std::max(e, std::isfinite(y[i]) ? static_cast<double>(diff / ref) : INFINITY);
                }
                lines.emplace_back(method, std::string(id) + "," + scientific(omega) + "," + scientific(omega * T) +
                                               "," + method + "," + scientific(e) + "\n");
            };
            for (const closed_form_evaluator& e : closed_form_evaluators) {
                double y[3];
                e.make(in.closed_form, d.problem.t).run(&T, y, 1);
                row(e.method, y);
            }
            for (num::stepper_kind k : {num::stepper_kind::rk4, num::stepper_kind::dopri5, num::stepper_kind::rkf78,
                                        num::stepper_kind::bulirsch_stoer}) {
                num::integration_options o;
                o.stepper = k;
                o.fixed_step = 1e-3;
                o.abs_tol = o.rel_tol = 1e-12;
                o.max_rhs_evaluations = s.rhs_budget;
                try {
                    const num::integration_result res = num::integrate(in.rhs, 0.0, in.initial, {T}, o);
                    row(num::stepper_name(k), row_major(res.states).data());
                } catch (const symrep::error&) {
                    const double inf[3] = {INFINITY, INFINITY, INFINITY};
                    row(num::stepper_name(k), inf);
                }
            }
            task.report(++done);
        }
        std::stable_sort(lines.begin(), lines.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        for (const auto& l : lines) out.f << l.second;
        lines.clear();
        std::cerr << "omega sweep " << id << " done\n";
    }
}

/// Error against t over 30 days at Paris (3 days with --quick; log-spaced times); error(t) =
/// max_i |y_i(t) - ref_i(t)| / max over all samples and components of |ref|.
void time_sweep(const settings& s) {
    csv out(s.out + "/wp_long_time.csv", "scene,method,parameter,t,error");
    derived d = derive(foucault_problem);
    const instance in = put_in(d, paris_data());
    const double span = (s.quick ? 3 : 30) * 86400.0;
    const int per_decade = s.quick ? 5 : 20;
    std::vector<double> times;
    for (int j = 0; std::pow(10.0, double(j) / per_decade) < span; ++j)
        times.push_back(std::pow(10.0, double(j) / per_decade));
    times.push_back(span);
    const reference r = reference_at(in, d.problem.t, times, 60);
    const long double amplitude = *std::max_element(r.scale.begin(), r.scale.end());
    const std::size_t n = times.size(), dim = in.closed_form.size();
    auto rows = [&](const std::string& method, const std::string& parameter, const double* y, std::size_t stride) {
        for (std::size_t k = 0; k < n; ++k) {
            double e = 0;
            for (std::size_t i = 0; i < dim; ++i)
                e = std::max(e, static_cast<double>(std::fabs(y[k * stride + i] - r.value[k][i]) / amplitude));
            out.f << (s.quick ? "foucault_3d," : "foucault_30d,") << method << "," << parameter << ","
                  << scientific(times[k]) << ","
                  << scientific(e) << "\n";
        }
    };
    for (const closed_form_evaluator& e : closed_form_evaluators) {
        std::vector<double> y(n * dim);
        e.make(in.closed_form, d.problem.t).run(times.data(), y.data(), n);
        rows(e.method, "-", y.data(), dim);
    }
    struct choice {
        num::stepper_kind k;
        double tol_or_step;
    };
    const choice choices[] = {{num::stepper_kind::rk4, 0.5},       {num::stepper_kind::dopri5, 1e-7},
                              {num::stepper_kind::rkf78, 1e-10},   {num::stepper_kind::rkf78, 1e-13},
                              {num::stepper_kind::bulirsch_stoer, 1e-10}, {num::stepper_kind::bulirsch_stoer, 1e-13}};
    progress_task task("time sweep", double(std::size(choices)));  // each integration its part
    double done = 0;
    for (const choice& c : choices) {
        task.report(done++);
        if (s.quick && c.tol_or_step < 1e-12) continue;
        num::integration_options o;
        o.stepper = c.k;
        o.fixed_step = c.tol_or_step;
        o.abs_tol = o.rel_tol = c.tol_or_step;
        o.max_rhs_evaluations = o.max_steps_between_outputs = s.quick ? 20'000'000 : 200'000'000;
        try {
            const num::integration_result res = num::integrate(in.rhs, 0.0, in.initial, times, o);
            rows(num::stepper_name(c.k), number(c.tol_or_step), row_major(res.states).data(),
                 static_cast<std::size_t>(res.states.cols()));
            std::cerr << "time sweep " << num::stepper_name(c.k) << " " << c.tol_or_step << ": " << res.rhs_evaluations
                      << " rhs, " << scientific(res.wall_seconds) << " s\n";
        } catch (const symrep::error& e) {
            std::cerr << "time sweep " << num::stepper_name(c.k) << " " << c.tol_or_step << ": " << e.what() << "\n";
        }
    }
    task.finish();
}

}  // namespace

int main(int argc, char** argv) {
    settings s;
    std::vector<std::string> parts;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--quick") s.quick = true;
        else if (a == "--out" && i + 1 < argc) s.out = argv[++i];
        else if (a == "--scene" && i + 1 < argc) s.only = argv[++i];
        else if (a == "--part" && i + 1 < argc) parts.push_back(argv[++i]);
        else {
            std::cerr << "usage: " << argv[0]
                      << " [--quick] [--out DIR] [--part work|derivation|omega|time]... [--scene ID]\n";
            return 2;
        }
    }
    if (s.quick) {
        s.time_per_point = 0.1;
        s.max_repeats = 5;
        s.rhs_budget = 2'000'000;
    }
    const auto progress = progress_on_terminal(STDERR_FILENO);  // a progress line on a terminal only
    auto want = [&](const char* p) { return parts.empty() || std::find(parts.begin(), parts.end(), p) != parts.end(); };
    try {
        if (want("derivation")) derivation(s);
        if (want("work")) work_precision(s);
        if (want("omega")) omega_sweep(s);
        if (want("time")) time_sweep(s);
    } catch (const std::exception& e) {
        std::cerr << "symrep_work_precision: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
