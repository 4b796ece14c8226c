// symrep/mechanics/cauchy_problem.cpp
#include "mechanics/cauchy_problem.h"
#include "mechanics/fixed_axis.h"
#include "mechanics/turning_frame.h"
#include "mechanics/quasi_polynomial.h"
#include "mechanics/solution_witness.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <set>

#include <cln/rational.h>
#include <cln/real.h>
#include <cln/complex.h>

#include "scalar/scalar.h"
#include "core/error.h"
#include "vector/vector.h"

namespace symrep::mechanics {

using GiNaC::ex;

namespace {

using vmap = std::map<ex, ex, GiNaC::ex_is_less>;

// e as the printer writes it (1/(w0 - 2), not GiNaC's (-2+w0)^(-1)), cut for a message
std::string text(const ex& e) {
    std::string s = to_string(e);
    return s.size() > 200 ? s.substr(0, 197) + "..." : s;
}

bool has_any(const ex& e, const std::vector<ex>& syms) {
    for (const ex& s : syms)
        if (e.has(s)) return true;
    return false;
}

// E with the unknowns in `zero` replaced by 0.
ex without(const cauchy_problem& P, const ex& e, const std::vector<std::size_t>& zero) {
    if (P.is_vector) {
        vmap m;
        for (std::size_t k : zero) m[P.unknowns[k]] = 0;
        return subs_vectors(e, m);
    }
    GiNaC::exmap m;
    for (std::size_t k : zero) m[P.unknowns[k]] = 0;
    return e.subs(m);
}

void require_vector_symbol(const ex& v, const cauchy_problem& P, std::size_t m) {
    if (!is_vector_symbol(v))
        throw domain_error("the operator acting on " + P.unknown_name(m) + " involves " + to_string(v) +
                           ", which is not a vector symbol: declare it with 'vector' and give its "
                           "components as values when evaluating");
}

// The axis w: the first vector acting on an unknown; every later one must equal it.
void set_axis(ex& axis, const ex& v, const cauchy_problem& P, std::size_t m) {
    require_vector_symbol(v, P, m);
    if (axis.is_zero()) {
        axis = v;
    } else if (!(axis - v).is_zero()) {
        throw domain_error("both " + to_string(axis) + " x and " + to_string(v) + " x act on the unknowns: "
                           "the solver needs the operators to be polynomials in one K = w x");
    }
}

// A_m(K) from the part L of E that is linear in u = x^(m): terms c u, c (w x u),
// c (w . u) w  (= c K^2 u + c |w|^2 u). `Wsq` collects the |w|^2 coefficients;
// the cross terms are summed into `cross` (c (a x u) + d (b x u) = (c a + d b) x u),
// whose vector the caller makes the axis, and A[1] is left to it.
void read_operator(const cauchy_problem& P, std::size_t m, const ex& L, ex& axis, operator_polynomial& A,
                   ex& Wsq, ex& cross) {
    const ex u = P.unknowns[m];
    A.assign(3, ex(0));
    if (!P.is_vector) {
        const ex a = GiNaC::normal(L.diff(ex_to<GiNaC::symbol>(u)));
        if (has_any(a, P.unknowns) || !is_zero_scalar(L - a * u))
            throw domain_error("the equation is not linear in " + P.unknown_name(m) + ": " + text(L));
        A[0] = a;
        return;
    }
    for (const vector_term& term : canonical_terms(L)) {
        const ex& mono = term.monomial;
        const ex& c = term.coefficient;
        if ((mono - u).is_zero()) {
            if (has_any(c, P.unknowns))
                throw domain_error("the equation is not linear in " + P.unknown_name(m) + ": term " +
                                   to_string(c * mono));
            A[0] += c;
        } else if (is_ex_the_function(mono, vcross) && (mono.op(0) == u || mono.op(1) == u)) {
            const bool first = mono.op(0) == u;  // u x v = -(v x u)
            const ex v = first ? mono.op(1) : mono.op(0);
            require_vector_symbol(v, P, m);
            if (has_any(c, P.unknowns))
                throw domain_error("the equation is not linear in " + P.unknown_name(m) + ": term " +
                                   to_string(c * mono));
            cross += (first ? -c : c) * v;
        } else if (is_vector_symbol(mono) && c.has(u)) {
            // c = k (w . u) with k free of u
            const GiNaC::symbol z;
            const ex cz = GiNaC::expand(c.subs(dot(mono, u) == z));
            const ex k = GiNaC::normal(cz.diff(z));
            if (cz.has(u) || k.has(z) || !is_zero_scalar(cz.subs(z == 0)) || has_any(k, P.unknowns))
                throw domain_error("the term " + to_string(c * mono) + " is not of the form k (w . " +
                                   P.unknown_name(m) + ") w");
            set_axis(axis, mono, P, m);
            A[2] += k;
            Wsq += k;  // k w (w . u) = k K^2 u + k |w|^2 u
        } else {
            throw domain_error("the term " + to_string(c * mono) + " of the equation is not a polynomial in "
                               "w x applied to " + P.unknown_name(m) + " (terms must read c " + P.unknown_name(m) +
                               ", c w x " + P.unknown_name(m) + ", c w x (w x " + P.unknown_name(m) +
                               ") or c (w . " + P.unknown_name(m) + ") w)");
        }
    }
}

// The scalar coefficient of the vector symbol v in c = sum_j c_j a_j.
ex coefficient_of(const ex& c, const ex& v) {
    ex k = 0;
    for (const vector_term& term : canonical_terms(c))
        if (term.monomial.is_equal(v)) k += term.coefficient;
    return k;
}

// sum_j c_j a_j / k with each coefficient normalized: (q B + 2 m w)/m = q/m B + 2 w.
ex combination_over(const ex& c, const ex& k) {
    ex out = 0;
    for (const vector_term& term : canonical_terms(c)) out += GiNaC::normal(term.coefficient / k) * term.monomial;
    return out;
}

// The axis from the cross terms c_m = sum_j c_mj a_j of each order m (c_m x x^(m)).
// One vector a in all of them (with or without (a . u) a terms, `squares`): K = a x
// and A_m[1] = c_m / a. Several vectors (the Lorentz force q v x B next to the
// Coriolis term 2 m w x v): their sum is one vector, and if the cross terms of
// every order are multiples of one combination W = c_m0 / k (k: the leading
// coefficient of the equation, so that W reads q/m B + 2 w), K = W x: the
// operators are polynomials in one K and the general theorems apply as they are.
void set_cross_axis(const cauchy_problem& P, const std::vector<ex>& cross, bool squares,
                    std::vector<operator_polynomial>& A, ex& axis) {
    std::vector<ex> vs;
    for (const ex& c : cross)
        for (const ex& v : vector_symbols(c))
            if (std::find_if(vs.begin(), vs.end(), [&](const ex& x) { return x.is_equal(v); }) == vs.end())
                vs.push_back(v);
    if (vs.empty()) return;
    if (vs.size() == 1 || squares) {  // one vector (squares: (w . u) w terms have set it; all must agree)
        for (std::size_t m = 0; m < cross.size(); ++m) {
            if (cross[m].is_zero()) continue;
            const std::vector<ex> here = vector_symbols(cross[m]);
            for (const ex& v : here) set_axis(axis, v, P, m);
            A[m][1] += GiNaC::normal(cross[m] / axis);
        }
        return;
    }
    std::size_t m0 = 0;
    while (cross[m0].is_zero()) ++m0;
    for (const vector_term& term : canonical_terms(cross[m0]))
        if (term.coefficient.has(P.t))  // t (B x r) + w x r: the axis would turn with t
            throw domain_error("the coefficient " + text(term.coefficient) + " of " + to_string(term.monomial) +
                               " x " + P.unknown_name(m0) + " depends on " + text(P.t) +
                               ": only constant coefficients are solved");
    const ex& lead = A.back()[0];
    const bool scalar_lead = !lead.is_zero() && A.back()[1].is_zero() && A.back()[2].is_zero();
    const ex k = scalar_lead && m0 != A.size() - 1 ? lead : ex(1);
    axis = combination_over(cross[m0], k);
    for (std::size_t m = 0; m < cross.size(); ++m) {
        if (cross[m].is_zero()) continue;
        // c_m = lambda W: lambda from the coefficient of one vector, then checked on all
        const ex lambda = GiNaC::normal(coefficient_of(cross[m], vs[0]) / coefficient_of(axis, vs[0]));
        if (lambda.is_zero() || !equal(cross[m], lambda * axis))
            throw domain_error("the cross products acting on " + P.unknown_name(m0) + " and " +
                               P.unknown_name(m) + " are along different vectors (" + to_string(axis) + " and " +
                               to_string(cross[m]) + "): the solver needs the operators to be polynomials in one "
                               "K = w x");
        A[m][1] += lambda;
    }
}

quasi_polynomial forcing_coefficient(const ex& c, const ex& t, const ex& v) {
    try {
        return quasi_polynomial::from_ex(c, t);
    } catch (const domain_error& e) {
        throw domain_error("the free term " + (v.is_equal(1) ? text(c) : to_string(c * v)) +
                           " is not a quasi-polynomial in " + text(t) + " times a constant vector (" +
                           e.what() + ")");
    }
}

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

// Floating-point numbers replaced by the exact rationals they denote (a float is
// an exact binary number): the solver then derives with rationals, decides signs
// and zeros exactly, and solve() rounds the exact solution once at the end.
// (Deriving in floats left -1.69e-21*I in a real solution.)
ex exact_floats(const ex& e) {
    struct exact : GiNaC::map_function {
        ex operator()(const ex& x) override {
            if (GiNaC::is_a<GiNaC::numeric>(x)) {
                const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(x);
                if (n.is_crational()) return x;
                const cln::cl_N z = n.to_cl_N();
                return GiNaC::numeric(cln::complex(cln::rational(cln::realpart(z)), cln::rational(cln::imagpart(z))));
            }
            return x.map(*this);
        }
    } f;
    return f(e);
}

bool problem_has_float(const cauchy_problem& P) {
    return has_float(P.expression) || std::any_of(P.initial.begin(), P.initial.end(), has_float);
}

}  // namespace

// The first additive term of E in which an unknown stands where the equation is not
// polynomial in it (under a negative or fractional power, inside a function other
// than the vector products): k r/|r|^3, sin(r), 1/y. Such a term makes the problem
// nonlinear; substituting 0 for the unknowns (as reduce() does) would divide by 0.
std::optional<ex> nonlinear_term(const cauchy_problem& P) {
    auto bad = [&](const ex& e) {
        for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
            const ex& x = *it;
            if (GiNaC::is_a<GiNaC::power>(x) && has_any(x.op(0), P.unknowns) &&
                !(GiNaC::is_a<GiNaC::numeric>(x.op(1)) && GiNaC::ex_to<GiNaC::numeric>(x.op(1)).is_pos_integer()))
                return true;
            if (GiNaC::is_a<GiNaC::function>(x) && !is_ex_the_function(x, vcross) && !is_ex_the_function(x, vdot) &&
                !is_ex_the_function(x, vtriple) && has_any(x, P.unknowns))
                return true;
        }
        return false;
    };
    const ex& E = P.expression;
    for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(E) ? E.nops() : 1); ++i) {
        const ex term = GiNaC::is_a<GiNaC::add>(E) ? E.op(i) : E;
        if (bad(term)) return term;
    }
    return std::nullopt;
}

