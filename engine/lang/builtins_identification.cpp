// symrep/lang/builtins_identification.cpp -- identification of nonlinear systems with Walsh
// algebras (thesis IV.2; identification/identify.h): walsh_coefficients, operational_matrix,
// block_pulse_matrix, simulate_system, identify.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "symrep/algebra/walsh_hadamard.h"
#include "symrep/core/error.h"
#include "symrep/numeric/reference.h"
#include "symrep/scalar/scalar.h"
#include "symrep/identification/identify.h"
#include "symrep/identification/operational_matrix.h"
#include "symrep/identification/sindy.h"
#include "symrep/identification/walsh_series.h"
#include "symrep/lang/builtins.h"
#include "symrep/lang/values.h"
#include "symrep/numeric/evaluator.h"
#include "symrep/output/formats.h"
#include "symrep/output/printer.h"

namespace symrep::lang {

namespace {

namespace id = symrep::identification;

const char* const section = "Identification (IV.2)";

// A function of t on [0, 1): a compiled closed form (every other symbol is an error, named).
std::function<double(double)> function_of(const GiNaC::ex& e, const GiNaC::symbol& t, const builtin& b,
                                          const std::string& what) {
    try {
        auto f = std::make_shared<num::compiled_function>(num::compile(e, {t}));
        return [f](double x) {
            double y;
            f->eval(&x, &y);
            return y;
        };
    } catch (const error& ex) {
        throw type_error(b.name + ": " + what + " " + output::print_ex(e) + " is not a numeric function of " +
                         t.get_name() + " (" + ex.what() + ")");
    }
}

// The time span [0, T) from argument i: the name t (T = 1, IV.2.25) or t = [0, T].
struct time_span {
    const GiNaC::symbol* t = nullptr;
    double T = 1;
};

time_span span_arg(const std::vector<value>& a, std::size_t i, const builtin& b) {
    time_span sp;
    if (a[i].is_ex() && GiNaC::is_a<GiNaC::relational>(a[i].as_ex())) {
        const GiNaC::ex& r = a[i].as_ex();
        const GiNaC::ex range = r.rhs();
        if (!GiNaC::is_a<GiNaC::symbol>(r.lhs()) ||
            !(GiNaC::is_a<GiNaC::lst>(range) || GiNaC::is_a<GiNaC::matrix>(range)) || range.nops() != 2)
            throw type_error(b.name + ": argument " + std::to_string(i + 1) + " must be the time t or t = [0, T] (usage: " +
                             b.signature + ")");
        sp.t = &GiNaC::ex_to<GiNaC::symbol>(r.lhs());
        if (!range.op(0).is_zero())
            throw domain_error(b.name + ": the span must start at 0 (zero initial data at t = 0, IV.2.38), not at " +
                               message_text(range.op(0)) + "; shift the time");
        sp.T = to_double(range.op(1), b, "the end T of the span");
        if (!(sp.T > 0) || !std::isfinite(sp.T))
            throw domain_error(b.name + ": the end T of the span [0, T] must be a positive number, not " +
                               message_text(range.op(1)));
        return sp;
    }
    sp.t = &arg_symbol(a, i, b);
    return sp;
}

bool has_jumps(const GiNaC::ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::function>(*it)) {
            const std::string name = GiNaC::ex_to<GiNaC::function>(*it).get_name();
            if (name == "step" || name == "abs") return true;
        }
    return false;
}

// A signal u(t) on [0, T) with its jump points: step(a t + b) and abs(a t + b) (sign is 2 step - 1)
// split [0, T) into pieces, each compiled with its branches fixed; right-continuous at a jump.
struct jump_signal {
    std::function<double(double)> f;
    std::vector<double> jumps;
};

jump_signal signal_of(const GiNaC::ex& e, const time_span& sp, const builtin& b, const std::string& what) {
    if (!has_jumps(e)) return {function_of(e, *sp.t, b, what), {}};
    jump_signal s;
    s.jumps = id::jump_points(e, *sp.t, sp.T);
    std::vector<double> ends{0.0};
    ends.insert(ends.end(), s.jumps.begin(), s.jumps.end());
    ends.push_back(sp.T);
    std::vector<std::function<double(double)>> pieces;
    for (std::size_t k = 0; k + 1 < ends.size(); ++k)
        pieces.push_back(function_of(id::piece_of(e, *sp.t, (ends[k] + ends[k + 1]) / 2), *sp.t, b, what));
    const std::vector<double> jumps = s.jumps;
    s.f = [pieces, jumps](double x) {
        return pieces[std::size_t(std::upper_bound(jumps.begin(), jumps.end(), x) - jumps.begin())](x);
    };
    return s;
}

// The 2^n block averages of a signal given as a list of numbers (its block values) or as an
// expression in t (averaged by quadrature, split at its jumps).
std::vector<double> blocks_of(const value& v, const time_span& sp, unsigned n, const builtin& b,
                              const std::string& what) {
    const std::size_t N = std::size_t(1) << n;
    if (v.is_list()) {
        const list& l = v.as_list();
        if (l.size() != N)
            throw domain_error(b.name + ": " + what + " has " + std::to_string(l.size()) + " block values; n = " +
                               std::to_string(n) + " needs 2^n = " + std::to_string(N) +
                               (is_pow2(l.size()) ? "" : " (" + std::to_string(l.size()) +
                                " is not a power of two: resample the signal to 2^n blocks)"));
        std::vector<double> out;
        for (std::size_t k = 0; k < N; ++k) {
            if (!l[k].is_ex()) throw type_error(b.name + ": block value " + std::to_string(k + 1) + " of " + what + " is not a number");
            out.push_back(to_double(l[k].as_ex(), b, "block value " + std::to_string(k + 1) + " of " + what));
        }
        return out;
    }
    if (!v.is_ex()) throw type_error(b.name + ": " + what + " must be an expression in t or a list of block values");
    const jump_signal s = signal_of(v.as_ex(), sp, b, what);
    return id::block_averages(s.f, n, sp.T, s.jumps);
}

// The a_k of (IV.2.37) from argument i, default [0, 0] (IV.2.25): numbers are known, symbols unknown.
id::linear_part linear_part_arg(const std::vector<value>& a, std::size_t i, const builtin& b) {
    if (a.size() <= i) return {0.0, 0.0};
    id::linear_part lin;
    for (const auto& e : arg_ex_list(a, i, b))
        lin.push_back(GiNaC::is_a<GiNaC::symbol>(e) ? std::optional<double>() : to_double(e, b, "a coefficient a_k"));
    if (lin.empty()) throw domain_error(b.name + ": the list of a_k is empty (order m >= 1)");
    return lin;
}

// The measured output q (argument 0) and input u (argument 1) on 2^n blocks of [0, T).
id::measured_system system_arg(const std::vector<value>& a, const time_span& sp, unsigned n, const builtin& b) {
    id::measured_system s;
    s.q = blocks_of(a[0], sp, n, b, "the output q");
    s.u = blocks_of(a[1], sp, n, b, "the input u");
    s.period = sp.T;
    return s;
}

// A number as a JSON value (null when not finite).
std::string json_number(double x) {
    if (!std::isfinite(x)) return "null";
    std::ostringstream os;
    os << std::setprecision(17) << x;
    return os.str();
}

std::string json_numbers(const std::vector<double>& xs) {
    std::string out = "[";
    for (std::size_t i = 0; i < xs.size(); ++i) out += (i ? ", " : "") + json_number(xs[i]);
    return out + "]";
}

list number_list(const std::vector<double>& xs) {
    list out;
    for (double x : xs) out.push_back(value(GiNaC::ex(num::from_double(x))));
    return out;
}

GiNaC::ex polynomial(const std::vector<double>& c, const GiNaC::ex& x) {
    GiNaC::ex p = 0;
    for (std::size_t i = 0; i < c.size(); ++i) p += GiNaC::numeric(c[i]) * GiNaC::pow(x, int(i));
    return p;
}

std::string shown(double x) {
    std::ostringstream os;
    os << std::setprecision(3) << x;
    return os.str();
}

value builtin_walsh_coefficients(const builtin& b, const std::vector<value>& a, context&) {
    if (a.size() == 1) {
        const std::vector<GiNaC::ex> xs = arg_ex_list(a, 0, b);
        list out;
        for (const auto& c : id::walsh_from_blocks(xs)) out.push_back(value(c));
        return out;
    }
    if (a.size() != 3) throw type_error(b.name + ": usage " + b.signature);
    const GiNaC::symbol& t = arg_symbol(a, 1, b);
    const unsigned n = unsigned(arg_int(a, 2, b, 1, 16));
    const GiNaC::ex& f = arg_ex(a, 0, b);
    list out;
    if (!has_matrix(f) && id::is_piecewise_polynomial(f, t)) {
        for (const auto& c : id::walsh_from_blocks(id::block_averages_exact(f, t, n))) out.push_back(value(c));
        return out;
    }
    const jump_signal sig = signal_of(f, time_span{&t, 1.0}, b, "the signal");
    return number_list(id::walsh_from_blocks(id::block_averages(sig.f, n, 1.0, sig.jumps)));
}

value builtin_walsh_blocks(const builtin& b, const std::vector<value>& a, context&) {
    list out;
    for (const auto& v : id::blocks_from_walsh(arg_ex_list(a, 0, b))) out.push_back(value(v));
    return out;
}

value builtin_operational_matrix(const builtin& b, const std::vector<value>& a, context&) {
    const unsigned n = unsigned(arg_int(a, 0, b, 1, 8));
    if (a.size() == 1) return GiNaC::ex(id::operational_matrix_exact(n));
    const GiNaC::ex& me = arg_ex(a, 1, b);
    if (!GiNaC::is_a<GiNaC::numeric>(me) || !GiNaC::ex_to<GiNaC::numeric>(me).is_integer() ||
        GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(me)) > 64)
        throw type_error(b.name + ": the power m must be an integer from -64 to 64 (usage: " + b.signature + ")");
    return GiNaC::ex(id::operational_matrix_power_exact(n, GiNaC::ex_to<GiNaC::numeric>(me).to_long()));
}

