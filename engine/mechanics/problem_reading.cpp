// symrep/mechanics/problem_reading.cpp -- reading a Cauchy problem (cauchy_problem.h):
// reduce(), E read as sum_m A_m(K) x^(m) = sum_j q_j(t) F_j in the algebra of K = w x
// (thesis VI.1.26-38), and read_problem(), the reading made once when a problem is posed:
// that operator form, or a rotating frame about a fixed axis (fixed_axis.h, VI.2), a turning
// frame (turning_frame.h, VI.3), or the velocity problem v = x' (VI.2.50-52).
#include "symrep/mechanics/cauchy_problem.h"
#include "symrep/mechanics/dual_darboux.h"
#include "symrep/mechanics/fixed_axis.h"
#include "symrep/mechanics/turning_frame.h"
#include "symrep/mechanics/quasi_polynomial.h"

#include <algorithm>
#include <map>
#include <optional>

#include "symrep/scalar/scalar.h"
#include "symrep/core/error.h"
#include "symrep/numeric/quadrature.h"
#include "symrep/numeric/reference.h"
#include "symrep/vector/vector.h"

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

// A vector declared as a function of t (vector w(t)) is not a constant coefficient.
void require_constant_vectors(const cauchy_problem& P) {
    for (const ex& v : vector_symbols(P.expression)) {
        if (std::any_of(P.unknowns.begin(), P.unknowns.end(), [&](const ex& u) { return u.is_equal(v); })) continue;
        if (!diff_t(v, P.t).is_zero())
            throw domain_error("the vector " + text(v) + " is a function of " + text(P.t) +
                               ": the coefficient it is in depends on " + text(P.t));
    }
}

void require_linear(const cauchy_problem& P) {
    if (const auto term = nonlinear_term(P)) {
        const std::string t = text(*term);
        // (a central field f(|r|) r/|r| in the rotating-frame form never gets here: ode() reads it
        // by turning_frame.h when this fails)
        throw domain_error("the term " + t + " is not linear in " + P.name +
                           ": ode() solves linear problems, and nonlinear ones of the form m (r'' + 2 w x r' + "
                           "w' x r + w x (w x r)) + m f(|r|) r/|r| = 0 with a central field (a function of |r| "
                           "only; Thm VI.3.2.1)");
    }
}

// A numeric axis has a known |w|: the derivation uses its value (decided signs: w x (w x r) + r
// with |w|^2 = 2 is hyperbolic, not cos(sqrt(1 - sqrt(2)) ...)).
void put_numeric_norm(operator_form& out, const ex& t) {
    if (!GiNaC::is_a<GiNaC::symbol>(out.Omega) || !is_vector_literal(out.axis)) return;
    bool numeric = true;
    for (std::size_t k = 0; k < 3; ++k) numeric = numeric && GiNaC::is_a<GiNaC::numeric>(out.axis.op(k));
    if (!numeric) return;
    const ex W = canonical_radicals(norm(out.axis));
    if (W.is_zero()) return;
    for (auto& Am : out.ode.A)
        for (ex& a : Am) a = tidy(a.subs(out.Omega == W));
    for (auto& f : out.ode.forcing)
        if (f.q.to_ex().has(out.Omega)) f.q = quasi_polynomial::from_ex(tidy(f.q.to_ex().subs(out.Omega == W)), t);
    out.Omega = W;
}

// Constant literal vectors acting on the unknowns (r' + [0, 0, 1] x r): each is named by a
// vector symbol for the derivation, and its components are put back into the form (the axis,
// |w|, the data vectors). Nothing when there is none.
std::optional<operator_form> reduce_named_literals(const cauchy_problem& P) {
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
    if (named.empty()) return std::nullopt;
    cauchy_problem Q = P;
    Q.expression = P.expression.subs(named, GiNaC::subs_options::no_pattern);
    Q.reduced = nullptr;
    operator_form out = reduce(Q);
    out.axis = out.axis.subs(back, GiNaC::subs_options::no_pattern);
    for (auto& d : out.data) d.second = d.second.subs(back, GiNaC::subs_options::no_pattern);
    for (auto& g : out.general) g.second = g.second.subs(back, GiNaC::subs_options::no_pattern);
    for (auto& Am : out.ode.A)
        for (ex& a : Am) a = a.subs(back, GiNaC::subs_options::no_pattern);
    put_numeric_norm(out, P.t);
    return out;
}

void require_initial_values(const cauchy_problem& P) {
    const std::size_t M = P.order();
    if (M == 0) throw domain_error("the equation has no derivative of " + P.name);
    if (P.initial.size() != M)
        throw domain_error("an equation of order " + std::to_string(M) + " needs " + std::to_string(M) +
                           " initial conditions, " + P.name + "(0) .. " + P.unknown_name(M - 1) + "(0); got " +
                           std::to_string(P.initial.size()));
}