operator_form reduce(const cauchy_problem& P) {
    // a vector declared as a function of t (vector w(t)) is not a constant coefficient
    for (const ex& v : vector_symbols(P.expression)) {
        if (std::any_of(P.unknowns.begin(), P.unknowns.end(), [&](const ex& u) { return u.is_equal(v); })) continue;
        if (!diff_t(v, P.t).is_zero())
            throw domain_error("the vector " + text(v) + " is a function of " + text(P.t) +
                               ": the coefficient it is in depends on " + text(P.t));
    }
    if (const auto term = nonlinear_term(P)) {
        const std::string t = text(*term);
        // (a central field f(|r|) r/|r| in the rotating-frame form never gets here: ode() reads it
        // by turning_frame.h when this fails)
        throw domain_error("the term " + t + " is not linear in " + P.name +
                           ": ode() solves linear problems, and nonlinear ones of the form m (r'' + 2 w x r' + "
                           "w' x r + w x (w x r)) + m f(|r|) r/|r| = 0 with a central field (a function of |r| "
                           "only; Thm VI.3.2.1)");
    }
    if (problem_has_float(P)) {
        cauchy_problem Q = P;
        Q.expression = exact_floats(P.expression);
        for (ex& x : Q.initial) x = exact_floats(x);
        Q.reduced = nullptr;
        return reduce(Q);
    }
    if (P.is_vector) {
        // constant literal vectors acting on the unknowns (r' + [0, 0, 1] x r): each is
        // named by a vector symbol for the derivation, and its components are put back
        // into the form (the axis, |w|, the data vectors)
        GiNaC::exmap named, back;
        for (auto it = P.expression.preorder_begin(); it != P.expression.preorder_end(); ++it) {
            if (!is_ex_the_function(*it, vcross) && !is_ex_the_function(*it, vdot)) continue;
            for (int k = 0; k < 2; ++k) {
                const ex L = it->op(k), other = it->op(1 - k);
                if (!is_vector_literal(L) || L.has(P.t) || has_any(L, P.unknowns) || !has_any(other, P.unknowns) ||
                    named.count(L))
                    continue;
                const ex w = vector_symbol("literal_vector_" + std::to_string(named.size() + 1));
                named[L] = w;
                back[w] = L;
            }
        }
        if (!named.empty()) {
            cauchy_problem Q = P;
            Q.expression = P.expression.subs(named, GiNaC::subs_options::no_pattern);
            Q.reduced = nullptr;
            operator_form out = reduce(Q);
            out.axis = out.axis.subs(back, GiNaC::subs_options::no_pattern);
            for (auto& d : out.data) d.second = d.second.subs(back, GiNaC::subs_options::no_pattern);
            for (auto& Am : out.ode.A)
                for (ex& a : Am) a = a.subs(back, GiNaC::subs_options::no_pattern);
            // a numeric axis has a known |w|: the derivation uses its value (decided
            // signs: w x (w x r) + r with |w|^2 = 2 is hyperbolic, not cos(sqrt(1 - sqrt(2)) ...))
            if (GiNaC::is_a<GiNaC::symbol>(out.Omega) && is_vector_literal(out.axis)) {
                bool numeric = true;
                for (std::size_t k = 0; k < 3; ++k)
                    numeric = numeric && GiNaC::is_a<GiNaC::numeric>(out.axis.op(k));
                if (numeric) {
                    const ex W = canonical_radicals(norm(out.axis));
                    if (!W.is_zero()) {
                        for (auto& Am : out.ode.A)
                            for (ex& a : Am) a = tidy(a.subs(out.Omega == W));
                        for (auto& f : out.ode.forcing)
                            if (f.q.to_ex().has(out.Omega))
                                f.q = quasi_polynomial::from_ex(tidy(f.q.to_ex().subs(out.Omega == W)), P.t);
                        out.Omega = W;
                    }
                }
            }
            return out;
        }
    }
    const std::size_t M = P.order();
    if (M == 0) throw domain_error("the equation has no derivative of " + P.name);
    if (P.initial.size() != M)
        throw domain_error("an equation of order " + std::to_string(M) + " needs " + std::to_string(M) +
                           " initial conditions, " + P.name + "(0) .. " + P.unknown_name(M - 1) + "(0); got " +
                           std::to_string(P.initial.size()));
    std::vector<std::size_t> all(M + 1);
    for (std::size_t m = 0; m <= M; ++m) all[m] = m;
    const ex f = without(P, P.expression, all);

    operator_form out;
    out.axis = 0;
    std::vector<operator_polynomial> A(M + 1);
    std::vector<ex> Wsq(M + 1, ex(0)), cross(M + 1, ex(0));
    ex linear_sum = 0;
    for (std::size_t m = 0; m <= M; ++m) {
        std::vector<std::size_t> others;
        for (std::size_t k = 0; k <= M; ++k)
            if (k != m) others.push_back(k);
        const ex L = without(P, P.expression, others) - f;
        linear_sum += L;
        read_operator(P, m, L, out.axis, A[m], Wsq[m], cross[m]);
    }
    set_cross_axis(P, cross, !out.axis.is_zero(), A, out.axis);
    for (std::size_t m = 0; m <= M; ++m)
        for (const ex& a : A[m])
            if (a.has(P.t))
                throw domain_error("the coefficient " + text(a) + " of " + P.unknown_name(m) +
                                   " depends on " + text(P.t) + ": only constant coefficients are solved");
    // E = f + sum_m L_m exactly, i.e. no products of unknowns
    const ex rest = P.expression - f - linear_sum;
    if (P.is_vector ? !equal(rest, 0) : !is_zero_scalar(rest))
        throw domain_error("the equation is not linear in " + P.name + " and its derivatives");
    if (A[M][0].is_zero() && A[M][1].is_zero() && A[M][2].is_zero())
        throw domain_error("the coefficient of " + P.unknown_name(M) + " is 0");

    // |w| as a positive symbol in the operator algebra; |w|^2 = w . w
    if (!out.axis.is_zero()) {
        out.Omega = GiNaC::possymbol("|" + to_string(out.axis) + "|");
        const ex w2 = dot(out.axis, out.axis);
        for (std::size_t m = 0; m <= M; ++m) {
            A[m][0] += Wsq[m] * w2;
            for (ex& a : A[m]) a = GiNaC::normal(a.subs(w2 == GiNaC::pow(out.Omega, 2)));
        }
    } else {
        out.Omega = 0;
    }
    out.ode.A = A;

    for (std::size_t m = 0; m < M; ++m) {
        const std::string nm = P.unknown_name(m) + "(0)";
        out.ode.initial.push_back(nm);
        out.data.emplace_back(nm, P.initial[m]);
    }
    // the free part, moved to the right side: sum q_j(t) F_j
    const ex F = -f;
    const ex w2 = out.axis.is_zero() ? ex(0) : dot(out.axis, out.axis);
    auto add_forcing = [&](const ex& c, const ex& v) {
        const ex cc = out.axis.is_zero() ? c : c.subs(w2 == GiNaC::pow(out.Omega, 2));
        const std::string nm = "F" + std::to_string(out.ode.forcing.size());
        out.ode.forcing.push_back({forcing_coefficient(cc, P.t, v), 0, nm});
        out.data.emplace_back(nm, v);
    };
    if (!P.is_vector) {
        if (!F.is_zero()) add_forcing(GiNaC::expand(F), 1);
    } else {
        for (const vector_term& term : canonical_terms(F)) {
            if (has_any(term.coefficient, P.unknowns))
                throw domain_error("the equation is not linear in " + P.name + ": term " +
                                   to_string(term.coefficient * term.monomial));
            if (is_vector_literal(term.monomial)) {  // split a literal into components
                for (unsigned k = 0; k < 3; ++k) {
                    const ex ck = GiNaC::expand(term.coefficient * term.monomial.op(k));
                    if (!ck.is_zero())
                        add_forcing(ck, vector_literal(k == 0 ? 1 : 0, k == 1 ? 1 : 0, k == 2 ? 1 : 0));
                }
            } else {
                add_forcing(term.coefficient, term.monomial);
            }
        }
    }
    return out;
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
    const ex x = solve_unwitnessed(P);
    require_witness(P, x);  // (issue 27) never a result that its residual at a point sees wrong
    return x;
}

