// symrep/signals/response.cpp -- see response.h.
#include "symrep/signals/response.h"

#include <algorithm>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "symrep/core/error.h"
#include "symrep/algebra/exact_linear.h"
#include "symrep/scalar/equality.h"
#include "symrep/scalar/scalar.h"
#include "symrep/algebra/multicomplex.h"
#include "symrep/signals/multicomplex_signals.h"
#include "symrep/signals/representation.h"

namespace symrep::signals {

using GiNaC::ex;

namespace {

/// The sign that makes p's leading coefficient positive, leading by the names of the symbols
/// (the alphabetically first symbol, its highest power, then the next symbol in that
/// coefficient, ...): a rule that does not depend on GiNaC's term order, which follows the
/// session's history (symbol serial numbers) and addresses.
int leading_sign_by_names(const GiNaC::ex& p0) {
    GiNaC::ex p = GiNaC::expand(p0);
    for (int guard = 0; guard < 64; ++guard) {
        if (GiNaC::is_a<GiNaC::numeric>(p)) {
            const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(p);
            return n.is_real() && n.is_negative() ? -1 : 1;
        }
        std::string first;
        GiNaC::ex v;
        for (auto it = p.preorder_begin(); it != p.preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::symbol>(*it)) {
                const std::string n = GiNaC::ex_to<GiNaC::symbol>(*it).get_name();
                if (v.is_zero() || n < first) {
                    first = n;
                    v = *it;
                }
            }
        if (v.is_zero() || !p.is_polynomial(v)) return 1;
        p = GiNaC::expand(p.lcoeff(v));
    }
    return 1;
}

}  // namespace

/// A response with parameters in one form whatever the session's history: the terms
/// collected by their factors in t (sin(2 t), sin(c t), e^(-t), t^k), each coefficient one
/// reduced fraction (normal) with expanded numerator and denominator, the denominator's
/// leading coefficient by names positive.
namespace {

/// The terms of x collected by their factors in t: (part in t, coefficient), in order of appearance.
std::vector<std::pair<GiNaC::ex, GiNaC::ex>> by_parts_in(const GiNaC::ex& x, const GiNaC::ex& t) {
    const GiNaC::ex e = GiNaC::expand(x);
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> by_part;
    for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1); ++i) {
        const GiNaC::ex term = GiNaC::is_a<GiNaC::add>(e) ? e.op(i) : e;
        GiNaC::ex part = 1, coefficient = 1;
        for (std::size_t j = 0; j < (GiNaC::is_a<GiNaC::mul>(term) ? term.nops() : 1); ++j) {
            const GiNaC::ex f = GiNaC::is_a<GiNaC::mul>(term) ? term.op(j) : term;
            (f.has(t) ? part : coefficient) *= f;
        }
        auto it = std::find_if(by_part.begin(), by_part.end(), [&](const auto& q) { return q.first.is_equal(part); });
        if (it == by_part.end()) by_part.emplace_back(part, coefficient);
        else it->second += coefficient;
    }
    return by_part;
}

}  // namespace

GiNaC::ex parameter_form(const GiNaC::ex& x, const GiNaC::ex& t) {
    GiNaC::ex out = 0;
    for (const auto& [part, coefficient] : by_parts_in(x, t)) {
        const GiNaC::ex nd = GiNaC::normal(coefficient).numer_denom();
        GiNaC::ex num = GiNaC::expand(nd.op(0)), den = GiNaC::expand(nd.op(1));
        if (leading_sign_by_names(den) < 0) {
            num = -num;
            den = -den;
        }
        out += num / den * part;
    }
    return out;
}

