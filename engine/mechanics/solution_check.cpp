// symrep/mechanics/solution_check.cpp -- check() (cauchy_problem.h): a candidate solution s
// substituted back into its problem, the residual E(s, s', ...) and the initial differences
// s^(m)(0) - X_m each decided. The residual is first proved 0 (residual_proof.h), else seen
// nonzero at one point (the point of solve()'s witness, solution_witness.h), else compared
// by components (vector.h); with floating-point numbers, what is left may be rounding
// (rounding_tolerance()).
#include "symrep/mechanics/cauchy_problem.h"
#include "symrep/dual/dual.h"
#include "symrep/mechanics/residual_proof.h"
#include "symrep/mechanics/solution_witness.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "symrep/scalar/scalar.h"
#include "symrep/core/error.h"
#include "symrep/numeric/quadrature.h"
#include "symrep/vector/vector.h"

namespace symrep::mechanics {

using GiNaC::ex;

double rounding_tolerance() { return std::pow(10.0, 5 - long(GiNaC::Digits)); }

namespace {

using vmap = std::map<ex, ex, GiNaC::ex_is_less>;

// The largest coefficient of e (the entries of a matrix; the terms of a sum): each
// term with t and every function call set to 1, evaluated; -1 when a term is not a
// number then (a symbol left: nothing to compare).
double largest_coefficient(const ex& e, const ex& t) {
    if (GiNaC::is_a<GiNaC::matrix>(e)) {
        double m = 0;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            const double x = largest_coefficient(e.op(i), t);
            if (x < 0) return -1;
            m = std::max(m, x);
        }
        return m;
    }
    struct ones : GiNaC::map_function {
        ex t;
        ex operator()(const ex& x) override {
            if (GiNaC::is_a<GiNaC::function>(x) && x.has(t)) return 1;
            return x.is_equal(t) ? ex(1) : x.map(*this);
        }
    } f;
    f.t = t;
    const ex x = GiNaC::expand(e);
    double m = 0;
    for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(x) ? x.nops() : 1); ++i) {
        const ex c = GiNaC::evalf(f(GiNaC::is_a<GiNaC::add>(x) ? x.op(i) : x));
        if (!GiNaC::is_a<GiNaC::numeric>(c)) return -1;
        m = std::max(m, GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(c)).to_double());
    }
    return m;
}

// A vector (or scalar) expression with its values in, as components: a 3x1 matrix.
ex as_components(const ex& e, bool is_vector) { return is_vector ? canonical(e).evalm() : e; }

// residual / scale when the residual is rounding-size (-1 otherwise): the residual
// is the sum of `parts`, with floating-point numbers in them.
double rounding_ratio(const ex& residual, const std::vector<ex>& parts, const ex& t, bool is_vector) {
    const double r = largest_coefficient(as_components(residual, is_vector), t);
    if (r < 0) return -1;
    double scale = 0;
    for (const ex& p : parts) {
        const double x = largest_coefficient(as_components(p, is_vector), t);
        if (x < 0) return -1;
        scale = std::max(scale, x);
        // and term by term: the terms of one part may cancel to rounding by themselves (y' of
        // y = cos(a t) e3 + (1 - cos(a t))/a^2 (w . e3) w, w = a e3, is 0 up to rounding: measured
        // as a whole, the part's size was the rounding, and a correct solution was refused)
        const ex e = GiNaC::expand(p);
        if (GiNaC::is_a<GiNaC::add>(e))
            for (std::size_t i = 0; i < e.nops(); ++i) {
                const double y = largest_coefficient(as_components(e.op(i), is_vector), t);
                if (y > scale) scale = y;
            }
    }
    if (r == 0) return 0;
    return scale > 0 && r <= rounding_tolerance() * scale ? r / scale : -1;
}