ex solve_unwitnessed(const cauchy_problem& P) {
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
    const ex x = vector_solution(P, F, solve(F.ode, R, P.t));
    // derived exactly from the rationals the floats denote (reduce), rounded once here
    return problem_has_float(P) ? GiNaC::evalf(x) : x;
}

double rounding_tolerance() { return std::pow(10.0, 5 - long(GiNaC::Digits)); }

namespace {

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
    }
    if (r == 0) return 0;
    return scale > 0 && r <= rounding_tolerance() * scale ? r / scale : -1;
}

}  // namespace

namespace {

bool has_integral(const ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::integral>(*it)) return true;
    return false;
}

// (linearity) sum_i c_i int_a^b f_i dtau -> int_a^b (sum_i c_i f_i) dtau for the c_i free of
// tau: the integral objects of a solution (fixed_axis.h) meet in its residual as several
// integrals over the same range, which cancel only as one.
ex merge_integrals(const ex& e) {
    const ex x = GiNaC::expand(e);
    std::vector<std::pair<ex, ex>> groups;  // (integral with integrand 1 as the key, sum of c_i f_i)
    ex rest = 0;
    for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(x) ? x.nops() : 1); ++i) {
        const ex term = GiNaC::is_a<GiNaC::add>(x) ? x.op(i) : x;
        ex I;  // the one integral factor of term
        std::size_t count = 0;
        const std::size_t n = GiNaC::is_a<GiNaC::mul>(term) ? term.nops() : 1;
        for (std::size_t j = 0; j < n; ++j) {
            const ex f = GiNaC::is_a<GiNaC::mul>(term) ? term.op(j) : term;
            if (GiNaC::is_a<GiNaC::integral>(f)) {
                I = f;
                ++count;
            } else if (has_integral(f)) {
                count = 2;
            }
        }
        if (count != 1 || I.op(0).is_equal(0)) {
            rest += term;
            continue;
        }
        const ex c = term / I;
        if (c.has(I.op(0))) {
            rest += term;
            continue;
        }
        const ex key = GiNaC::lst{I.op(0), I.op(1), I.op(2)};
        auto g = std::find_if(groups.begin(), groups.end(), [&](const auto& p) { return p.first.is_equal(key); });
        if (g == groups.end()) groups.push_back({key, c * I.op(3)});
        else g->second += c * I.op(3);
    }
    for (const auto& [key, f] : groups) {
        const ex F = GiNaC::normal(GiNaC::expand(f));
        if (!F.is_zero()) rest += GiNaC::integral(key.op(0), key.op(1), key.op(2), F);
    }
    return rest;
}