// A_0(K) .. A_M(K) from E with its free part f: each L_m = E(x^(m) only) - f read by
// read_operator, the axis set from the cross terms; `Wsq` receives the |w|^2 coefficients.
// Throws when a coefficient depends on t, when E is not the sum f + sum_m L_m (products of
// unknowns) or when A_M = 0.
std::vector<operator_polynomial> read_operators(const cauchy_problem& P, const ex& f, ex& axis, std::vector<ex>& Wsq) {
    const std::size_t M = P.order();
    std::vector<operator_polynomial> A(M + 1);
    std::vector<ex> cross(M + 1, ex(0));
    ex linear_sum = 0;
    for (std::size_t m = 0; m <= M; ++m) {
        std::vector<std::size_t> others;
        for (std::size_t k = 0; k <= M; ++k)
            if (k != m) others.push_back(k);
        const ex L = without(P, P.expression, others) - f;
        linear_sum += L;
        read_operator(P, m, L, axis, A[m], Wsq[m], cross[m]);
    }
    set_cross_axis(P, cross, !axis.is_zero(), A, axis);
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
    return A;
}

// |w| as a positive symbol in the operator algebra; |w|^2 = w . w
void put_norm(operator_form& out, std::vector<operator_polynomial>& A, const std::vector<ex>& Wsq) {
    if (out.axis.is_zero()) {
        out.Omega = 0;
        return;
    }
    out.Omega = GiNaC::possymbol("|" + to_string(out.axis) + "|");
    const ex w2 = dot(out.axis, out.axis);
    for (std::size_t m = 0; m < A.size(); ++m) {
        A[m][0] += Wsq[m] * w2;
        for (ex& a : A[m]) a = GiNaC::normal(a.subs(w2 == GiNaC::pow(out.Omega, 2)));
    }
}

// The free part f moved to the right side: -f = sum q_j(t) F_j, each F_j a data vector.
void read_forcing(const cauchy_problem& P, const ex& f, operator_form& out) {
    const ex F = -f;
    const ex w2 = out.axis.is_zero() ? ex(0) : dot(out.axis, out.axis);
    auto add_quasi_polynomial = [&](const ex& c, const ex& v) {
        const ex cc = out.axis.is_zero() ? c : c.subs(w2 == GiNaC::pow(out.Omega, 2));
        const std::string nm = "F" + std::to_string(out.ode.forcing.size());
        out.ode.forcing.push_back({forcing_coefficient(cc, P.t, v), 0, nm});
        out.data.emplace_back(nm, v);
    };
    // (VI.1.26-38 for every f) a coefficient that is not a quasi-polynomial: its quasi-polynomial
    // terms as before, the rest kept for its Duhamel integral (cauchy_solve.cpp), when finite
    // for every t >= 0
    auto add_forcing = [&](const ex& c, const ex& v) {
        try {
            add_quasi_polynomial(c, v);
            return;
        } catch (const domain_error&) {
        }
        const ex e = GiNaC::expand(c);
        ex rest = 0;
        for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1); ++i) {
            const ex term = GiNaC::is_a<GiNaC::add>(e) ? e.op(i) : e;
            try {
                quasi_polynomial::from_ex(term, P.t);
                add_quasi_polynomial(term, v);
            } catch (const domain_error&) {
                rest += term;
            }
        }
        const ex g = GiNaC::normal(rest);
        num::require_finite_on_half_line(g, P.t, "the free term " + (v.is_equal(1) ? text(g) : to_string(g * v)));
        out.general.emplace_back(g, v);
    };
    if (!P.is_vector) {
        if (!F.is_zero()) add_forcing(GiNaC::expand(F), 1);
        return;
    }
    for (const vector_term& term : canonical_terms(F)) {
        if (has_any(term.coefficient, P.unknowns))
            throw domain_error("the equation is not linear in " + P.name + ": term " +
                               to_string(term.coefficient * term.monomial));
        if (is_vector_literal(term.monomial)) {  // split a literal into components
            for (unsigned k = 0; k < 3; ++k) {
                const ex ck = GiNaC::expand(term.coefficient * term.monomial.op(k));
                if (!ck.is_zero()) add_forcing(ck, vector_literal(k == 0 ? 1 : 0, k == 1 ? 1 : 0, k == 2 ? 1 : 0));
            }
        } else {
            add_forcing(term.coefficient, term.monomial);
        }
    }
}

}  // namespace

bool problem_has_float(const cauchy_problem& P) {
    return has_float(P.expression) || std::any_of(P.initial.begin(), P.initial.end(), has_float);
}