value builtin_block_pulse_matrix(const builtin& b, const std::vector<value>& a, context&) {
    return GiNaC::ex(id::block_pulse_matrix_exact(unsigned(arg_int(a, 0, b, 1, 8))));
}

value builtin_simulate_system(const builtin& b, const std::vector<value>& a, context&) {
    const GiNaC::symbol& x = arg_symbol(a, 1, b);
    const time_span sp = span_arg(a, 3, b);
    const unsigned n = unsigned(arg_int(a, 4, b, 1, 16));
    std::vector<double> coeffs{0, 0};
    if (a.size() == 6) {
        coeffs.clear();
        for (const auto& e : arg_ex_list(a, 5, b)) coeffs.push_back(to_double(e, b, "a coefficient a_k"));
    }
    const auto f = function_of(arg_ex(a, 0, b), x, b, "f");
    const jump_signal u = signal_of(arg_ex(a, 2, b), sp, b, "the input u");
    const id::measured_system s = id::simulate_system(f, u.f, coeffs, n, sp.T);
    return list{value(number_list(s.q)), value(number_list(s.u))};
}

value builtin_identify_points(const builtin& b, const std::vector<value>& a, context& c) {
    const time_span sp = span_arg(a, 2, b);
    const unsigned n = unsigned(arg_int(a, 3, b, 2, 16));
    const id::identification_report rep = id::identify_values(system_arg(a, sp, n, b), linear_part_arg(a, 4, b), 0);
    if (!rep.warning.empty())
        c.report_fields(b.name, "warning: " + rep.warning + "\n",
                        "\"warning\": " + output::json_quote(rep.warning));
    list out;
    for (std::size_t k = 0; k < rep.points_q.size(); ++k)
        out.push_back(value(list{value(GiNaC::ex(num::from_double(rep.points_q[k]))),
                                 value(GiNaC::ex(num::from_double(rep.values_f[k])))}));
    return out;
}

