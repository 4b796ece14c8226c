// symrep/signals/response.cpp -- see response.h.
#include "signals/response.h"

#include <algorithm>
#include <string>
#include <vector>

#include "core/error.h"
#include "scalar/equality.h"
#include "scalar/scalar.h"
#include "algebra/multicomplex.h"
#include "signals/multicomplex_signals.h"
#include "signals/representation.h"

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
GiNaC::ex parameter_form(const GiNaC::ex& x, const GiNaC::ex& t) {
    const GiNaC::ex e = GiNaC::expand(x);
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> by_part;  // (part in t, coefficient)
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
    GiNaC::ex out = 0;
    for (const auto& [part, coefficient] : by_part) {
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

std::string text(const ex& e) { return message_text(e, 300); }

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

// A solution of M x = y (rows >= columns), free unknowns 0; false when inconsistent.
bool solve_any(const GiNaC::matrix& M, const std::vector<ex>& y, coeffs& x) {
    const unsigned n = M.cols();
    GiNaC::matrix vars(n, 1), rhs(M.rows(), 1);
    std::vector<GiNaC::symbol> unknowns(n);
    for (unsigned j = 0; j < n; ++j) vars(j, 0) = unknowns[j];
    for (unsigned i = 0; i < M.rows(); ++i) rhs(i, 0) = y[i];
    GiNaC::matrix s;
    try {
        s = M.solve(vars, rhs, GiNaC::solve_algo::gauss);
    } catch (const std::runtime_error&) {
        return false;  // "inconsistent linear system"
    }
    GiNaC::exmap free;
    for (unsigned j = 0; j < n; ++j) free[unknowns[j]] = 0;
    x.assign(n, ex(0));
    for (unsigned j = 0; j < n; ++j) x[j] = tidy(s(j, 0).subs(free));
    return true;
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

system_response respond_on(const std::vector<ex>& a, const std::vector<ex>& b, const ex& f, const GiNaC::symbol& t,
                           bool discrete) {
    if (a.empty() || is_zero_scalar(a[0]))
        throw domain_error("response: the leading coefficient a_0 of the system is 0");
    if (b.empty()) throw domain_error("response: the input side b_0 .. b_p is empty");
    const std::size_t m = a.size() - 1;
    // analog: m > p (IV.3.7; at m = p the zero-state response jumps at t = 0); digital: m >= p
    if (m < 1 || b.size() - 1 > m || (!discrete && b.size() - 1 == m))
        throw domain_error(std::string("response: the system needs order ") + (discrete ? "m >= p" : "m > p") +
                           " (IV.3.7): m = " + std::to_string(m) + ", p = " + std::to_string(b.size() - 1));
    for (const ex& c : a)
        if (c.has(t)) throw domain_error("response: a coefficient a_k depends on " + t.get_name());
    for (const ex& c : b)
        if (c.has(t)) throw domain_error("response: a coefficient b_k depends on " + t.get_name());
    system_response out;
    const GiNaC::symbol X("X");
    const ex r = discrete ? sequence_annihilator(f, t, X) : annihilator(f, t, X);
    const auto element = [&](const representation& Rep) {
        return discrete ? sequence_element(Rep, f, t) : element_of(Rep, f, t);
    };
    const auto signal = [&](const representation& Rep, const coeffs& u) {
        return discrete ? sequence_formula(Rep, u, t) : signal_of(Rep, u, t);
    };
    const auto apply = [&](const ex& poly, const ex& x) {
        return discrete ? apply_shift(poly, X, x, t) : apply_operator(poly, X, x, t);
    };
    out.input_equation = r;
    const ex P = system_polynomial(a, X), Q = system_polynomial(b, X);

    // the input's class: A = P_r, d = v (IV.3.10-16)
    const representation R = polynomial_representation(r, X);
    const algebra& A = *R.A;
    const coeffs w = element(R);
    const coeffs pd = A.evaluate_polynomial(P.subs(X == R.X), R.X, R.d);
    const coeffs qd = A.evaluate_polynomial(Q.subs(X == R.X), R.X, R.d);
    const coeffs y = A.multiply(qd, w);
    const bool zero_divisor = A.is_zero_divisor(pd);
    coeffs xw;
    const std::vector<ex> yv(y.begin(), y.end());
    const bool solvable = solve_any(multiplication_matrix(A, pd), yv, xw);

    // the zero-state response on P_Pi, Pi = p r (Thm IV.3.2.1): p(v) x = q(v) F and
    // lambda(x v^k) = x^(k)(0) = 0, k < m
    std::string zero_state_refused;
    try {
        const ex Pi = GiNaC::expand(P * r / a[0]);
        const representation B = polynomial_representation(Pi, X);
        const std::size_t N = B.A->dim();
        const coeffs F = element(B);
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
        if (!solve_any(M, rhs, xs)) throw algebra_error("internal: the zero-state response of the system has no solution");
        out.zero_state = signal(B, xs);


    } catch (const closed_form_error& e) {  // exp on P_Pi needs the roots of p r (a sign not decided)
        out.has_zero_state = false;
        out.zero_state = 0;
        zero_state_refused = e.what();
    }
    if (algebra::equal(y, A.zero())) {
        out.kind = "filtered out";
        out.particular = 0;
        out.report = "filtered out: q(d) Psi(f) = 0 (q vanishes on every mode of the input), so the particular "
                     "response is 0 (case a of IV.3.2)";
    } else if (solvable) {
        out.particular = signal(R, xw);
        // the order of the response's least equation: the dimension of the span of x, d x,
        // d^2 x, ... (the least g with g(d) x = 0). Case b of IV.3.2 prints "the minimal
        // polynomial of the element", which is not it: the unit has minimal polynomial
        // X - 1, yet represents the impulse response, of order n.
        const std::size_t n = A.dim();
        GiNaC::matrix K{static_cast<unsigned>(n), static_cast<unsigned>(n)};
        coeffs u = xw;
        for (std::size_t k = 0; k < n; ++k) {
            for (std::size_t i = 0; i < n; ++i) K(unsigned(i), unsigned(k)) = u[i];
            u = A.multiply(u, R.d);
        }
        const unsigned order = K.rank();
        if (order < n) {
            out.kind = "partially filtered";
            out.report = "partially filtered: the response satisfies an equation of order " + std::to_string(order) +
                         " < " + std::to_string(n) + ", the order of the input's (case b of IV.3.2)";
        } else {
            out.kind = "passed";
            out.report = "passed: the response is in the input's class, x = Psi^-1[H(d) Psi(f)] (IV.3.16)";
        }
        if (zero_divisor) {
            out.report += "; p(d) is a zero divisor, but the input has no component on the modes p shares "
                          "with it (no resonance)";
        } else {
            // generic in the parameters: say where it stops holding
            const ex det = GiNaC::factor(tidy(A.determinant(pd)));
            bool symbolic = false;
            for (auto it = det.preorder_begin(); it != det.preorder_end(); ++it)
                symbolic = symbolic || GiNaC::is_a<GiNaC::symbol>(*it);
            if (symbolic)
                out.report += "; for parameters with det p(d) = " + text(det) +
                              " not 0 (where it is 0, p shares a mode with the input)";
        }
    } else {
        out.kind = "resonant";
        if (!out.has_zero_state)
            throw domain_error("response: the input resonates with the system, and its response (on the "
                               "polynomial algebra of p r) is not derived: " + zero_state_refused);
        out.particular = out.zero_state;
        const GiNaC::symbol Y;
        const ex common = GiNaC::gcd(GiNaC::expand(P.subs(X == Y)), GiNaC::expand(r.subs(X == Y)));
        out.report = "resonant: p and the input's equation share the factor " +
                     polynomial_text(common.subs(Y == X), X) +
                     " and q does not cancel it, so no response is in the input's class (case e of IV.3.2); "
                     "the response has secular terms and lives on the polynomial algebra of p r (Thm IV.3.2.1)";
    }
    // one form whatever the pivots of the linear solves were (they follow GiNaC's term order,
    // which depends on the session's history and on addresses): coefficients in the field of
    // their square root
    // (numeric coefficients: radicals of rationals; with parameters the forms stay as derived)
    const auto canonical_form = [&](const ex& x) {
        for (auto it = x.preorder_begin(); it != x.preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::symbol>(*it) && !it->is_equal(t)) return parameter_form(x, t);
        return GiNaC::expand(simplified_square_roots(x, t, true));
    };
    if (!discrete) {
        out.particular = canonical_form(out.particular);
        if (out.has_zero_state) out.zero_state = canonical_form(out.zero_state);
    }
    // every response substituted into the system (IV.3.7)
    const ex lhs_minus_rhs = [&](const ex& x) {
        return tidy(GiNaC::expand(apply(P, x) - apply(Q, f)));
    }(out.particular);
    const ex zs = out.has_zero_state ? tidy(GiNaC::expand(apply(P, out.zero_state) - apply(Q, f))) : ex(0);
    if (!out.has_zero_state) out.report += "; the zero-state response is not derived: " + zero_state_refused;
    for (const ex& residual : {lhs_minus_rhs, zs}) {
        if (is_zero_scalar(residual)) continue;
        const zero_decision z = decide_zero(residual);
        if (z.is_zero == truth::no)
            throw algebra_error("internal: a derived response does not satisfy the system (residual " +
                                text(residual) + ", not 0 " + witness_text(z) + ")");
        if (z.is_zero == truth::unknown && cubic_roots_only_numeric(residual, t)) continue;
        if (z.is_zero == truth::unknown)
            throw domain_error("response: the derived response is not proved to satisfy the system (the residual " +
                               text(residual) +
                               " is neither proved 0 nor seen nonzero; with square roots of squares such as "
                               "sqrt(w^2), declaring the parameters positive lets the proof through)");
    }
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
                                message_text(residual, 200) + (z.is_zero == truth::no ? ")" : ", not proved 0)"));
    }
    if (algebra::equal(out.element, A->zero())) {
        out.kind = "filtered out";
        out.report = "filtered out: H(d) Psi(f) = 0, the response is 0 (case a of IV.3.2)";
        return out;
    }
    const GiNaC::symbol X("X");
    const int order_in = annihilator(f, t, X).degree(X), order_out = annihilator(out.particular, t, X).degree(X);
    if (const auto* M = dynamic_cast<const multicomplex*>(A.get())) {
        const truth in = amplitude_modulated(*M, w).holds, h = amplitude_modulated(*M, H).holds,
                    y = amplitude_modulated(*M, out.element).holds;
        if (in == truth::yes && h == truth::yes) {
            out.kind = "not distorted";
            out.report = "not distorted: Psi(f) and H(d) are of special type, so is their product: the response is "
                         "amplitude-modulated on the same carriers as the input (case c of IV.3.2)";
        } else if (in == truth::no && y == truth::yes) {
            out.kind = "corrected";
            out.report = "corrected: Psi(f) is not of special type but H(d) Psi(f) is, so the system removes the "
                         "input's phase modulation (case d of IV.3.2)";
        } else if (in == truth::yes && y == truth::no) {
            out.kind = "distorted";
            out.report = "distorted: the input is amplitude-modulated (Psi(f) of special type) and the response is not";
        }
        if (!out.kind.empty()) {
            if (order_out < order_in)
                out.report += "; also partially filtered: order " + std::to_string(order_out) + " < " +
                              std::to_string(order_in) + " (case b)";
            return out;
        }
    }
    if (order_out < order_in) {
        out.kind = "partially filtered";
        out.report = "partially filtered: the response satisfies an equation of order " + std::to_string(order_out) +
                     " < " + std::to_string(order_in) + ", the order of the input's (case b of IV.3.2)";
    } else {
        out.kind = "passed";
        out.report = "passed: x = Psi^-1[H(d) Psi(f)] on " + A->name() + " (IV.3.16)";
    }
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