// sin(A), cos(A) as sin, cos of a fresh symbol per argument A (the angle a(t) of a rate
// a + b sin(c t), w0 t, w0 tau). Sound for a zero proof: what vanishes for every value of
// the symbols vanishes at the arguments. The residual of a Duhamel integral needs only
// sin^2 + cos^2 = 1 per argument (G(t - tau) is split by the addition theorems), and the
// zero test then works with a few independent angles instead of exponentials of each.
ex atomize_trig_arguments(const ex& e) {
    // the outermost sin and cos (those inside another one's argument go with it)
    std::vector<ex> outer;
    std::function<void(const ex&)> collect = [&](const ex& x) {
        if (is_ex_the_function(x, GiNaC::sin) || is_ex_the_function(x, GiNaC::cos)) {
            if (!GiNaC::is_a<GiNaC::numeric>(x.op(0))) outer.push_back(x);
            return;
        }
        for (std::size_t i = 0; i < x.nops(); ++i) collect(x.op(i));
    };
    collect(e);
    std::vector<std::pair<ex, ex>> args;  // expanded argument -> symbol
    GiNaC::exmap sub;
    for (const ex& f : outer) {
        const ex A = GiNaC::expand(f.op(0));
        ex alpha;
        int sign = 1;
        for (const auto& [k, sym] : args) {
            if (k.is_equal(A)) alpha = sym;
            else if (GiNaC::expand(k + A).is_zero()) alpha = sym, sign = -1;
            if (!alpha.is_zero()) break;
        }
        if (alpha.is_zero()) {
            alpha = GiNaC::realsymbol("alpha" + std::to_string(args.size()));
            args.push_back({A, alpha});
        }
        sub[f] = is_ex_the_function(f, GiNaC::sin) ? sign * GiNaC::sin(alpha) : GiNaC::cos(alpha);
    }
    return sub.empty() ? e : e.subs(sub, GiNaC::subs_options::no_pattern);
}