// A vector residual seen nonzero at one point: every vector symbol given rational components,
// every other symbol (t too) a rational, all fixed by their names (so the output is the same on
// every run); evaluated at 40 digits, the value must exceed 1e-20 of the sum of the absolute
// values of the terms it is the sum of (rounding at 40 digits is 1e-40 of that). False when the
// point does not decide (a pole, a value too small, something not numeric): then the caller's
// exact test by components decides. Spares that test (seconds with |w| = sqrt(w1^2 + ...)) for
// a wrong solution.
// |value| / (sum of |terms|) of r at that point, the largest over the components; -1 where the
// point does not decide (a pole, something not numeric).
double residual_ratio_at_point(const ex& r, const ex& t) {
    const auto rational_for = witness_rational;  // the point of solve()'s witness (solution_witness.h)
    vmap comps;
    for (const ex& v : vector_symbols(r)) {
        const std::string n = to_string(v);
        comps[v] = vector_literal(rational_for(n, 1), -rational_for(n, 2), rational_for(n, 3));
    }
    double ratio = 0;
    try {
        const ex c = subs_components(r, comps);
        GiNaC::exmap point;
        for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::matrix>(c) ? c.nops() : 1); ++i) {
            const ex ci = GiNaC::is_a<GiNaC::matrix>(c) ? c.op(i) : c;
            for (auto it = ci.preorder_begin(); it != ci.preorder_end(); ++it)
                if (GiNaC::is_a<GiNaC::symbol>(*it) && !point.count(*it))
                    point[*it] = it->is_equal(t) ? witness_time()
                                                 : ex(rational_for(GiNaC::ex_to<GiNaC::symbol>(*it).get_name(), 0));
        }
        const long saved = GiNaC::Digits;
        struct restore {
            long d;
            ~restore() { GiNaC::Digits = d; }
        } keep{saved};
        GiNaC::Digits = 40;
        // with floats the components are measured against the largest of their sizes: a component
        // made of rounding only (1e-22 next to terms of 1e-2 in another) is rounding, not a residual
        GiNaC::numeric float_total = 0, float_size = 0;
        bool any_float = false;
        for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::matrix>(c) ? c.nops() : 1); ++i) {
            const ex raw = GiNaC::is_a<GiNaC::matrix>(c) ? c.op(i) : c;
            // with floats the terms are put at the point one by one: substituted together, the
            // float terms (sin(0.03*t) at t = 7/3 is a number) add up to one number at once, and
            // the sum of their sizes would be the size of the sum (a residual 0 by sin^2 + cos^2
            // = 1 up to rounding was seen nonzero: check of a correct solution said false)
            const bool floats = has_float(raw);
            const ex ci = floats ? GiNaC::expand(raw) : GiNaC::expand(raw.subs(point));
            GiNaC::numeric total = 0, size = 0;
            for (std::size_t j = 0; j < (GiNaC::is_a<GiNaC::add>(ci) ? ci.nops() : 1); ++j) {
                const ex term = GiNaC::is_a<GiNaC::add>(ci) ? ci.op(j) : ci;
                const ex v = GiNaC::evalf(floats ? term.subs(point) : term);
                if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) return -1;
                total += GiNaC::ex_to<GiNaC::numeric>(v);
                size += GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(v));
            }
            if (floats) {
                any_float = true;
                float_total = std::max(float_total, GiNaC::abs(total));
                float_size = std::max(float_size, size);
                continue;
            }
            if (size.is_zero()) continue;
            ratio = std::max(ratio, GiNaC::ex_to<GiNaC::numeric>(GiNaC::abs(total) / size).to_double());
        }
        if (any_float && !float_size.is_zero())
            ratio = std::max(ratio, GiNaC::ex_to<GiNaC::numeric>(float_total / float_size).to_double());
    } catch (const std::exception&) {
        return -1;
    }
    return ratio;
}

bool nonzero_at_a_point(const ex& r, const ex& t) { return residual_ratio_at_point(r, t) > 1e-20; }

