// symrep/mechanics/scene.cpp -- the smallest exact model of a scene (scene.h).
#include "symrep/mechanics/scene.h"
#include "symrep/mechanics/solution_witness.h"

#include "symrep/mechanics/dual_darboux.h"
#include "symrep/mechanics/fixed_axis.h"
#include "symrep/mechanics/turning_frame.h"
#include "symrep/numeric/quadrature.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <functional>

#include "symrep/scalar/scalar.h"
#include "symrep/core/error.h"
#include "symrep/numeric/reference.h"
#include "symrep/vector/vector.h"

namespace symrep::mechanics {

using GiNaC::ex;

namespace {

// |w| can stand in the algebra of K (rotation_operator_algebra): 0, or known positive.
bool usable_as_omega(const ex& W) {
    if (W.is_zero() || W.info(GiNaC::info_flags::positive)) return true;
    if (has_symbol(W)) return false;
    const ex x = GiNaC::evalf(W);
    return GiNaC::is_a<GiNaC::numeric>(x) && GiNaC::ex_to<GiNaC::numeric>(x).is_real() &&
           GiNaC::ex_to<GiNaC::numeric>(x).is_positive();
}

bool is_zero_vector_or_scalar(const ex& x) {
    if (x.is_zero()) return true;
    return is_vector(x) ? equal(x, 0) : is_zero_scalar(x);
}

// e as an operand: in parentheses when its text has an operator (a literal has none)
std::string paren(const ex& e) {
    const std::string s = to_string(e);
    return !is_vector_literal(e) && s.find(' ') != std::string::npos ? "(" + s + ")" : s;
}

// "w0^2 r'", "2 w x r'", "-q/m w x v": a term c K^j x^(m) of the equation.
std::string term_text(const ex& c, unsigned j, const std::string& x, const ex& axis) {
    const std::string w = axis.is_zero() ? std::string("K") : paren(axis);
    const std::string op = j == 0 ? x : j == 1 ? w + " x " + x : w + " x (" + w + " x " + x + ")";
    if (c.is_equal(1)) return op;
    if (c.is_equal(-1)) return "-" + op;
    return paren(c) + " " + op;
}

std::string polynomial_text(const std::vector<cex>& a) {
    std::string s;
    for (std::size_t m = a.size(); m-- > 0;) {
        const ex c = a[m].re + GiNaC::I * a[m].im;
        if (c.is_zero()) continue;
        const std::string mono = m == 0 ? "" : m == 1 ? "s" : "s^" + std::to_string(m);
        std::string cs = GiNaC::is_a<GiNaC::add>(c) ? "(" + to_string(c) + ")" : to_string(c);
        if (m > 0 && c.is_equal(1)) cs = "";
        else if (m > 0 && c.is_equal(-1)) cs = "-";
        else if (m > 0) cs += "*";
        const std::string term = cs + mono;
        if (s.empty()) s = term;
        else if (term[0] == '-') s += " - " + term.substr(1);
        else s += " + " + term;
    }
    return (s.empty() ? "0" : s) + " = 0";
}

std::string algebra_text(const rotation_operator_algebra& R, cyclic_factors m) {
    const ex p = R.minimal_polynomial(m);
    if (p.is_equal(1)) return "R[X]/(1) = {0}";
    const ex W2 = R.omega() * R.omega();
    const std::string w2 = W2.is_equal(1) ? "" : paren(W2) + " ";
    std::string s;
    if (m.axial && m.planar && !R.degenerate()) s = "X^3 + " + w2 + "X";
    else if (m.planar && !R.degenerate()) s = "X^2 + " + to_string(W2);
    else s = to_string(p);
    return "R[X]/(" + s + ")";
}

}  // namespace

ex put_values(const ex& e, const parameter_values& v) {
    try {
        ex x = v.vectors.empty() || vector_symbols(e).empty() ? e : subs_vectors(e, v.vectors);
        if (vector_symbols(x).empty() && is_vector(x)) x = subs_components(x, {});  // one literal [x, y, z]
        return v.scalars.empty() ? x : x.subs(v.scalars);
    } catch (const error&) {
        throw;
    } catch (const std::exception& err) {
        std::string why = err.what(), text = to_string(e);
        if (why.find("division by zero") != std::string::npos) why = "division by zero";  // GiNaC's power::eval()
        if (text.size() > 160) text = text.substr(0, 157) + "...";
        throw domain_error("the values make " + text + " singular (" + why + ")");
    }
}

namespace {

void check_value_names(const cauchy_problem& P, const parameter_values& v) {
    // by name too: a script's symbol r is not the unknown r of ode(...), but a value for it is a mistake
    auto refuse = [&](const ex& k) {
        const std::string name = to_string(k);
        if (k.is_equal(P.t) || name == to_string(P.t))
            throw domain_error(name + " is the independent variable of the problem: it cannot be given a value");
        for (std::size_t m = 0; m < P.unknowns.size(); ++m)
            if (k.is_equal(P.unknowns[m]) || name == P.unknown_name(m))
                throw domain_error(P.unknown_name(m) + " is the unknown of the problem: it cannot be given a value");
    };
    // the parameters of P are constants: a value that depends on t would give the solution of a
    // different (time-dependent) problem, frozen at each t, without a word (refused)
    auto constant = [&](const ex& k, const ex& x) {
        bool depends = x.has(P.t);
        for (auto it = x.preorder_begin(); !depends && it != x.preorder_end(); ++it)
            depends = GiNaC::is_a<GiNaC::symbol>(*it) && to_string(*it) == to_string(P.t);
        if (depends)
            throw domain_error("the value of " + to_string(k) + " depends on " + to_string(P.t) + ", but " +
                               to_string(k) + " is a constant of the problem (its solution holds only for values "
                               "that do not depend on " + to_string(P.t) + ")");
    };
    for (const auto& kv : v.vectors) { refuse(kv.first); constant(kv.first, kv.second); }
    for (const auto& kv : v.scalars) { refuse(kv.first); constant(kv.first, kv.second); }
}

}  // namespace

cauchy_problem with_values(const cauchy_problem& P, const parameter_values& v) {
    check_value_names(P, v);
    cauchy_problem Q = P;
    Q.reduced = nullptr;
    Q.expression = put_values(P.expression, v);
    for (ex& x : Q.initial) x = put_values(x, v);
    return Q;
}

placeholder_factors scene_model::factors() const {
    placeholder_factors f;
    for (const data_model& d : data) f[d.name] = d.factors;
    return f;
}

scene_model classify(const cauchy_problem& P, const parameter_values& v) {
    check_value_names(P, v);
    const operator_form F = P.reduced ? *P.reduced : reduce(P);
    if (!F.general.empty())
        throw domain_error("the free term " + to_string(F.general.front().first * F.general.front().second) +
                           " is not a quasi-polynomial in " + to_string(P.t) +
                           ": the scene's cases are read on quasi-polynomial forcing (solve(P, values) gives its "
                           "Duhamel integral)");
    scene_model out;
    out.axis = F.axis;
    out.form = F;
    const std::size_t M = F.ode.A.size() - 1;

    // the exact values go into the coefficients; |w| too when it is known positive (or 0)
    parameter_values exact;
    for (const auto& [k, x] : v.vectors)
        if (!has_float(x)) exact.vectors.emplace(k, x);
    for (const auto& [k, x] : v.scalars)
        if (!has_float(x)) exact.scalars.emplace(k, x);
    out.axis_value = F.axis.is_zero() ? ex(0) : put_values(F.axis, v);
    out.axis_zero = !F.axis.is_zero() && is_zero_vector_or_scalar(out.axis_value);
    const ex Omega_value = F.axis.is_zero() ? ex(0) : tidy(put_values(norm(F.axis), v));
    out.Omega = F.axis.is_zero() ? ex(0)
                : !has_float(Omega_value) && usable_as_omega(Omega_value) ? Omega_value : F.Omega;
    out.form.Omega = out.Omega;
    auto all_values = [&](const ex& c) {
        return put_values(F.axis.is_zero() ? c : c.subs(F.Omega == Omega_value), v);
    };
    auto model_values = [&](const ex& c) {
        return tidy(put_values(F.axis.is_zero() ? c : c.subs(F.Omega == out.Omega), exact));
    };
    auto vanishes = [&](const ex& c) { return is_zero_scalar(all_values(c)); };

    // which values the coefficients use (for the report)
    std::vector<ex> used;
    auto note_symbols = [&](const ex& c) {
        for (auto it = c.preorder_begin(); it != c.preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::symbol>(*it) && !it->is_equal(P.t) && !it->is_equal(F.Omega) &&
                (v.scalars.count(*it) || v.vectors.count(*it)))
                used.push_back(*it);
    };

    // terms that vanish for the values are dropped (a coefficient split into the
    // terms of its numerator; the whole coefficient when its terms cancel)
    auto drop = [&](const ex& c, const std::function<std::string(const ex&)>& text) -> ex {
        if (c.is_zero()) return c;
        note_symbols(c);
        const ex n = GiNaC::normal(c);
        const ex num = GiNaC::expand(GiNaC::numer(n)), den = GiNaC::denom(n);
        if (vanishes(den))
            throw domain_error("the coefficient " + to_string(c) + " is singular for the values");
        ex kept = 0;
        for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(num) ? num.nops() : 1); ++i) {
            const ex term = GiNaC::is_a<GiNaC::add>(num) ? num.op(i) : num;
            if (vanishes(term)) out.dropped.push_back(text(term / den) + " (0 for the values)");
            else kept += term;
        }
        if (!kept.is_zero() && vanishes(kept)) {
            out.dropped.push_back(text(kept / den) + " (0 for the values)");
            kept = 0;
        }
        return kept / den;
    };
    for (std::size_t m = 0; m <= M; ++m)
        for (std::size_t j = 0; j < F.ode.A[m].size(); ++j) {
            const ex c = drop(F.ode.A[m][j], [&](const ex& k) {
                return term_text(k, unsigned(j), P.unknown_name(m), F.axis);
            });
            out.form.ode.A[m][j] = c.is_zero() ? c : model_values(c);
        }
    bool leading = false;
    for (const ex& c : out.form.ode.A[M]) leading = leading || !c.is_zero();
    if (!leading)
        throw domain_error("the coefficient of " + P.unknown_name(M) + " is 0 for the values: the equation is not "
                           "of order " + std::to_string(M) + " there");
    for (std::size_t m = 0; m <= M && P.is_vector && !F.axis.is_zero(); ++m)
        for (std::size_t j = 1; j < out.form.ode.A[m].size(); ++j)
            out.operator_present = out.operator_present || !out.form.ode.A[m][j].is_zero();

    // the data vectors: each one's relation to w decides its local minimal polynomial
    std::map<std::string, ex> data(F.data.begin(), F.data.end());
    std::vector<forcing_term> forcing;
    auto classify_data = [&](const std::string& name, const ex& P_vector, bool zero_coefficient) {
        data_model d;
        d.name = name;
        d.vector = P_vector;
        const std::string label = to_string(P_vector);
        const ex Pv = put_values(P_vector, v);
        if (zero_coefficient || is_zero_vector_or_scalar(Pv)) {
            d.relation = data_relation::zero;
            d.reason = zero_coefficient ? "its coefficient is 0" : P_vector.is_zero() ? "" : label + " = 0";
        } else if (!P.is_vector || !out.operator_present) {
            d.relation = data_relation::no_operator;
            d.reason = !P.is_vector ? "scalar problem" : F.axis.is_zero() ? "no operator term"
                                                                          : "no term with " + paren(F.axis) + " x";
        } else if (out.axis_zero) {
            d.relation = data_relation::along_axis;
            d.reason = to_string(F.axis) + " = 0";
        } else if (equal(cross(out.axis_value, Pv), 0)) {
            d.relation = data_relation::along_axis;
            d.reason = paren(F.axis) + " x " + paren(P_vector) + " = 0";
        } else if (equal(dot(out.axis_value, Pv), 0)) {
            d.relation = data_relation::perpendicular;
            d.reason = paren(F.axis) + " . " + paren(P_vector) + " = 0";
        } else {
            d.relation = data_relation::general;
            d.reason = "neither along nor perpendicular to " + paren(F.axis);
        }
        switch (d.relation) {
            case data_relation::zero: d.factors = {false, false}; break;
            case data_relation::along_axis:
            case data_relation::no_operator: d.factors = {true, false}; break;
            case data_relation::perpendicular: d.factors = {false, true}; break;
            case data_relation::general: d.factors = {true, true}; break;
        }
        out.algebra.axial = out.algebra.axial || d.factors.axial;
        out.algebra.planar = out.algebra.planar || d.factors.planar;
        out.data.push_back(d);
    };
    for (const std::string& nm : F.ode.initial) classify_data(nm, data.at(nm), false);
    for (const forcing_term& f : F.ode.forcing) {
        const ex vec = data.at(f.vector);
        const bool vector_zero = is_zero_vector_or_scalar(put_values(vec, v));
        const ex q = vector_zero ? ex(0) : drop(GiNaC::expand(f.q.to_ex()), [&](const ex& k) {
            return paren(k) + " " + paren(vec);
        });
        classify_data(f.vector, vec, !vector_zero && q.is_zero());
        if (!q.is_zero()) forcing.push_back({quasi_polynomial::from_ex(model_values(q), P.t), f.power, f.vector});
    }
    out.form.ode.forcing = forcing;

    // values put into the coefficients, values kept as symbols until the end
    std::sort(used.begin(), used.end(), [](const ex& a, const ex& b) { return to_string(a) < to_string(b); });
    used.erase(std::unique(used.begin(), used.end(), [](const ex& a, const ex& b) { return a.is_equal(b); }),
               used.end());
    for (const ex& s : used) {
        const auto it = v.scalars.find(s);
        const auto iv = v.vectors.find(s);
        const ex x = it != v.scalars.end() ? it->second : iv->second;
        if (has_float(x)) out.deferred_values.push_back(to_string(s));
        else out.exact_values.push_back(to_string(s) + " = " + to_string(x));
    }
    if (!F.axis.is_zero() && !has_float(Omega_value) && out.Omega.is_equal(Omega_value) && out.operator_present)
        out.exact_values.push_back("|" + to_string(F.axis) + "| = " + to_string(Omega_value));

    // the scalar problems of the model (the characteristic polynomials solved)
    const rotation_operator_algebra R(out.Omega);
    if (out.algebra.axial) {
        std::vector<cex> a0;
        for (const auto& Am : out.form.ode.A) a0.push_back(cex(Am.empty() ? ex(0) : Am[0], ex(0)));
        out.axial_problem = polynomial_text(a0);
    }
    if (out.algebra.planar) {
        std::vector<cex> a1;
        for (const auto& Am : out.form.ode.A) a1.push_back(R.at_i_omega(Am));
        out.planar_problem = polynomial_text(a1);
    }
    out.method = solution_method::closed_form;
    out.method_reason = "constant coefficients and quasi-polynomial forcing: the closed form is exact "
                        "(impulse responses of the scalar problems, convolution with the forcing; VI.1.26-38)";
    return out;
}