// The bound variables of the integral objects renamed by nesting depth (tau_0 for an integral
// without one inside, tau_1 around those, ...): int_0^t g(tau) dtau and int_0^t g(sigma) dsigma,
// which meet in a residual when a nested integral is differentiated, become one object.
int integral_depth(const ex& e) {
    int d = -1;
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::integral>(*it)) d = std::max(d, 1 + integral_depth(it->op(3)));
    return d;
}

ex canonical_bound_variables(const ex& e) {
    if (!has_integral(e)) return e;
    if (GiNaC::is_a<GiNaC::integral>(e) && GiNaC::is_a<GiNaC::symbol>(e.op(0))) {
        static std::vector<ex> names;
        const ex f = canonical_bound_variables(e.op(3));
        const std::size_t d = std::size_t(1 + integral_depth(f));
        while (names.size() <= d) names.push_back(GiNaC::realsymbol("tau_" + std::to_string(names.size())));
        return GiNaC::integral(names[d], e.op(1), e.op(2), f.subs(e.op(0) == names[d]));
    }
    struct recurse : GiNaC::map_function {
        ex operator()(const ex& c) override { return canonical_bound_variables(c); }
    } inner;
    return e.map(inner);
}

// (issue 15.2) A vector residual proved 0 coordinate-free: each coefficient of its canonical
// form, with |v| a positive symbol (|v|^2 for v . v), a quasi-polynomial in t that is the zero
// function (quasi_polynomial's canonical form: t^k e^(lambda t) for distinct (k, lambda) are
// independent, each coefficient by the scalar zero test). Sound: an identity in independent
// symbols holds at |v|; when a coefficient is not read or not proved 0, nothing is concluded
// (the canonical form is not unique with four vectors or more) and the caller decides by
// components, which with |w| = sqrt(w1^2 + w2^2 + w3^2) cost 100 times the derivation.
bool quasi_polynomial_residual_zero(const ex& r, const ex& t) {
    try {
        for (const vector_term& term : canonical_terms(r)) {
            // |v| a positive symbol (|v|^2 for v . v), the other dot and triple products independent
            // real symbols
            GiNaC::exmap atoms;
            std::size_t count = 0;
            std::function<void(const ex&)> scan = [&](const ex& x) {
                if (atoms.count(x)) return;
                if (is_ex_the_function(x, vdot) || is_ex_the_function(x, vtriple)) {
                    if (is_ex_the_function(x, vdot) && x.op(0).is_equal(x.op(1))) {
                        const GiNaC::possymbol n("|v" + std::to_string(count++) + "|");
                        atoms[x] = GiNaC::pow(n, 2);
                        atoms[GiNaC::sqrt(x)] = n;
                    } else {
                        atoms[x] = GiNaC::realsymbol("d" + std::to_string(count++));
                    }
                    return;
                }
                for (std::size_t i = 0; i < x.nops(); ++i) scan(x.op(i));
            };
            scan(term.coefficient);
            const ex c = term.coefficient.subs(atoms, GiNaC::subs_options::no_pattern);
            if (!vector_symbols(c).empty()) return false;  // a vector left where no atom was read
            if (!quasi_polynomial::from_ex(c, t).is_zero()) return false;
        }
    } catch (const domain_error&) {
        return false;
    }
    return true;
}

