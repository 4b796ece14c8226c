// symrep/mechanics/cauchy_problem.cpp
#include "mechanics/cauchy_problem.h"

#include <map>

#include "algebra/scalar.h"
#include "io/error.h"
#include "vector/vector.h"

namespace symrep::mechanics {

using GiNaC::ex;

namespace {

using vmap = std::map<ex, ex, GiNaC::ex_is_less>;

std::string text(const ex& e) { return message_text(e, 200); }

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

// The axis w: the first vector acting on an unknown; every later one must equal it.
void set_axis(ex& axis, const ex& v, const cauchy_problem& P, std::size_t m) {
    if (!is_vector_symbol(v))
        throw domain_error("the operator acting on " + P.unknown_name(m) + " involves " + to_string(v) +
                           ", which is not a vector symbol: declare it with 'vector' and give its "
                           "components as values when evaluating");
    if (axis.is_zero()) {
        axis = v;
    } else if (!(axis - v).is_zero()) {
        throw domain_error("both " + to_string(axis) + " x and " + to_string(v) + " x act on the unknowns: "
                           "the solver needs the operators to be polynomials in one K = w x");
    }
}

// A_m(K) from the part L of E that is linear in u = x^(m): terms c u, c (w x u),
// c (w . u) w  (= c K^2 u + c |w|^2 u). `Wsq` collects the |w|^2 coefficients.
void read_operator(const cauchy_problem& P, std::size_t m, const ex& L, ex& axis, operator_polynomial& A,
                   ex& Wsq) {
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
            set_axis(axis, first ? mono.op(1) : mono.op(0), P, m);
            if (has_any(c, P.unknowns))
                throw domain_error("the equation is not linear in " + P.unknown_name(m) + ": term " +
                                   to_string(c * mono));
            A[1] += first ? -c : c;
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

}  // namespace

operator_form reduce(const cauchy_problem& P) {
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
    std::vector<ex> Wsq(M + 1, ex(0));
    ex linear_sum = 0;
    for (std::size_t m = 0; m <= M; ++m) {
        std::vector<std::size_t> others;
        for (std::size_t k = 0; k <= M; ++k)
            if (k != m) others.push_back(k);
        const ex L = without(P, P.expression, others) - f;
        linear_sum += L;
        read_operator(P, m, L, out.axis, A[m], Wsq[m]);
        for (const ex& a : A[m])
            if (a.has(P.t))
                throw domain_error("the coefficient " + text(a) + " of " + P.unknown_name(m) +
                                   " depends on " + text(P.t) + ": only constant coefficients are solved");
    }
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
    auto back = [&](const ex& c) {
        return positive_trig_arguments(normalize_trig_signs(omega_symbol ? c.subs(F.Omega == norm_w) : c), P.t);
    };
    ex x = 0;
    for (const placeholder_coefficients& pc : S.terms) {
        const ex v = data.at(pc.vector);
        const ex c0 = back(pc.c[0].to_ex()), c1 = back(pc.c[1].to_ex()), c2 = back(pc.c[2].to_ex());
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
    const operator_form F = P.reduced ? *P.reduced : reduce(P);
    const rotation_operator_algebra R(F.Omega);
    return vector_solution(P, F, solve(F.ode, R, P.t));
}

solution_check check(const cauchy_problem& P, const ex& s) {
    solution_check out;
    std::vector<ex> d{s};
    for (std::size_t m = 1; m <= P.order(); ++m)
        d.push_back(P.is_vector ? diff_t(d.back(), P.t) : d.back().diff(ex_to<GiNaC::symbol>(P.t)));
    if (P.is_vector) {
        vmap sub;
        for (std::size_t m = 0; m <= P.order(); ++m) sub[P.unknowns[m]] = d[m];
        out.residual = subs_vectors(P.expression, sub);
        out.residual_zero = equal(out.residual, 0);
    } else {
        GiNaC::exmap sub;
        for (std::size_t m = 0; m <= P.order(); ++m) sub[P.unknowns[m]] = d[m];
        out.residual = P.expression.subs(sub);
        out.residual_zero = is_zero_scalar(out.residual);
    }
    out.residual = out.residual_zero ? ex(0) : P.is_vector ? canonical(out.residual) : GiNaC::normal(out.residual);
    out.initial_ok = true;
    for (std::size_t m = 0; m < P.order(); ++m) {
        ex diff = d[m].subs(P.t == 0) - P.initial[m];
        const bool zero = P.is_vector ? equal(diff, 0) : is_zero_scalar(diff);
        out.initial_differences.push_back(zero ? ex(0) : diff);
        out.initial_ok = out.initial_ok && zero;
    }
    return out;
}

}  // namespace symrep::mechanics