std::string scene_model::report() const {
    if (!reduction.empty()) return reduction;
    const rotation_operator_algebra R(Omega);
    const std::string w = axis.is_zero() ? std::string() : paren(axis);  // (q*B/m + 2*w) x: a sum in parentheses
    const std::string wbar = axis.is_zero() ? std::string() : to_string(axis);  // |q*B/m + 2*w|
    std::string s;
    const cyclic_factors full{true, true};
    if (!axis.is_zero() && operator_present) {
        // the general model in |w| when the values make w = 0 (K nilpotent there)
        const std::string general = R.degenerate() ? "R[X]/(X^3 + |" + wbar + "|^2 X)" : algebra_text(R, full);
        s += "model: " + algebra_text(R, algebra) + ", K = " + w + " x" +
             (algebra == full ? std::string(" (the general model)") : " (general model " + general + ")") + "\n";
    } else {
        s += "model: " + algebra_text(R, algebra) + " (no rotation operator: one scalar problem for every data "
                                                    "vector)\n";
    }
    for (const data_model& d : data) {
        s += "  " + d.name + " = " + to_string(d.vector) + ": ";
        switch (d.relation) {
            case data_relation::zero: s += "no term" + (d.reason.empty() ? "" : " (" + d.reason + ")") + "\n"; continue;
            case data_relation::along_axis: s += "along " + w + " (" + d.reason + ")"; break;
            case data_relation::perpendicular: s += "perpendicular to " + w + " (" + d.reason + ")"; break;
            case data_relation::general: s += "general (" + d.reason + ")"; break;
            case data_relation::no_operator: s += d.reason; break;
        }
        s += ": " + algebra_text(R, d.factors);
        if (d.factors.axial && !d.factors.planar && d.reason != "scalar problem")
            s += ", one-dimensional: a multiple of " + paren(d.vector);
        else if (d.factors.planar && !d.factors.axial)
            s += ", two-dimensional: in the plane perpendicular to " + w;
        s += "\n";
    }
    for (const std::string& d : dropped) s += "dropped: " + d + "\n";
    if (!exact_values.empty()) {
        s += "exact values in the derivation:";
        for (std::size_t i = 0; i < exact_values.size(); ++i) s += (i ? ", " : " ") + exact_values[i];
        s += "\n";
    }
    if (!floats_made_exact.empty()) {
        s += "floating-point values taken exactly (put in at the end, they made the solution singular):";
        for (std::size_t i = 0; i < floats_made_exact.size(); ++i) s += (i ? ", " : " ") + floats_made_exact[i];
        s += "; the result is evaluated in floating point\n";
    }
    if (!deferred_values.empty()) {
        s += "floating-point values put in at the end:";
        for (std::size_t i = 0; i < deferred_values.size(); ++i) s += (i ? ", " : " ") + deferred_values[i];
        s += "\n";
    }
    s += "method: closed form";
    if (!axial_problem.empty()) s += "; axial problem " + axial_problem;
    if (!planar_problem.empty()) s += "; planar problem " + planar_problem;
    if (axial_problem.empty() && planar_problem.empty()) s += "; every data vector is 0, so x = 0";
    s += "\nwhy: " + method_reason + "\n";
    return s;
}