// (issue 15.2) The check in the algebra of K = w x (VI.1.21-22, 26-38): s read exactly as
//     s = sum_v [ c0_v(t) v + c1_v(t) K v + c2_v(t) K^2 v ]
// over the vector symbols v of the problem's data (K^2 v = w (w . v) - |w|^2 v), each c_k a
// quasi-polynomial in t, and the residual  sum_m A_m(K) s^(m) - sum_j q_j K^(k_j) F_j  computed
// on those coefficients (derivatives and products by K^3 = -|w|^2 K in quasi_polynomial
// arithmetic), each coefficient decided by the scalar zero test. All coefficients 0 proves the
// residual 0 (it is their combination); otherwise, or when s is not of that form (another
// vector, a literal, a coefficient not a quasi-polynomial), nothing is concluded and the caller
// tests the vector residual. Costs a few derivations where expanding the vector residual cost
// 15 (t e^-t cos 2t forcing).
namespace operator_check {

using triple = std::array<quasi_polynomial, 3>;

// a_v v + b_v (w x v) per vector symbol v
struct reading {
    vmap a, b;
};

void add_into(reading& x, const reading& y, const ex& scale) {
    for (const auto& [v, c] : y.a) x.a[v] += scale * c;
    for (const auto& [v, c] : y.b) x.b[v] += scale * c;
}

// K applied to a reading: v -> w x v, w x v -> w (w . v) - v (w . w)
reading apply_K(const reading& y, const ex& w) {
    reading x;
    for (const auto& [v, c] : y.a)
        if (!v.is_equal(w)) x.b[v] += c;
    for (const auto& [v, c] : y.b) {
        if (v.is_equal(w)) continue;
        x.a[w] += c * dot(w, v);
        x.a[v] -= c * dot(w, w);
    }
    return x;
}

// c when y is c w exactly (structurally), nullopt otherwise
std::optional<ex> multiple_of(const reading& y, const ex& w) {
    if (!y.b.empty() || y.a.size() != 1 || !y.a.begin()->first.is_equal(w)) return std::nullopt;
    return y.a.begin()->second;
}

std::optional<reading> read(const ex& e, const ex& w) {
    reading x;
    if (is_vector_symbol(e)) {
        x.a[e] = 1;
        return x;
    }
    if (GiNaC::is_a<GiNaC::add>(e)) {
        for (std::size_t i = 0; i < e.nops(); ++i) {
            const auto y = read(e.op(i), w);
            if (!y) return std::nullopt;
            add_into(x, *y, 1);
        }
        return x;
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
        ex scale = 1;
        std::optional<ex> vec;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            if (!is_vector(e.op(i))) {
                scale *= e.op(i);
            } else if (!vec) {
                vec = e.op(i);
            } else {
                return std::nullopt;  // a vector in two factors (a dot product times a vector, say)
            }
        }
        if (!vec) return std::nullopt;
        const auto y = read(*vec, w);
        if (!y) return std::nullopt;
        add_into(x, *y, scale);
        return x;
    }
    if (is_ex_the_function(e, vcross) && !w.is_zero()) {
        const auto l = read(e.op(0), w), r = read(e.op(1), w);
        if (!l || !r) return std::nullopt;
        if (const auto c = multiple_of(*l, w)) {  // (c w) x y = c K y
            add_into(x, apply_K(*r, w), *c);
            return x;
        }
        if (const auto c = multiple_of(*r, w)) {  // y x (c w) = -c K y
            add_into(x, apply_K(*l, w), -*c);
            return x;
        }
    }
    return std::nullopt;
}