namespace {

std::string text(const ex& e) { return message_text(e, text_limit::signal_report); }

// The matrix of multiplication by u (columns: u e_j).
GiNaC::matrix multiplication_matrix(const algebra& A, const coeffs& u) {
    const std::size_t n = A.dim();
    GiNaC::matrix M{static_cast<unsigned>(n), static_cast<unsigned>(n)};
    for (std::size_t j = 0; j < n; ++j) {
        const coeffs c = A.multiply(u, A.basis_vector(j));
        for (std::size_t i = 0; i < n; ++i) M(unsigned(i), unsigned(j)) = c[i];
    }
    return M;
}

// sum c_k D^k applied to x(t), c from the polynomial in l.
ex apply_operator(const ex& poly, const GiNaC::symbol& l, const ex& x, const GiNaC::symbol& t) {
    const ex P = GiNaC::expand(poly);
    ex out = 0, dx = x;
    for (int k = 0; k <= P.degree(l); ++k) {
        out += P.coeff(l, k) * dx;
        dx = dx.diff(t);
    }
    return out;
}

// The residual of a response over the roots of an irreducible cubic (Cardano's radicals, or
// cos(theta/3 - 2 pi k/3) for three real roots), whose relations (such as the one cos(2 pi/9)
// satisfies) the exact zero test does not know: without parameters, 0 at 60 digits at
// t = 1/3, 1 and 7/5, each to 10^-45 of the size of its terms (as inverse_laplace checks its
// Cardano inverses numerically).
bool cubic_roots_only_numeric(const ex& residual, const GiNaC::symbol& t) {
    bool cubic = false;
    for (auto it = residual.preorder_begin(); it != residual.preorder_end(); ++it) {
        if (GiNaC::is_a<GiNaC::symbol>(*it) && !it->is_equal(t)) return false;
        if (GiNaC::is_a<GiNaC::power>(*it) && GiNaC::is_a<GiNaC::numeric>(it->op(1)) &&
            GiNaC::ex_to<GiNaC::numeric>(it->op(1)).denom() == 3)
            cubic = true;
        if (GiNaC::is_a<GiNaC::function>(*it) && !it->has(t) && it->has(GiNaC::Pi)) cubic = true;  // cos(2 pi/9)
    }
    if (!cubic) return false;
    const ex e = GiNaC::expand(residual);
    for (const GiNaC::numeric& t0 : {GiNaC::numeric(1, 3), GiNaC::numeric(1), GiNaC::numeric(7, 5)}) {
        GiNaC::numeric v, size = 1, part;
        if (!evaluate_numeric(e.subs(t == t0), 60, v)) return false;
        for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1); ++i) {
            if (!evaluate_numeric((GiNaC::is_a<GiNaC::add>(e) ? e.op(i) : e).subs(t == t0), 60, part)) return false;
            size += GiNaC::abs(part);
        }
        if (GiNaC::abs(v) > GiNaC::numeric("1e-45") * size) return false;
    }
    return true;
}

}  // namespace

std::string kind_text(response_kind k) {
    switch (k) {
        case response_kind::passed: return "passed";
        case response_kind::partially_filtered: return "partially filtered";
        case response_kind::filtered_out: return "filtered out";
        case response_kind::resonant: return "resonant";
        case response_kind::not_distorted: return "not distorted";
        case response_kind::corrected: return "corrected";
        case response_kind::distorted: return "distorted";
    }
    return "unknown";
}

std::ostream& operator<<(std::ostream& os, response_kind k) { return os << kind_text(k); }

ex system_polynomial(const std::vector<ex>& a, const GiNaC::symbol& l) {
    ex p = 0;
    for (std::size_t k = 0; k < a.size(); ++k) p += a[k] * GiNaC::pow(l, int(a.size() - 1 - k));
    return p;
}

// (IV.3.15)
coeffs transmittance(const algebra& A, const coeffs& d, const std::vector<ex>& a, const std::vector<ex>& b) {
    const GiNaC::symbol l;
    const coeffs pd = A.evaluate_polynomial(system_polynomial(a, l), l, d);
    const coeffs qd = A.evaluate_polynomial(system_polynomial(b, l), l, d);
    if (A.is_zero_divisor(pd))
        throw zero_divisor_error("transmittance: p(d) is a zero divisor in " + A.name() +
                                     " (a root of p is an eigenvalue of d: case e of IV.3.2), so H(d) = q(d)/p(d) "
                                     "does not exist; an input with a component on that mode is resonant",
                                 {});
    return A.multiply(qd, A.inverse(pd));
}