// s, s', ..., s^(M)
std::vector<ex> derivatives(const cauchy_problem& P, const ex& s) {
    std::vector<ex> d{s};
    for (std::size_t m = 1; m <= P.order(); ++m)
        d.push_back(P.is_vector ? diff_t(d.back(), P.t) : d.back().diff(ex_to<GiNaC::symbol>(P.t)));
    return d;
}

// e with s^(m) (d[m]) for each unknown x^(m)
ex substituted(const cauchy_problem& P, const ex& e, const std::vector<ex>& d) {
    if (P.is_vector) {
        vmap sub;
        for (std::size_t m = 0; m <= P.order(); ++m) sub[P.unknowns[m]] = d[m];
        return subs_vectors(e, sub);
    }
    GiNaC::exmap sub;
    for (std::size_t m = 0; m <= P.order(); ++m) sub[P.unknowns[m]] = d[m];
    return e.subs(sub);
}

// out.residual decided exactly: proved 0 (with integral objects; in the algebra of K;
// coordinate-free), seen nonzero at a point, or by components. Returns what the algebra of K
// proved (the initial values with the residual).
operator_check::proof decide_residual(const cauchy_problem& P, const ex& s, solution_check& out) {
    operator_check::proof in_algebra;
    if (!P.is_vector) {
        out.residual_zero = is_zero_scalar(out.residual);
    } else if (num::has_integral(out.residual)) {
        out.residual_zero = integral_residual_zero(out.residual);
    } else if ((in_algebra = operator_check::prove(P, s)).residual ||
               quasi_polynomial_residual_zero(out.residual, P.t)) {
        out.residual_zero = true;
    } else if (nonzero_at_a_point(out.residual, P.t)) {  // seen nonzero: no proof by components needed
        out.residual_zero = false;
        out.residual_seen_nonzero = true;
    } else {
        out.residual_zero = equal(out.residual, 0);
    }
    return in_algebra;
}

// With floating-point numbers: a residual not exactly 0 taken as 0 when it is rounding-size.
void accept_rounding_residual(const cauchy_problem& P, const std::vector<ex>& d, solution_check& out) {
    // the terms of E, each with the solution in: the residual is their sum
    const ex E = GiNaC::expand(P.expression);
    std::vector<ex> parts;
    for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(E) ? E.nops() : 1); ++i)
        parts.push_back(substituted(P, GiNaC::is_a<GiNaC::add>(E) ? E.op(i) : E, d));
    double q = rounding_ratio(out.residual, parts, P.t, P.is_vector);
    // with symbols left (q, m, E: no coefficient is a number), at the witness point: the
    // rounding of the floats' arithmetic (2/3 as 0.66...67 in the solution) is what remains
    if (q < 0 && P.is_vector && !num::has_integral(out.residual)) {
        const double at_point = residual_ratio_at_point(out.residual, P.t);
        if (at_point >= 0 && at_point <= rounding_tolerance()) q = at_point;
    }
    if (q >= 0) {
        out.residual_zero = true;
        out.residual_seen_nonzero = false;
        out.rounding = std::max(out.rounding, q);
    }
}

// s^(m)(0) - X_m for m < M, each 0 exactly (or rounding-size with floats).
void check_initial_values(const cauchy_problem& P, const std::vector<ex>& d, bool floats, solution_check& out) {
    for (std::size_t m = 0; m < P.order(); ++m) {
        const ex at0 = d[m].subs(P.t == 0);
        ex diff = at0 - P.initial[m];
        bool zero = P.is_vector ? quasi_polynomial_residual_zero(diff, P.t) || equal(diff, 0) : is_zero_scalar(diff);
        if (!zero && floats) {
            // the scale of the rounding: the initial value and s^(m)(0); a zero initial value (v0 = 0)
            // has no size of its own: then the terms of s^(m), which cancel to it at t = 0
            const bool zero_value = P.is_vector ? equal(P.initial[m], 0) : is_zero_scalar(P.initial[m]);
            const double q = zero_value ? rounding_ratio(diff, {at0, d[m]}, P.t, P.is_vector)
                                        : rounding_ratio(diff, {at0, P.initial[m]}, P.t, P.is_vector);
            if (q >= 0) {
                zero = true;
                out.rounding = std::max(out.rounding, q);
            }
        }
        out.initial_differences.push_back(zero ? ex(0) : P.is_vector ? canonical(diff) : GiNaC::normal(diff));
        out.initial_ok = out.initial_ok && zero;
    }
}