// The coefficients (c0, c1, c2) of s on each data vector symbol, |w| as Omega, into out; false
// when s is not read so.
bool coefficients(const cauchy_problem& P, const operator_form& F, const ex& s,
                                 std::map<ex, triple, GiNaC::ex_is_less>& out) {
    const ex& w = F.axis;
    if (!w.is_zero() && (!is_vector_symbol(w) || !GiNaC::is_a<GiNaC::symbol>(F.Omega))) return false;
    std::set<ex, GiNaC::ex_is_less> data;
    for (const auto& [name, v] : F.data) {
        if (v.is_zero()) continue;  // x(0) = 0
        if (!is_vector_symbol(v) || v.is_equal(w)) return false;
        data.insert(v);
    }
    const auto x = read(s, w);
    if (!x) return false;
    // |w| -> Omega, w . v -> d_v (fresh), then every coefficient free of vectors
    GiNaC::exmap to_omega;
    vmap d;
    if (!w.is_zero()) {
        to_omega[dot(w, w)] = GiNaC::pow(F.Omega, 2);
        for (const ex& v : data) d[v] = GiNaC::realsymbol("d_" + to_string(v));
    }
    GiNaC::exmap to_d = to_omega;
    for (const auto& [v, s_v] : d) to_d[dot(w, v)] = s_v;
    auto scalar = [&](const ex& c) -> std::optional<ex> {
        const ex y = c.subs(to_omega, GiNaC::subs_options::no_pattern);
        if (!vector_symbols(y).empty()) return std::nullopt;
        return y;
    };
    std::map<ex, std::array<ex, 3>, GiNaC::ex_is_less> c;
    for (const ex& v : data) c[v] = {0, 0, 0};
    for (const auto& [v, a] : x->a) {
        if (v.is_equal(w)) continue;
        if (!data.count(v)) return false;
        const auto y = scalar(a);
        if (!y) return false;
        c[v][0] += *y;
    }
    for (const auto& [v, b] : x->b) {
        if (!data.count(v)) return false;
        const auto y = scalar(b);
        if (!y) return false;
        c[v][1] += *y;
    }
    if (const auto it = x->a.find(w); it != x->a.end()) {
        // a_w = sum_v c2_v (w . v), linear in the d_v with nothing else
        const ex aw = it->second.subs(to_d, GiNaC::subs_options::no_pattern);
        if (!vector_symbols(aw).empty()) return false;
        GiNaC::exmap none;
        for (const auto& [v, s_v] : d) none[s_v] = 0;
        if (!aw.subs(none, GiNaC::subs_options::no_pattern).is_zero()) return false;
        for (const auto& [v, s_v] : d) {
            const ex c2 = aw.diff(GiNaC::ex_to<GiNaC::symbol>(s_v));
            for (const auto& [u, s_u] : d)
                if (c2.has(s_u)) return false;
            c[v][2] += c2;
            c[v][0] += GiNaC::pow(F.Omega, 2) * c2;
        }
    }
    try {
        for (const auto& [v, k] : c)
            out[v] = {quasi_polynomial::from_ex(k[0], P.t), quasi_polynomial::from_ex(k[1], P.t),
                      quasi_polynomial::from_ex(k[2], P.t)};
    } catch (const domain_error&) {
        return false;
    }
    return true;
}

// What the check in the algebra proved: the residual 0, the initial values right.
struct proof {
    bool residual = false, initial = false;
};

proof prove(const cauchy_problem& P, const ex& s) {
    if (!P.is_vector || P.fixed_axis || P.turning || P.velocity) return {};
    try {
        const operator_form F = P.reduced ? *P.reduced : reduce(P);
        std::map<ex, triple, GiNaC::ex_is_less> G;
        if (!coefficients(P, F, s, G)) return {};
        const ex W2 = GiNaC::pow(F.Omega, 2);
        auto K = [&](const triple& c) { return triple{quasi_polynomial(), c[0] - W2 * c[2], c[1]}; };
        const std::map<std::string, ex> data(F.data.begin(), F.data.end());
        const std::size_t M = F.ode.A.size() - 1;
        proof out{true, true};
        for (const auto& [v, g] : G) {
            triple lhs{}, Gm = g;
            for (std::size_t m = 0; m <= M; ++m) {
                if (m < M) {  // s^(m)(0) = x^(m)(0) on v
                    const bool here = data.at(F.ode.initial[m]).is_equal(v);
                    for (int k = 0; k < 3; ++k) {  // the zero proof of normalize(); else the caller tests
                        const cex at0 = Gm[k].at_zero_untidied();
                        out.initial = out.initial && proved_zero_by_denominators(at0.re - (here && k == 0 ? 1 : 0)) &&
                                      proved_zero_by_denominators(at0.im);
                    }
                }
                triple KjG = Gm;  // A_m(K) s^(m)
                for (std::size_t j = 0; j < F.ode.A[m].size(); ++j) {
                    if (j) KjG = K(KjG);
                    for (int k = 0; k < 3; ++k) lhs[k] = lhs[k] + F.ode.A[m][j] * KjG[k];
                }
                for (int k = 0; k < 3; ++k) Gm[k] = Gm[k].derivative();
            }
            for (const forcing_term& f : F.ode.forcing) {
                if (!data.at(f.vector).is_equal(v)) continue;
                triple q{f.q, quasi_polynomial(), quasi_polynomial()};
                for (unsigned j = 0; j < f.power; ++j) q = K(q);
                for (int k = 0; k < 3; ++k) lhs[k] = lhs[k] - q[k];
            }
            for (const auto& r : lhs) out.residual = out.residual && r.is_zero();
            if (!out.residual) return {};
        }
        // an initial value or a forcing vector met in no coefficient of s
        for (std::size_t m = 0; m < M; ++m) {
            const ex& u = data.at(F.ode.initial[m]);
            out.initial = out.initial && (u.is_zero() || G.count(u));
        }
        for (const forcing_term& f : F.ode.forcing)
            if (!G.count(data.at(f.vector))) return {};
        return out;
    } catch (const type_error&) {  // a form the reading does not take: the caller decides
        return {};
    } catch (const domain_error&) {
        return {};
    }
}

}  // namespace operator_check

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
        for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::matrix>(c) ? c.nops() : 1); ++i) {
            const ex ci = GiNaC::expand((GiNaC::is_a<GiNaC::matrix>(c) ? c.op(i) : c).subs(point));
            GiNaC::numeric total = 0, size = 0;
            for (std::size_t j = 0; j < (GiNaC::is_a<GiNaC::add>(ci) ? ci.nops() : 1); ++j) {
                const ex v = GiNaC::evalf(GiNaC::is_a<GiNaC::add>(ci) ? ci.op(j) : ci);
                if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) return -1;
                total += GiNaC::ex_to<GiNaC::numeric>(v);
                size += GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(v));
            }
            if (size.is_zero()) continue;
            ratio = std::max(ratio, GiNaC::ex_to<GiNaC::numeric>(GiNaC::abs(total) / size).to_double());
        }
    } catch (const std::exception&) {
        return -1;
    }
    return ratio;
}