namespace {

// An upper bound of log10 of the magnitude of e (the sum of the absolute values of its terms,
// solution_witness.h) at t = 1, |cos| and |sin| taken as 1: sums by their largest term, so that
// a sum that cancels counts with the size of its terms; a vector by its largest component.
// Exact numbers (no float), any size.
// Symbol-free parts other than sums are evaluated (30 digits); LONG_MIN for 0.
long magnitude_exponent(const ex& e, const ex& t) {
    if (e.is_zero()) return LONG_MIN;
    if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::matrix>(e) || GiNaC::is_a<GiNaC::lst>(e)) {
        long m = LONG_MIN;
        for (std::size_t i = 0; i < e.nops(); ++i) m = std::max(m, magnitude_exponent(e.op(i), t));
        return m;
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
        long m = 0;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            const long f = magnitude_exponent(e.op(i), t);
            if (f == LONG_MIN) return LONG_MIN;
            m += f;
        }
        return m;
    }
    if (e.is_equal(t)) return 0;
    if (!e.has(t)) {
        const num::digits_scope d(30);
        ex x;
        try {
            x = GiNaC::evalf(e);
        } catch (const std::exception&) {
            return 0;
        }
        if (GiNaC::is_a<GiNaC::numeric>(x) && !GiNaC::ex_to<GiNaC::numeric>(x).is_zero()) {
            const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(x);
            return num::decimal_exponent(GiNaC::abs(n.real()) + GiNaC::abs(n.imag())) + 1;
        }
        return 0;
    }
    if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)) &&
        GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_pos_integer()) {
        const long b = magnitude_exponent(e.op(0), t);
        return b == LONG_MIN ? b : b * GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_long();
    }
    if (GiNaC::is_a<GiNaC::function>(e) && e.nops() == 1 && GiNaC::ex_to<GiNaC::function>(e).get_name() == "exp") {
        // exp(a t) at t = 1 (the size its coefficient multiplies; at least 1)
        const num::digits_scope d(30);
        const ex a = GiNaC::evalf(GiNaC::real_part(e.op(0).subs(t == 1)));
        if (GiNaC::is_a<GiNaC::numeric>(a) && GiNaC::ex_to<GiNaC::numeric>(a).is_real())
            return std::max(0L, long(std::floor(GiNaC::ex_to<GiNaC::numeric>(a).to_double() / std::log(10.0))) + 1);
    }
    return 0;  // sin, cos of a real argument, t^k at t = 1
}