operator_form reduce(const cauchy_problem& P) {
    require_constant_vectors(P);
    require_linear(P);
    // Floating-point numbers replaced by the exact rationals they denote (a float is an exact
    // binary number): the solver then derives with rationals, decides signs and zeros exactly,
    // and solve() rounds the exact solution once at the end. (Deriving in floats left
    // -1.69e-21*I in a real solution.)
    if (problem_has_float(P)) {
        cauchy_problem Q = P;
        Q.expression = num::exact_floats_of(P.expression);
        for (ex& x : Q.initial) x = num::exact_floats_of(x);
        Q.reduced = nullptr;
        return reduce(Q);
    }
    if (P.is_vector)
        if (auto out = reduce_named_literals(P)) return std::move(*out);
    require_initial_values(P);
    const std::size_t M = P.order();
    std::vector<std::size_t> all(M + 1);
    for (std::size_t m = 0; m <= M; ++m) all[m] = m;
    const ex f = without(P, P.expression, all);

    operator_form out;
    out.axis = 0;
    std::vector<ex> Wsq(M + 1, ex(0));
    std::vector<operator_polynomial> A = read_operators(P, f, out.axis, Wsq);
    put_norm(out, A, Wsq);
    out.ode.A = A;
    for (std::size_t m = 0; m < M; ++m) {
        const std::string nm = P.unknown_name(m) + "(0)";
        out.ode.initial.push_back(nm);
        out.data.emplace_back(nm, P.initial[m]);
    }
    read_forcing(P, f, out);
    return out;
}

namespace {

// The rotating-frame readings of P: a fixed axis (VI.2), else a turning frame or a central
// field (VI.3), with the reason each gave when it did not take P. A domain_error or type_error
// thrown by a reading is that reason too.
struct frame_reading {
    std::optional<fixed_axis_form> fixed_axis;
    std::optional<turning_frame_form> turning;
    std::string why_fixed_axis, why_turning;
};

frame_reading read_frame(const cauchy_problem& P) {
    frame_reading out;
    try {
        out.fixed_axis = read_fixed_axis(P, &out.why_fixed_axis);
        if (!out.fixed_axis) out.turning = read_turning_frame(P, &out.why_turning);
    } catch (const error& e) {
        if (!dynamic_cast<const domain_error*>(&e) && !dynamic_cast<const type_error*>(&e)) throw;
        out.why_turning = e.what();
    }
    return out;
}

// (VI.2.50-52) A second-order vector problem in which x itself is absent (a charge in B(t)):
// the first-order problem for v = x', when a rotating-frame reading takes it; then
// x = x(0) + int_0^t v. Nothing otherwise.
// `why` receives the reading's reason when it has one (a free term singular at some t >= 0).
std::shared_ptr<const cauchy_problem> velocity_problem(const cauchy_problem& P, std::string& why) {
    if (!P.is_vector || P.order() != 2 || P.expression.has(P.unknowns[0])) return nullptr;
    auto V = std::make_shared<cauchy_problem>(P);
    V->name = P.name + "'";
    V->unknowns = {P.unknowns[1], P.unknowns[2]};
    V->initial = {P.initial[1]};
    frame_reading r = read_frame(*V);
    if (r.fixed_axis) V->fixed_axis = std::make_shared<const fixed_axis_form>(std::move(*r.fixed_axis));
    else if (r.turning) V->turning = std::make_shared<const turning_frame_form>(std::move(*r.turning));
    else {
        why = !r.why_fixed_axis.empty() ? r.why_fixed_axis : r.why_turning;
        return nullptr;
    }
    return V;
}

}  // namespace

void read_problem(cauchy_problem& P) {
    if (auto D = read_dual_darboux(P)) {  // the dual Poisson-Darboux problem (issue 31 item 3)
        P.dual_darboux = std::make_shared<const dual_darboux_form>(std::move(*D));
        return;
    }
    try {
        P.reduced = std::make_shared<const operator_form>(reduce(P));
    } catch (const domain_error&) {
        // a rotating frame with w(t) = s(t) u (VI.2): solved by reduction to the inertial problem
        // a turning w(t) or a central field (VI.3): r = F_(-w)(psi), evaluated numerically
        frame_reading r = read_frame(P);
        std::shared_ptr<const cauchy_problem> V;
        std::string why_velocity;
        if (!r.fixed_axis && !r.turning) V = velocity_problem(P, why_velocity);
        if (r.fixed_axis) P.fixed_axis = std::make_shared<const fixed_axis_form>(std::move(*r.fixed_axis));
        else if (r.turning) P.turning = std::make_shared<const turning_frame_form>(std::move(*r.turning));
        else if (V) P.velocity = V;
        // the velocity reading's reason first when it reads the free term (x itself absent)
        else if (why_velocity.find("the free term") != std::string::npos) throw domain_error(why_velocity);
        else if (!r.why_fixed_axis.empty()) throw domain_error(r.why_fixed_axis);  // a fixed axis, in another form
        else if (!r.why_turning.empty()) throw domain_error(r.why_turning);
        else throw;
    }
}

}  // namespace symrep::mechanics