namespace {

// sum c_i x(k + i), c from the polynomial in l (the shift E).
ex apply_shift(const ex& poly, const GiNaC::symbol& l, const ex& x, const GiNaC::symbol& k) {
    const ex P = GiNaC::expand(poly);
    ex out = 0;
    for (int i = 0; i <= P.degree(l); ++i) out += P.coeff(l, i) * x.subs(k == k + i);
    return out;
}

// The input's side of the system: f in the variable t, analog (the derivative D) or digital
// (the shift E): its element, its signal and an operator polynomial applied to a signal.
struct input_signal {
    const ex& f;
    const GiNaC::symbol& t;
    bool discrete;

    coeffs element(const representation& Rep) const {
        return discrete ? sequence_element(Rep, f, t) : element_of(Rep, f, t);
    }
    ex signal(const representation& Rep, const coeffs& u) const {
        return discrete ? sequence_formula(Rep, u, t) : signal_of(Rep, u, t);
    }
    ex apply(const ex& poly, const GiNaC::symbol& X, const ex& x) const {
        return discrete ? apply_shift(poly, X, x, t) : apply_operator(poly, X, x, t);
    }
};

// The system a_0 x^(m) + ... = b_0 f^(p) + ... with constant coefficients and a_0 != 0; analog:
// m > p (IV.3.7; at m = p the zero-state response jumps at t = 0); digital: m >= p.
void check_system(const std::vector<ex>& a, const std::vector<ex>& b, const GiNaC::symbol& t, bool discrete) {
    if (a.empty() || is_zero_scalar(a[0]))
        throw domain_error("response: the leading coefficient a_0 of the system is 0");
    if (b.empty()) throw domain_error("response: the input side b_0 .. b_p is empty");
    const std::size_t m = a.size() - 1;
    if (m < 1 || b.size() - 1 > m || (!discrete && b.size() - 1 == m))
        throw domain_error(std::string("response: the system needs order ") + (discrete ? "m >= p" : "m > p") +
                           " (IV.3.7): m = " + std::to_string(m) + ", p = " + std::to_string(b.size() - 1));
    for (const ex& c : a)
        if (c.has(t)) throw domain_error("response: a coefficient a_k depends on " + t.get_name());
    for (const ex& c : b)
        if (c.has(t)) throw domain_error("response: a coefficient b_k depends on " + t.get_name());
}

// M x = y by GiNaC's elimination (solve_any: the forms of the responses are its pivots'), and
// where that sees an inconsistency, again with the exact zero test (solve_linear, M of full
// column rank): GiNaC's normal() does not see that cos(2) - 2 cos(1)^2 + 1 or
// cos(1)^2 + sin(1)^2 - 1 is 0 in a row it has reduced, and would call the system inconsistent.
bool solve_with_zero_test(const GiNaC::matrix& M, const std::vector<ex>& y, coeffs& x) {
    if (solve_any(M, y, x)) return true;
    std::vector<std::vector<ex>> rows(M.rows(), std::vector<ex>(M.cols()));
    for (unsigned i = 0; i < M.rows(); ++i)
        for (unsigned j = 0; j < M.cols(); ++j) rows[i][j] = M(i, j);
    const auto solution = solve_linear(rows, y);
    if (!solution) return false;
    x.assign(solution->begin(), solution->end());
    return true;
}

// p(d) x = q(d) Psi(f) in the input's class: A = P_r, d = v (IV.3.10-16).
struct class_solution {
    explicit class_solution(representation rep) : R(std::move(rep)) {}
    representation R;
    coeffs pd;         // p(d)
    coeffs y;          // q(d) Psi(f)
    bool zero_divisor = false;
    bool solvable = false;
    coeffs x;          // a solution, where solvable
};

class_solution solve_in_input_class(const input_signal& in, const ex& r, const GiNaC::symbol& X, const ex& P,
                                    const ex& Q) {
    class_solution s(polynomial_representation(r, X));
    const algebra& A = *s.R.A;
    const coeffs w = in.element(s.R);
    s.pd = A.evaluate_polynomial(P.subs(X == s.R.X), s.R.X, s.R.d);
    const coeffs qd = A.evaluate_polynomial(Q.subs(X == s.R.X), s.R.X, s.R.d);
    s.y = A.multiply(qd, w);
    s.zero_divisor = A.is_zero_divisor(s.pd);
    const std::vector<ex> yv(s.y.begin(), s.y.end());
    // p(d) invertible: solvable (a failure of solve_any is its zero test's, retried exactly)
    s.solvable = s.zero_divisor ? solve_any(multiplication_matrix(A, s.pd), yv, s.x)
                                : solve_with_zero_test(multiplication_matrix(A, s.pd), yv, s.x);
    return s;
}

// The zero-state response on P_Pi, Pi = p r (Thm IV.3.2.1): p(v) x = q(v) F and
// lambda(x v^k) = x^(k)(0) = 0, k < m. Sets out.zero_state, or out.has_zero_state = false and
// returns why (exp on P_Pi needs the roots of p r: a sign not decided).
std::string derive_zero_state(const input_signal& in, const std::vector<ex>& a, const ex& r,
                              const GiNaC::symbol& X, const ex& P, const ex& Q, system_response& out) {
    const std::size_t m = a.size() - 1;
    try {
        const ex Pi = GiNaC::expand(P * r / a[0]);
        const representation B = polynomial_representation(Pi, X);
        const std::size_t N = B.A->dim();
        const coeffs F = in.element(B);
        const GiNaC::matrix PM = multiplication_matrix(*B.A, B.A->evaluate_polynomial(P.subs(X == B.X), B.X, B.d));
        const coeffs QF = B.A->multiply(B.A->evaluate_polynomial(Q.subs(X == B.X), B.X, B.d), F);
        GiNaC::matrix M{static_cast<unsigned>(N + m), static_cast<unsigned>(N)};
        std::vector<ex> rhs(N + m, ex(0));
        for (unsigned i = 0; i < N; ++i) {
            for (unsigned j = 0; j < N; ++j) M(i, j) = PM(i, j);
            rhs[i] = QF[i];
        }
        coeffs vk = B.A->unit();
        for (std::size_t k = 0; k < m; ++k) {  // lambda(e_j v^k)
            for (unsigned j = 0; j < N; ++j)
                M(unsigned(N + k), j) = B.A->multiply(B.A->basis_vector(j), vk).back();
            vk = B.A->multiply(vk, B.d);
        }
        coeffs xs;
        if (!solve_with_zero_test(M, rhs, xs))
            throw algebra_error("internal: the zero-state response of the system has no solution");
        out.zero_state = in.signal(B, xs);
    } catch (const closed_form_error& e) {
        out.has_zero_state = false;
        out.zero_state = 0;
        return e.what();
    }
    return {};
}

// Case b of IV.3.2 where the response's least equation has lower order than the input's, else
// passed (with the report `passed`).
std::pair<response_kind, std::string> order_case(long order, long input_order, std::string passed) {
    if (order < input_order)
        return {response_kind::partially_filtered, "partially filtered: the response satisfies an equation of order " +
                                                       std::to_string(order) + " < " + std::to_string(input_order) +
                                                       ", the order of the input's (case b of IV.3.2)"};
    return {response_kind::passed, std::move(passed)};
}

// The order of the response's least equation: the dimension of the span of x, d x, d^2 x, ...
// (the least g with g(d) x = 0). Case b of IV.3.2 prints "the minimal polynomial of the
// element", which is not it: the unit has minimal polynomial X - 1, yet represents the impulse
// response, of order n.
unsigned response_order(const algebra& A, const coeffs& x, const coeffs& d) {
    const std::size_t n = A.dim();
    GiNaC::matrix K{static_cast<unsigned>(n), static_cast<unsigned>(n)};
    coeffs u = x;
    for (std::size_t k = 0; k < n; ++k) {
        for (std::size_t i = 0; i < n; ++i) K(unsigned(i), unsigned(k)) = u[i];
        u = A.multiply(u, d);
    }
    return K.rank();
}

// A response in the input's class: passed or partially filtered (case b), and where it holds.
void classify_in_class(const class_solution& s, const input_signal& in, system_response& out) {
    const algebra& A = *s.R.A;
    out.particular = in.signal(s.R, s.x);
    const std::size_t n = A.dim();  // the order of the input's least equation
    std::tie(out.kind, out.report) =
        order_case(response_order(A, s.x, s.R.d), long(n),
                   "passed: the response is in the input's class, x = Psi^-1[H(d) Psi(f)] (IV.3.16)");
    if (s.zero_divisor) {
        out.report += "; p(d) is a zero divisor, but the input has no component on the modes p shares "
                      "with it (no resonance)";
        return;
    }
    // generic in the parameters: say where it stops holding
    const ex det = GiNaC::factor(tidy(A.determinant(s.pd)));
    if (has_symbol(det))
        out.report += "; for parameters with det p(d) = " + text(det) +
                      " not 0 (where it is 0, p shares a mode with the input)";
}

// The cases of IV.3.2: filtered out (a), in the input's class (passed, b), or resonant (e:
// then the particular response is the zero-state response, on the algebra of p r).
void classify(const class_solution& s, const input_signal& in, const ex& P, const ex& Q, const ex& r,
              const GiNaC::symbol& X, const std::string& zero_state_refused, system_response& out) {
    if (algebra::equal(s.y, s.R.A->zero())) {
        out.kind = response_kind::filtered_out;
        out.particular = 0;
        out.report = "filtered out: q(d) Psi(f) = 0 (q vanishes on every mode of the input), so the particular "
                     "response is 0 (case a of IV.3.2)";
        return;
    }
    if (s.solvable) {
        classify_in_class(s, in, out);
        return;
    }
    out.kind = response_kind::resonant;
    const GiNaC::symbol Y;
    const ex common = GiNaC::gcd(GiNaC::expand(P.subs(X == Y)), GiNaC::expand(r.subs(X == Y)));
    out.report = "resonant: p and the input's equation share the factor " + polynomial_text(common.subs(Y == X), X) +
                 " and q does not cancel it, so no response is in the input's class (case e of IV.3.2); "
                 "the response has secular terms and lives on the polynomial algebra of p r (Thm IV.3.2.1)";
    if (out.has_zero_state) {
        out.particular = out.zero_state;
        return;
    }
    // the roots of p r not all known (a factor of p of degree > 3 without radicals): a particular
    // response on the algebra of p1 r instead, p1 the largest factor of p whose roots are modes of
    // the input (their roots are r's, known); p(v) x = q(v) F is solvable there, as p / p1 is
    // invertible on it (Thm IV.3.2.1 with p1 for p)
    ex rest = GiNaC::expand(P.subs(X == Y)), p1 = 1;
    const ex ry = GiNaC::expand(r.subs(X == Y));
    for (int guard = 0; guard < 64; ++guard) {
        const ex g = GiNaC::gcd(rest, ry);
        if (g.degree(Y) < 1) break;
        p1 = GiNaC::expand(p1 * g);
        rest = GiNaC::quo(rest, g, Y);
    }
    const ex Pi1 = GiNaC::expand(p1.subs(Y == X) * r / p1.subs(Y == X).lcoeff(X));
    try {
        const representation B = polynomial_representation(Pi1, X);
        const coeffs F = in.element(B);
        const coeffs QF = B.A->multiply(B.A->evaluate_polynomial(Q.subs(X == B.X), B.X, B.d), F);
        const GiNaC::matrix PM = multiplication_matrix(*B.A, B.A->evaluate_polynomial(P.subs(X == B.X), B.X, B.d));
        coeffs xs;
        if (!solve_with_zero_test(PM, std::vector<ex>(QF.begin(), QF.end()), xs))
            throw algebra_error("internal: the resonant particular response has no solution on the algebra of p1 r");
        out.particular = in.signal(B, xs);
    } catch (const closed_form_error& e) {
        throw domain_error("response: the input resonates with the system, and neither its zero-state response "
                           "(on the polynomial algebra of p r: " + zero_state_refused +
                           ") nor a particular response is derived: " + e.what());
    }
    out.report += "; the particular response is on the polynomial algebra of p1 r, p1 = " +
                  polynomial_text(p1.subs(Y == X), X) + " the factor of p on the input's modes";
}

// One form whatever the pivots of the linear solves were (they follow GiNaC's term order,
// which depends on the session's history and on addresses): coefficients in the field of
// their square root (numeric coefficients: radicals of rationals; with parameters
// parameter_form).
void canonical_forms(system_response& out, const GiNaC::symbol& t) {
    const auto canonical_form = [&](const ex& x) {
        for (auto it = x.preorder_begin(); it != x.preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::symbol>(*it) && !it->is_equal(t)) return parameter_form(x, t);
        return GiNaC::expand(simplified_square_roots(x, t, true));
    };
    out.particular = canonical_form(out.particular);
    if (out.has_zero_state) out.zero_state = canonical_form(out.zero_state);
}

// A digital response with its constant coefficients (the ratios' cos(c), sin(c) for cos(c k))
// collected by their factors in k, each one fraction with sin(u)^2 written 1 - cos(u)^2.
void discrete_forms(system_response& out, const GiNaC::symbol& k) {
    const auto form = [&](const ex& x) {
        ex sum = 0;
        for (const auto& [part, c] : by_parts_in(x, k)) sum += GiNaC::normal(sines_squared_as_cosines(c)) * part;
        return sum;
    };
    out.particular = form(out.particular);
    if (out.has_zero_state) out.zero_state = form(out.zero_state);
}

// Every response substituted into the system (IV.3.7): the residuals p(D) x - q(D) f proved 0
// (or, over the roots of an irreducible cubic, 0 to 45 digits); an unproved residual is refused.
void verify_response(const system_response& out, const input_signal& in, const ex& P, const ex& Q,
                     const GiNaC::symbol& X) {
    const ex lhs_minus_rhs = tidy(GiNaC::expand(in.apply(P, X, out.particular) - in.apply(Q, X, in.f)));
    const ex zs = out.has_zero_state ? tidy(GiNaC::expand(in.apply(P, X, out.zero_state) - in.apply(Q, X, in.f)))
                                     : ex(0);
    for (const ex& residual : {lhs_minus_rhs, zs}) {
        if (is_zero_scalar(residual)) continue;
        const zero_decision z = decide_zero(residual);
        if (z.is_zero == truth::no)
            throw algebra_error("internal: a derived response does not satisfy the system (residual " +
                                text(residual) + ", not 0 " + witness_text(z) + ")");
        if (z.is_zero == truth::unknown && cubic_roots_only_numeric(residual, in.t)) continue;
        if (z.is_zero == truth::unknown)
            throw domain_error("response: the derived response is not proved to satisfy the system (the residual " +
                               text(residual) +
                               " is neither proved 0 nor seen nonzero; with square roots of squares such as "
                               "sqrt(w^2), declaring the parameters positive lets the proof through)");
    }
}

system_response respond_on(const std::vector<ex>& a, const std::vector<ex>& b, const ex& f, const GiNaC::symbol& t,
                           bool discrete) {
    check_system(a, b, t, discrete);
    system_response out;
    const GiNaC::symbol X("X");
    const ex r = discrete ? sequence_annihilator(f, t, X) : annihilator(f, t, X);
    const input_signal in{f, t, discrete};
    out.input_equation = r;
    const ex P = system_polynomial(a, X), Q = system_polynomial(b, X);
    const class_solution s = solve_in_input_class(in, r, X, P, Q);
    const std::string zero_state_refused = derive_zero_state(in, a, r, X, P, Q, out);
    classify(s, in, P, Q, r, X, zero_state_refused, out);
    if (!discrete) canonical_forms(out, t);
    else discrete_forms(out, t);
    if (!out.has_zero_state) out.report += "; the zero-state response is not derived: " + zero_state_refused;
    verify_response(out, in, P, Q, X);
    return out;
}

}  // namespace