bool nonzero_at_a_point(const ex& r, const ex& t) { return residual_ratio_at_point(r, t) > 1e-20; }

// A vector residual with integral objects: 0 when each component, with fresh symbols for the
// vectors and the integrals merged, is 0.
bool integral_residual_zero(const ex& r0) {
    const ex r = canonical_bound_variables(r0);
    // coordinate-free first (fewer symbols: dot products and norms as atoms); the canonical
    // form is not unique with four vectors or more, so a coefficient left is not a proof of
    // anything: then by components
    bool all_zero = true;
    for (const vector_term& term : canonical_terms(r))
        if (!is_zero_scalar(atomize_trig_arguments(merge_integrals(term.coefficient)))) {
            all_zero = false;
            break;
        }
    if (all_zero) return true;
    vmap comps;
    for (const ex& v : vector_symbols(r)) {
        const std::string n = to_string(v);
        comps[v] = vector_literal(GiNaC::realsymbol(n + "_1"), GiNaC::realsymbol(n + "_2"), GiNaC::realsymbol(n + "_3"));
    }
    const ex c = subs_components(r, comps);
    for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::matrix>(c) ? c.nops() : 1); ++i)
        if (!is_zero_scalar(atomize_trig_arguments(merge_integrals(GiNaC::is_a<GiNaC::matrix>(c) ? c.op(i) : c))))
            return false;
    return true;
}

}  // namespace

solution_check check(const cauchy_problem& P, const ex& s) {
    solution_check out;
    operator_check::proof in_algebra;
    std::vector<ex> d{s};
    for (std::size_t m = 1; m <= P.order(); ++m)
        d.push_back(P.is_vector ? diff_t(d.back(), P.t) : d.back().diff(ex_to<GiNaC::symbol>(P.t)));
    if (P.is_vector) {
        vmap sub;
        for (std::size_t m = 0; m <= P.order(); ++m) sub[P.unknowns[m]] = d[m];
        out.residual = subs_vectors(P.expression, sub);
        if (has_integral(out.residual)) {
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
    } else {
        GiNaC::exmap sub;
        for (std::size_t m = 0; m <= P.order(); ++m) sub[P.unknowns[m]] = d[m];
        out.residual = P.expression.subs(sub);
        out.residual_zero = is_zero_scalar(out.residual);
    }
    const bool floats = has_float(P.expression) || has_float(s) ||
                        std::any_of(P.initial.begin(), P.initial.end(), has_float);
    if (!out.residual_zero && floats) {
        // the terms of E, each with the solution in: the residual is their sum
        const ex E = GiNaC::expand(P.expression);
        std::vector<ex> parts;
        for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(E) ? E.nops() : 1); ++i) {
            const ex term = GiNaC::is_a<GiNaC::add>(E) ? E.op(i) : E;
            if (P.is_vector) {
                vmap sub;
                for (std::size_t m = 0; m <= P.order(); ++m) sub[P.unknowns[m]] = d[m];
                parts.push_back(subs_vectors(term, sub));
            } else {
                GiNaC::exmap sub;
                for (std::size_t m = 0; m <= P.order(); ++m) sub[P.unknowns[m]] = d[m];
                parts.push_back(term.subs(sub));
            }
        }
        double q = rounding_ratio(out.residual, parts, P.t, P.is_vector);
        // with symbols left (q, m, E: no coefficient is a number), at the witness point: the
        // rounding of the floats' arithmetic (2/3 as 0.66...67 in the solution) is what remains
        if (q < 0 && P.is_vector && !has_integral(out.residual)) {
            const double at_point = residual_ratio_at_point(out.residual, P.t);
            if (at_point >= 0 && at_point <= rounding_tolerance()) q = at_point;
        }
        if (q >= 0) {
            out.residual_zero = true;
            out.residual_seen_nonzero = false;
            out.rounding = std::max(out.rounding, q);
        }
    }
    out.residual = out.residual_zero ? ex(0) : P.is_vector ? canonical(out.residual) : GiNaC::normal(out.residual);
    out.initial_ok = true;
    if (in_algebra.initial) {  // proved in the algebra of K with the residual
        out.initial_differences.assign(P.order(), ex(0));
        return out;
    }
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
    return out;
}

}  // namespace symrep::mechanics