value builtin_identify(const builtin& b, const std::vector<value>& a, context& c) {
    const time_span sp = span_arg(a, 2, b);
    const unsigned n = unsigned(arg_int(a, 3, b, 1, 16));
    const GiNaC::symbol& x = arg_symbol(a, 4, b);
    const unsigned d = unsigned(arg_int(a, 5, b, 0, 20));
    const id::linear_part lin = linear_part_arg(a, 6, b);
    const std::string method = a.size() == 8 ? arg_string(a, 7, b) : "integral";
    const id::measured_system s = system_arg(a, sp, n, b);
    id::identification_report rep;
    if (method == "integral") rep = id::identify_integral(s, lin, d);
    else if (method == "values") rep = id::identify_values(s, lin, d);
    else if (method == "sindy") rep = id::identify_sindy_cv(s, lin, d);
    else if (method == "derivatives") rep = id::identify_sindy(s, lin, d, 0.0);
    else
        throw type_error(b.name + ": unknown method \"" + method +
                         "\" (\"integral\", \"values\", \"sindy\" or \"derivatives\")");
    std::ostringstream prose;
    prose << "identify (" << method << "): " << rep.points << " points, condition number "
          << shown(rep.condition_number) << ", residual of the integrated equation " << shown(rep.residual);
    if (method == "sindy")
        prose << ", window " << rep.window << " samples, threshold " << shown(rep.threshold);
    prose << "\n";
    if (!rep.warning.empty()) prose << "warning: " << rep.warning << "\n";
    std::string fields = "\"method\": " + output::json_quote(method) +
                         ", \"points\": " + std::to_string(rep.points) +
                         ", \"condition_number\": " + json_number(rep.condition_number) +
                         ", \"residual\": " + json_number(rep.residual) + ", \"f\": " + json_numbers(rep.f) +
                         ", \"a\": " + json_numbers(rep.a) + ", \"T\": " + json_number(sp.T);
    if (method == "sindy")
        fields += ", \"window\": " + std::to_string(rep.window) + ", \"threshold\": " + json_number(rep.threshold);
    fields += ", \"warning\": " + output::json_quote(rep.warning);
    c.report_fields(b.name, prose.str(), fields);
    const GiNaC::ex f = polynomial(rep.f, x);
    if (std::all_of(lin.begin(), lin.end(), [](const auto& k) { return k.has_value(); })) return f;
    list as;
    for (double v : rep.a) as.push_back(value(GiNaC::ex(num::from_double(v))));
    return list{value(f), value(as)};
}

}  // namespace