frequency_response frequency_response_of(const std::vector<ex>& a, const std::vector<ex>& b, const ex& w) {
    if (a.empty() || b.empty()) throw type_error("frequency_response: the lists a and b must not be empty");
    const GiNaC::symbol l("l");
    const ex iw = GiNaC::I * w;
    const ex p = system_polynomial(a, l).subs(l == iw).expand(), q = system_polynomial(b, l).subs(l == iw).expand();
    const ex pr = tidy(GiNaC::real_part(p)), pi = tidy(GiNaC::imag_part(p));
    const ex qr = tidy(GiNaC::real_part(q)), qi = tidy(GiNaC::imag_part(q));
    const ex p2 = tidy((pr * pr + pi * pi).expand()), q2 = tidy((qr * qr + qi * qi).expand());
    frequency_response r;
    r.gain = GiNaC::sqrt(tidy(q2 / p2));
    // H = q conj(p) / |p|^2
    r.phase = GiNaC::atan2(tidy((qi * pr - qr * pi).expand()), tidy((qr * pr + qi * pi).expand()));
    return r;
}

algebra_response respond_over(const algebra_ptr& A, const coeffs& d, const std::vector<ex>& a,
                              const std::vector<ex>& b, const ex& f, const GiNaC::symbol& t) {
    if (a.size() <= b.size())
        throw domain_error("response: the system is not causal (m = " + std::to_string(a.size() - 1) +
                           " <= p = " + std::to_string(b.size() - 1) + ")");
    const representation R = represent_on(A, d);
    const coeffs w = element_of(R, f, t);
    const coeffs H = transmittance(*A, d, a, b);  // zero_divisor_error: case e
    algebra_response out;
    out.element = A->multiply(H, w);
    for (ex& x : out.element) x = tidy(x);
    out.particular = algebra::equal(out.element, A->zero()) ? ex(0) : signal_of(R, out.element, t);
    // the response substituted back: p(D) x = q(D) f
    const GiNaC::symbol l("l");
    const ex residual = tidy(GiNaC::expand(apply_operator(system_polynomial(a, l), l, out.particular, t) -
                                           apply_operator(system_polynomial(b, l), l, f, t)));
    if (!is_zero_scalar(residual)) {
        const zero_decision z = decide_zero(residual);
        if (z.is_zero != truth::yes)
            throw algebra_error("response: the response does not satisfy the system (residual " +
                                message_text(residual, text_limit::report) + (z.is_zero == truth::no ? ")" : ", not proved 0)"));
    }
    if (algebra::equal(out.element, A->zero())) {
        out.kind = response_kind::filtered_out;
        out.report = "filtered out: H(d) Psi(f) = 0, the response is 0 (case a of IV.3.2)";
        return out;
    }
    const GiNaC::symbol X("X");
    const int order_in = annihilator(f, t, X).degree(X), order_out = annihilator(out.particular, t, X).degree(X);
    if (const auto* M = dynamic_cast<const multicomplex*>(A.get())) {
        const truth in = amplitude_modulated(*M, w).holds, h = amplitude_modulated(*M, H).holds,
                    y = amplitude_modulated(*M, out.element).holds;
        bool special = true;  // one of the cases c, d of the special type (or its converse)
        if (in == truth::yes && h == truth::yes) {
            out.kind = response_kind::not_distorted;
            out.report = "not distorted: Psi(f) and H(d) are of special type, so is their product: the response is "
                         "amplitude-modulated on the same carriers as the input (case c of IV.3.2)";
        } else if (in == truth::no && y == truth::yes) {
            out.kind = response_kind::corrected;
            out.report = "corrected: Psi(f) is not of special type but H(d) Psi(f) is, so the system removes the "
                         "input's phase modulation (case d of IV.3.2)";
        } else if (in == truth::yes && y == truth::no) {
            out.kind = response_kind::distorted;
            out.report = "distorted: the input is amplitude-modulated (Psi(f) of special type) and the response is not";
        } else {
            special = false;
        }
        if (special) {
            if (order_out < order_in)
                out.report += "; also partially filtered: order " + std::to_string(order_out) + " < " +
                              std::to_string(order_in) + " (case b)";
            return out;
        }
    }
    std::tie(out.kind, out.report) =
        order_case(order_out, order_in, "passed: x = Psi^-1[H(d) Psi(f)] on " + A->name() + " (IV.3.16)");
    return out;
}

system_response respond(const std::vector<ex>& a, const std::vector<ex>& b, const ex& f, const GiNaC::symbol& t) {
    return respond_on(a, b, f, t, false);
}

system_response respond_discrete(const std::vector<ex>& a, const std::vector<ex>& b, const ex& f,
                                 const GiNaC::symbol& k) {
    return respond_on(a, b, f, k, true);
}

}  // namespace symrep::signals