// The exact closed form x (the values put in as exact numbers) evaluated in floating point,
// each number rounded to the digits that keep Digits of the result: terms of the size
// 10^M (M = magnitude_exponent: 1/|w|^4 (w x (g x w)) for small |w|) cancel down to the size of
// the data, 10^scale (the smallest value given), so each number keeps Digits + M - scale + 2
// digits: the rounding is 10^-(Digits + 2) of the data's size at t = 1, and T^k times that at
// t = T for the t^k of the terms (1e-18 at T = 10 with k = 4 and Digits = 20). Before issue
// 27 the digits were Digits plus the exponent of the largest number only when above 1, read as
// a double clamped at 1e300: with |w| = 1e-270 and data of 1e-200 (terms of 1e340 cancelling
// to 1e-200) the result was noise, and with data of 1e-200 and |w| = 1e-50 (terms of 1e-100)
// no digit was added. Refused beyond 20000 digits.
ex evaluate_with_guard(const ex& x, const ex& t, long scale) {
    const long saved = GiNaC::Digits;
    const long M = magnitude_exponent(x, t);
    const long extra = M == LONG_MIN || M <= scale ? 0 : M - scale + 2;
    const long digits = saved + extra;
    if (digits > 20000)
        throw domain_error("the closed form of the scene cancels about " + std::to_string(extra) +
                           " decimal digits at these values (terms of 10^" + std::to_string(M) +
                           " for data of 10^" + std::to_string(scale) +
                           "): too many to print it in floating point; solve(P) and eval at the times "
                           "evaluate it, or give the values as exact numbers");
    const num::digits_scope d(digits + 10);
    return num::round_digits(GiNaC::evalf(x), digits);
}