void register_identification_builtins(registry& r) {
    add_builtins(r, section, {
        {"walsh_coefficients", "walsh_coefficients(f, t, n) | walsh_coefficients(values)",
         "The 2^n Walsh coefficients c_p = int_0^1 f w_p dt (IV.2.4) of f on [0, 1), Walsh functions in Paley's "
         "ordering (the one in which P is the recursion IV.2.19). Exact for a piecewise polynomial f in t (polynomials, "
         "step(a t + b), abs(a t + b) with rational a, b), by Gauss-Kronrod quadrature otherwise; from a list of 2^n block values (block averages) by the fast Walsh-Hadamard "
         "transform, exact for exact values.",
         "(IV.2.4-5, IV.2.10)", "walsh_coefficients(t^2, t, 2)", 1, 3, builtin_walsh_coefficients},
        {"walsh_blocks", "walsh_blocks(c)",
         "The block values of the truncated Walsh series sum_p c_p w_p (2^n coefficients, Paley's ordering): v = W^T c "
         "(IV.2.10), by the fast Walsh-Hadamard transform; the inverse of walsh_coefficients(values). Series given by "
         "their Walsh coefficients enter identify() this way.",
         "(IV.2.5, IV.2.10)", "walsh_blocks([1/3, -1/4, -1/8, 1/16])", 1, 1, builtin_walsh_blocks},
        {"operational_matrix", "operational_matrix(n [, m])",
         "P_(2^n), the operational matrix of integration in the Walsh basis: int_0^t w = P w (IV.2.18), by the "
         "recursion P_1 = 1/2, P_m = [[P_(m/2), -I/(2m)], [I/(2m), 0]] (IV.2.19); exact, n = 1 .. 8. P = W Q W^T / 2^n "
         "(IV.2.22-23, W the Walsh functions on the blocks). With m: the power P^m for any integer m (m = -1: the "
         "inverse), through Q^m (IV.2.24, IV.2.51), never a dense inverse.",
         "(IV.2.19, IV.2.24)", "operational_matrix(2, -1)", 1, 2, builtin_operational_matrix},
        {"block_pulse_matrix", "block_pulse_matrix(n)",
         "Q_(2^n), the operational matrix of integration in the block-pulse basis: int_0^t e = Q e (IV.2.20-21); "
         "exact, n = 1 .. 8. Its characteristic and minimal polynomial are (lambda - 1/2^(n+1))^(2^n).",
         "(IV.2.21)", "block_pulse_matrix(2)", 1, 1, builtin_block_pulse_matrix},
        {"simulate_system", "simulate_system(f, x, u, t, n [, [a_1, ..., a_m]])",
         "The output of q^(m) + a_1 q^(m-1) + ... + a_m q + f(q) = u (IV.2.37; default m = 2, a = 0: IV.2.25) on "
         "[0, T) from zero initial data, integrated by Boost.Odeint (rkf78, 1e-12): [q, u] as two lists of 2^n "
         "block averages, the data identify() reads. f is an expression in x, u in t (with jumps: step, sign, abs of "
         "a t + b). t: the time (T = 1) or t = [0, T].",
         "(IV.2.25, IV.2.37)", "simulate_system(4*x + x^3, x, 10*sin(2*pi*t), t, 3)", 5, 6, builtin_simulate_system},
        {"identify_points", "identify_points(q, u, t, n [, [a_1, ..., a_m]])",
         "The table of the thesis's procedure (IV.2.36, IV.2.45): the values of f at the points q_e, [[q_k, f_k], ...], "
         "from the linear system for the vector f, neighbours averaged m times to cancel the alternating pole of "
         "(Q^T)^-m (2^n - m points; docs/identification.md). q, u and t as in identify; every a_k known (default [0, 0]).",
         "(IV.2.32-36, IV.2.45)", "identify_points(simulate_system(4*x + x^3, x, 10*sin(2*pi*t), t, 3)[0], 10*sin(2*pi*t), t, 3)",
         4, 5, builtin_identify_points},
        {"identify", "identify(q, u, t, n, x, d [, [a_1, ..., a_m] [, method]])",
         "The nonlinearity f of q^(m) + a_1 q^(m-1) + ... + a_m q + f(q) = u (IV.2.25, IV.2.37; zero initial data) "
         "on [0, T) as a polynomial of degree d in x, from the measured output q and input u: expressions in t (with "
         "jumps: step, sign, abs of a t + b) or lists of 2^n block averages. t: the time (T = 1) or t = [0, T]. a: "
         "numbers (known) or symbols (unknown, estimated jointly; returns [f, [a_1, ..., a_m]]); default [0, 0]. "
         "method \"integral\" (default): least squares in the integrated equation (IV.2.39) -- nothing is "
         "differentiated; \"values\": the thesis's procedure, f at the 2^n points from the linear system (IV.2.36, "
         "IV.2.45), its alternating pole cancelled, then fitted; \"sindy\": the SINDy pipeline (Savitzky-Golay "
         "derivatives, thresholded least squares, window and threshold by cross-validation on held-out time blocks; "
         "2^n >= 64); \"derivatives\": least squares on unsmoothed finite differences. Reports the points used, the "
         "condition number, the residual of the integrated equation (and for sindy the window and threshold chosen); "
         "an ill-conditioned fit is said with its number. Under --format json the report is one JSON line "
         "{\"kind\": \"report\", \"from\": \"identify\", \"method\", \"points\", \"condition_number\", "
         "\"residual\", \"f\", \"a\", \"T\", \"warning\"[, \"window\", \"threshold\"]}.",
         "(IV.2.26-36, IV.2.39-46)", "identify(simulate_system(4*x + 50*x^3, x, 40*sin(2*pi*t), t, 8)[0], 40*sin(2*pi*t), t, 8, x, 3)",
         6, 8, builtin_identify},
    });
}

}  // namespace symrep::lang