// (issue 31) A problem or solution in the dual unit eps: the residual and the initial differences
// reduced modulo eps^2 (dual/dual.h), each part (primal, dual) decided as a real one.
bool dual_part_zero(const cauchy_problem& P, const ex& r, bool floats, solution_check& out) {
    if (r.is_zero()) return true;
    bool zero = false;
    if (!P.is_vector) zero = is_zero_scalar(r);
    else if (num::has_integral(r)) zero = integral_residual_zero(r);
    else if (quasi_polynomial_residual_zero(r, P.t)) zero = true;
    else if (nonzero_at_a_point(r, P.t)) out.residual_seen_nonzero = !floats;
    else zero = equal(r, 0);
    if (!zero && floats && P.is_vector) {  // rounding-size at the point (floats rounded once)
        const double q = residual_ratio_at_point(r, P.t);
        if (q >= 0 && q <= rounding_tolerance()) {
            out.residual_seen_nonzero = false;
            out.rounding = std::max(out.rounding, q);
            zero = true;
        }
    }
    return zero;
}

solution_check check_dual(const cauchy_problem& P, const ex& s) {
    solution_check out;
    const bool floats = problem_has_float(P) || has_float(s);
    const std::vector<ex> d = derivatives(P, s);
    const dual::dual_parts r = dual::parts(substituted(P, P.expression, d));
    const auto tidy = [&](const ex& e) { return P.is_vector ? canonical(e) : GiNaC::normal(e); };
    const bool primal = dual_part_zero(P, r.primal, floats, out);
    const bool dual = primal && dual_part_zero(P, r.dual, floats, out);
    out.residual_zero = primal && dual;
    if (out.residual_zero) out.residual_seen_nonzero = false;
    out.residual = out.residual_zero ? ex(0) : dual::make_dual(tidy(r.primal), tidy(r.dual));
    out.initial_ok = true;
    for (std::size_t m = 0; m < P.order(); ++m) {
        const dual::dual_parts i = dual::parts(d[m].subs(P.t == 0) - P.initial[m]);
        solution_check scratch;
        const bool zero = dual_part_zero(P, i.primal, floats, scratch) && dual_part_zero(P, i.dual, floats, scratch);
        out.rounding = std::max(out.rounding, scratch.rounding);
        out.initial_differences.push_back(zero ? ex(0) : dual::make_dual(tidy(i.primal), tidy(i.dual)));
        out.initial_ok = out.initial_ok && zero;
    }
    return out;
}

}  // namespace

solution_check check(const cauchy_problem& P, const ex& s) {
    if (dual::has_dual_unit(s) || P.dual_darboux || dual::has_dual_unit(P.expression) ||
        std::any_of(P.initial.begin(), P.initial.end(), [](const ex& x) { return dual::has_dual_unit(x); }))
        return check_dual(P, s);
    solution_check out;
    const std::vector<ex> d = derivatives(P, s);
    out.residual = substituted(P, P.expression, d);
    const operator_check::proof in_algebra = decide_residual(P, s, out);
    const bool floats = problem_has_float(P) || has_float(s);
    if (!out.residual_zero && floats) accept_rounding_residual(P, d, out);
    out.residual = out.residual_zero ? ex(0) : P.is_vector ? canonical(out.residual) : GiNaC::normal(out.residual);
    out.initial_ok = true;
    if (in_algebra.initial) {  // proved in the algebra of K with the residual
        out.initial_differences.assign(P.order(), ex(0));
        return out;
    }
    check_initial_values(P, d, floats, out);
    return out;
}

}  // namespace symrep::mechanics