// floor(log10) of the smallest nonzero size among the values (of a vector its largest
// component): the scale of the data a scene's result is measured against; 0 without one.
long values_scale(const parameter_values& v) {
    long s = LONG_MAX;
    auto note = [&](const ex& x) {
        const num::digits_scope d(30);
        GiNaC::numeric size = 0;
        for (std::size_t i = 0; i < (is_vector_literal(x) ? 3u : 1u); ++i) {
            const ex y = GiNaC::evalf(is_vector_literal(x) ? x.op(i) : x);
            if (GiNaC::is_a<GiNaC::numeric>(y))
                size = std::max(size, GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(y).real()) +
                                          GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(y).imag()));
        }
        if (!size.is_zero()) s = std::min(s, num::decimal_exponent(size));
    };
    for (const auto& [k, x] : v.vectors) note(x);
    for (const auto& [k, x] : v.scalars) note(x);
    return s == LONG_MAX ? 0 : s;
}

}  // namespace

scene_solution solve(const cauchy_problem& P, const parameter_values& v) {
    if (is_dual_problem(P))  // (issue 31) the scenes' cases are real: no eps as a parameter
        throw closed_form_error("solve(P, values) of a problem in the dual unit eps: solve(P) gives its closed form "
                                "(docs/rigid_body.md section 3), subs puts the values in");
    const std::optional<ex> closed_turning =
        !P.reduced && P.turning ? closed_solution(P, *P.turning) : std::optional<ex>();
    if (!P.reduced && P.turning && !closed_turning)
        throw closed_form_error("the solution " + describe_reduction(P, *P.turning) +
                                "\nhas no closed form in t (reduced_solution.h evaluates it)");
    // a free term kept as a Duhamel integral (operator_form::general, VI.1.26-38): the general
    // solution with the values put in, as for the readings below
    const bool duhamel_terms = P.reduced && !P.reduced->general.empty();
    if ((!P.reduced && (P.fixed_axis || closed_turning || P.velocity)) || duhamel_terms) {
        // a frame rotating about a fixed axis (VI.2) or precessing regularly (VI.3): the general reduction with the values
        // put in (floats as the exact numbers they are, the result evaluated once at the end)
        check_value_names(P, v);
        scene_solution out;
        bool floats = false;
        parameter_values exact = v;
        for (auto& [k, x] : exact.vectors) {
            floats = floats || has_float(x);
            x = num::exact_floats_of(x);
        }
        for (auto& [k, x] : exact.scalars) {
            floats = floats || has_float(x);
            x = num::exact_floats_of(x);
        }
        // solve(P) reduces as solve_fixed_axis does, with its witness (solution_witness.h)
        if (closed_turning) require_witness(P, *closed_turning);
        out.model_solution = closed_turning ? *closed_turning : solve(P);
        out.x = put_values(out.model_solution, exact);
        // (with the digits its cancellations need, as below; integral objects keep Digits)
        if (floats)
            out.x = normalize_trig_signs(num::has_integral(out.x) ? GiNaC::evalf(out.x)
                                                                  : evaluate_with_guard(out.x, P.t, values_scale(exact)));
        // integral objects (a free term across the axis) keep the nesting of the general form:
        // its canonical form folds the scale factors that the exact rationals of the floats leave
        if (floats && num::has_integral(out.x)) out.x = canonical(out.x);
        if (closed_turning) {
            out.model.reduction = "method: reduction to the inertial problem (Thm VI.3.2.1): r = Q psi, Q = A B a "
                                  "regular precession, both in closed form\n";
            return out;
        }
        if (P.velocity) {
            out.model.reduction = "method: the velocity " + P.velocity->name + " by reduction to the inertial problem "
                                  "(Thm VI.2.1.1), then " + P.name + " = " + P.name + "(0) + int_0^t " +
                                  P.velocity->name + " (VI.2.51)\n";
            return out;
        }
        if (duhamel_terms) {
            out.model.reduction = "method: the operator solution in the algebra of K (VI.1.26-38), the free terms "
                                  "that are not quasi-polynomials as Duhamel integrals int_0^t Y(t - tau) f(tau) "
                                  "dtau\n";
            return out;
        }
        const fixed_axis_form& fa = *P.fixed_axis;
        out.model.reduction = "method: reduction to the inertial problem (Thm VI.2.1.1, VI.2.2): w(t) = (" +
                              to_string(fa.s) + ") " + to_string(fa.u) + ", r = Q psi, Q the rotation by -(" +
                              to_string(fa.angle) + ") about " + to_string(fa.u) + "\n";
        return out;
    }
    scene_solution out;
    out.model = classify(P, v);
    const rotation_operator_algebra R(out.model.form.Omega);
    const operator_solution S = solve(out.model.form.ode, R, P.t, out.model.factors());
    out.model_solution = vector_solution(P, out.model.form, S);
    bool floats = false;
    for (const auto& [k, x] : v.vectors) floats = floats || has_float(x);
    for (const auto& [k, x] : v.scalars) floats = floats || has_float(x);
    // the floats as exact numbers (the decimal each float prints as: 0.1 is 1/10, so that
    // 5 sin(t/5) prints as 5.0*sin(0.2*t); it differs from the binary number by less than the
    // float's own rounding), put into the exact solution, and the result evaluated at the end
    // with the digits its cancellations need (evaluate_with_guard): rounding each coefficient to
    // Digits before the terms of size 1/|w|^3 cancel would lose the digits the general path's
    // eval keeps, and floats inside the derivation made the printed solution depend on the order
    // GiNaC happened to sum them in
    parameter_values exact = v;
    for (auto& [k, x] : exact.vectors) x = num::decimal_floats_of(x);
    for (auto& [k, x] : exact.scalars) x = num::decimal_floats_of(x);
    ex x_exact;
    try {
        x_exact = put_values(floats ? num::decimal_floats_of(out.model_solution) : out.model_solution, exact);
    } catch (const domain_error&) {
        if (out.model.deferred_values.empty()) throw;
        // the floats meet where the derivation, without them, could not see it (w0 = 2.0 next to
        // cos(2 t) is a resonance): derive again with the floats as the exact numbers they are
        parameter_values binary = v;
        for (auto& [k, x] : binary.vectors) x = num::exact_floats_of(x);
        for (auto& [k, x] : binary.scalars) x = num::exact_floats_of(x);
        cauchy_problem Q = P;
        Q.reduced = nullptr;
        Q.expression = num::exact_floats_of(P.expression);
        for (ex& x : Q.initial) x = num::exact_floats_of(x);
        scene_solution again = solve(Q, binary);  // exact values: witnessed there
        again.model.floats_made_exact = out.model.deferred_values;
        again.x = normalize_trig_signs(evaluate_with_guard(again.x, P.t, values_scale(binary)));
        return again;
    }
    // the witness (solution_witness.h) on the exact result against the problem with the same
    // exact values: solve(P, values) never returns what its residual test sees as nonzero.
    // Floats in the problem itself were in the derivation: the witness then measures with the
    // rounding of floats (it sees them in the result).
    require_witness(with_values(P, exact), x_exact);
    // a numeric frequency may come out negative (1 - q of a damped pendulum): sin(-1.9 t) -> -sin(1.9 t)
    out.x = floats ? normalize_trig_signs(evaluate_with_guard(x_exact, P.t, values_scale(exact))) : x_exact;
    return out;
}

}  // namespace symrep::mechanics
