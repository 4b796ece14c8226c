// symrep/numeric/quadrature.cpp -- integral objects, nested ones included, by one march of
// Chebyshev panels (quadrature.h, quadrature_chain.h).
#include "symrep/numeric/quadrature.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "symrep/core/error.h"
#include "symrep/numeric/evaluator.h"
#include "symrep/numeric/quadrature_chain.h"
#include "symrep/numeric/reference.h"
#include "symrep/scalar/scalar.h"

namespace symrep::num {

using GiNaC::ex;

bool has_integral(const ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::integral>(*it)) return true;
    return false;
}

namespace {

// The integral objects of an integrand as the unknowns of y_j' = g_j(x, y_0, ..., y_{j-1}),
// inner ones first (each int_c^s g(sigma) dsigma with s the variable of the integral around it
// is one unknown, the same integral met twice one unknown), the integrand itself last.
struct quadrature_system {
    const GiNaC::symbol x{"x"};        // the march variable
    std::vector<GiNaC::symbol> y;      // the unknowns
    std::vector<ex> g;                 // g_j in x and y_0 .. y_{j-1}
    std::vector<ex> lower;             // c_j
    std::vector<ex> variable, written; // s and g(s) as written (the start value when c_j != a)

    // e (in the variable s) with its integral objects replaced by unknowns
    ex reduce(const ex& e, const ex& s) {
        if (GiNaC::is_a<GiNaC::integral>(e)) return y[unknown(e, s)];
        if (e.nops() == 0 || !has_integral(e)) return e;
        struct recurse : GiNaC::map_function {
            quadrature_system& q;
            const ex& s;
            recurse(quadrature_system& qs, const ex& v) : q(qs), s(v) {}
            ex operator()(const ex& c) override { return q.reduce(c, s); }
        } inner(*this, s);
        return e.map(inner);
    }

    // the unknown of int_c^s g(sigma) dsigma met in an integrand in s
    std::size_t unknown(const ex& I, const ex& s) {
        const ex sigma = I.op(0), c = I.op(1);
        if (!GiNaC::is_a<GiNaC::symbol>(sigma) || sigma.is_equal(s) || !I.op(2).is_equal(s) || has_symbol(c))
            throw domain_error("integral: the nested integral in " + message_text(sigma) + " from " + message_text(c) +
                               " to " + message_text(I.op(2)) + " is not of the form int_c^" + message_text(s) +
                               " g(sigma) dsigma with g in its own variable sigma and a number c");
        const ex gs = reduce(I.op(3), sigma);
        check_symbols(gs, sigma);
        const ex gx = gs.subs(sigma == x, GiNaC::subs_options::no_pattern);
        for (std::size_t j = 0; j < g.size(); ++j)
            if (lower[j].is_equal(c) && g[j].is_equal(gx)) return j;
        return add(gx, c, sigma, I.op(3));
    }

    std::size_t add(const ex& gx, const ex& c, const ex& s, const ex& as_written) {
        y.emplace_back("y" + std::to_string(y.size()));
        g.push_back(gx);
        lower.push_back(c);
        variable.push_back(s);
        written.push_back(as_written);
        return g.size() - 1;
    }

    // only s and the unknowns may be left
    void check_symbols(const ex& e, const ex& s) const {
        for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::symbol>(*it) && !it->is_equal(s) &&
                std::none_of(y.begin(), y.end(), [&](const GiNaC::symbol& u) { return it->is_equal(u); }))
                throw domain_error("integral: the integrand in " + message_text(s) + " has symbols without values (" +
                                   message_text(*it) + ")");
    }
};

}  // namespace

integral_value evaluate_integral(const ex& variable, double a, double b, const ex& integrand) {
    if (!std::isfinite(a) || !std::isfinite(b)) throw type_error("integral: the limits must be finite numbers");
    integral_value out;
    if (a == b) return out;
    quadrature_system q;
    const ex top = q.reduce(integrand, variable);
    q.check_symbols(top, variable);
    q.add(top.subs(variable == q.x, GiNaC::subs_options::no_pattern), a, variable, integrand);
    const std::size_t n = q.g.size();
    // y_j(a): 0 when the inner integral starts at a, else int_c^a of it (the same method)
    std::vector<double> start(n, 0.0);
    for (std::size_t j = 0; j + 1 < n; ++j) {
        const double c = accurate_double(q.lower[j]);
        if (c != a) start[j] = evaluate_integral(q.variable[j], c, a, q.written[j]).value;
    }
    std::vector<ex> inputs{q.x};
    for (const auto& s : q.y) inputs.push_back(s);
    std::vector<compiled_function> f;
    f.reserve(n);
    for (const ex& gj : q.g) f.push_back(compile(gj, inputs));
    std::vector<double> at(n + 1, 0.0);
    const chain_integrand G = [&](std::size_t j, double x, const double* y) {
        at[0] = x;
        std::copy(y, y + j, at.begin() + 1);
        double v;
        f[j].eval(at.data(), &v);
        return v;
    };
    const chain_result r = integrate_chain(G, n, a, b, start, message_text(variable));
    out.value = r.value.back();
    out.error = r.error.back();
    out.scale = std::max(r.l1.back(), std::fabs(out.value));
    out.panels = r.panels;
    out.evaluations = r.evaluations;
    return out;
}

namespace {

constexpr double converged = 1e-10;  // of the scale: the estimate that is accepted

std::string not_converged(const ex& variable, double a, double b, const integral_value& v, const std::string& more = "") {
    std::ostringstream os;
    os.precision(3);
    os << "integral: the quadrature in " << message_text(variable) << " over [" << a << ", " << b
       << "] did not converge (error estimate " << v.error << " for the value " << v.value << ", int |f| = "
       << v.scale << more << ")";
    return os.str();
}

double judged(const ex& variable, double a, double b, const ex& integrand) {
    const integral_value v = evaluate_integral(variable, a, b, integrand);
    if (v.error <= converged * v.scale) return v.value;
    throw domain_error(not_converged(variable, a, b, v));
}

// An integral object evaluated but not converged by its own scale: judged with the whole expression.
struct open_integral {
    GiNaC::symbol z;
    integral_value v;
    ex variable;
    double a = 0, b = 0;
};

// e with its integral objects (numeric limits, no symbol but their variables) replaced by their
// values, those whose estimate is above 1e-10 of their own scale by symbols (open)
ex values_of_integrals(const ex& e, std::vector<open_integral>& open) {
    if (!has_integral(e)) return e;
    if (GiNaC::is_a<GiNaC::integral>(e)) {
        const ex x = e.op(0);
        const ex f = integrals_as_numbers(e.op(3));  // constant integrals inside, judged alone
        const ex a = e.op(1), b = e.op(2);
        if (!GiNaC::is_a<GiNaC::symbol>(x)) return e;
        // the limits as doubles (exact expressions such as 7/3 or pi)
        auto limit = [&](const ex& l, double& out) {
            if (l.has(x) || has_symbol(l)) return false;
            out = accurate_double(l);
            return true;
        };
        double A, B;
        if (!limit(a, A) || !limit(b, B)) return e;
        if (!has_integral(f))
            for (auto it = f.preorder_begin(); it != f.preorder_end(); ++it)
                if (GiNaC::is_a<GiNaC::symbol>(*it) && !it->is_equal(x)) return e;
        const integral_value v = evaluate_integral(x, A, B, f);
        if (v.error <= converged * v.scale) return GiNaC::numeric(v.value);
        open.push_back({GiNaC::symbol("z"), v, x, A, B});
        return open.back().z;
    }
    struct recurse : GiNaC::map_function {
        std::vector<open_integral>& open;
        explicit recurse(std::vector<open_integral>& o) : open(o) {}
        ex operator()(const ex& c) override { return values_of_integrals(c, open); }
    } inner(open);
    return e.map(inner);
}

}  // namespace

ex integrals_as_numbers(const ex& e) {
    std::vector<open_integral> open;
    const ex x = values_of_integrals(e, open);
    if (open.empty()) return x;
    GiNaC::exmap at;
    for (const auto& o : open) at[o.z] = GiNaC::numeric(o.v.value);
    const ex out = x.subs(at, GiNaC::subs_options::no_pattern);
    // an integral that is small in the whole (t = 0.006 in r = r0 + ...): its estimate judged
    // against the expression's value, sum_k |d e/d I_k| error_k <= 1e-10 |e|
    double whole = std::numeric_limits<double>::quiet_NaN();
    if (!has_symbol(out)) {
        try {
            whole = accurate_double(out);
            double spread = 0;
            for (const auto& o : open)
                spread += std::fabs(accurate_double(x.diff(o.z).subs(at, GiNaC::subs_options::no_pattern))) * o.v.error;
            if (spread <= converged * std::fabs(whole)) return out;
        } catch (const std::exception&) {  // a value or derivative that does not evaluate: refused below
        }
    }
    const auto worst = std::max_element(open.begin(), open.end(), [](const auto& p, const auto& q) {
        return p.v.error / std::max(p.v.scale, 1e-300) < q.v.error / std::max(q.v.scale, 1e-300);
    });
    std::ostringstream more;
    more.precision(3);
    if (std::isfinite(whole)) more << ", the whole value " << whole;
    throw domain_error(not_converged(worst->variable, worst->a, worst->b, worst->v, more.str()));
}

double integrate_numerically(const ex& variable, double a, double b, const ex& integrand) {
    return judged(variable, a, b, integrand);
}

double integrate_nested(const ex& variable, double a, double b, const ex& integrand) {
    return judged(variable, a, b, integrand);
}

namespace {

// Distinct real zeros of the polynomial p (rational coefficients, p(0) != 0) in (0, inf):
// Sturm's chain p, p', -rem(...), its sign changes at 0 less those at +inf.
int zeros_on_positive_axis(const ex& p, const GiNaC::symbol& x) {
    std::vector<ex> chain{GiNaC::expand(p), GiNaC::expand(p.diff(x))};
    while (!chain.back().is_zero() && chain.back().degree(x) > 0) {
        const ex r = GiNaC::expand(-GiNaC::rem(chain[chain.size() - 2], chain.back(), x));
        if (r.is_zero()) break;
        chain.push_back(r);
    }
    auto changes = [](const std::vector<GiNaC::numeric>& v) {
        int n = 0, last = 0;
        for (const auto& a : v) {
            const int s = a.is_zero() ? 0 : a.is_positive() ? 1 : -1;
            if (s == 0) continue;
            if (last != 0 && s != last) ++n;
            last = s;
        }
        return n;
    };
    std::vector<GiNaC::numeric> at0, atinf;
    for (const ex& q : chain) {
        at0.push_back(GiNaC::ex_to<GiNaC::numeric>(q.subs(x == 0)));
        atinf.push_back(GiNaC::ex_to<GiNaC::numeric>(q.lcoeff(x)));
    }
    return changes(at0) - changes(atinf);
}

// A polynomial in x with rational coefficients.
bool rational_polynomial(const ex& p, const GiNaC::symbol& x) {
    if (!p.is_polynomial(x)) return false;
    const ex e = GiNaC::expand(p);
    for (int k = e.ldegree(x); k <= e.degree(x); ++k) {
        const ex c = e.coeff(x, k);
        if (!GiNaC::is_a<GiNaC::numeric>(c) || !GiNaC::ex_to<GiNaC::numeric>(c).is_rational()) return false;
    }
    return true;
}

struct half_line_check {
    const GiNaC::symbol& x;
    const std::string& what;

    [[noreturn]] void undecided(const ex& f) const {
        throw domain_error(what + ": cannot decide that " + message_text(f) + " is finite for every " +
                           message_text(x) + " >= 0 (an integral object int_0^" + message_text(x) +
                           " needs it; refused rather than integrated)");
    }
    [[noreturn]] void singular(const ex& f, const ex& p) const {
        throw domain_error(what + ": " + message_text(f) + " is not finite at a zero of " + message_text(p) + " in " +
                           message_text(x) + " >= 0: int_0^" + message_text(x) +
                           " over it is singular (refused, not integrated)");
    }
    // p has no zero in [0, inf) (strict: also not at 0), or p >= 0 there with a zero at 0 allowed
    void require_sign(const ex& f, const ex& p0, bool zero_at_origin_allowed) const {
        if (!p0.has(x)) return;
        if (!rational_polynomial(p0, x)) undecided(f);
        ex p = GiNaC::expand(p0);
        const int low = p.ldegree(x);
        if (low > 0) {
            if (!zero_at_origin_allowed) singular(f, p0);
            p = GiNaC::expand(GiNaC::quo(p, GiNaC::pow(x, low), x));
        }
        const GiNaC::numeric p_at_0 = GiNaC::ex_to<GiNaC::numeric>(p.subs(x == 0));
        if (zeros_on_positive_axis(p, x) > 0) singular(f, p0);
        if (zero_at_origin_allowed && !p_at_0.is_positive()) singular(f, p0);
    }
    void operator()(const ex& f) const {
        if (!f.has(x) || f.is_equal(x)) return;
        if (GiNaC::is_a<GiNaC::add>(f) || GiNaC::is_a<GiNaC::mul>(f)) {
            for (std::size_t i = 0; i < f.nops(); ++i) (*this)(f.op(i));
            return;
        }
        if (GiNaC::is_a<GiNaC::power>(f)) {
            const ex b = f.op(0), e = f.op(1);
            if (e.has(x)) {  // c^g(x) = exp(g log c): a positive number c
                if (b.has(x) || !GiNaC::is_a<GiNaC::numeric>(b) || !GiNaC::ex_to<GiNaC::numeric>(b).is_positive())
                    undecided(f);
                (*this)(e);
                return;
            }
            (*this)(b);
            if (!GiNaC::is_a<GiNaC::numeric>(e) || !GiNaC::ex_to<GiNaC::numeric>(e).is_real()) undecided(f);
            const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(e);
            if (n.is_pos_integer()) return;
            require_sign(f, b, n.is_positive());
            return;
        }
        using namespace GiNaC;
        if (is_ex_the_function(f, exp) || is_ex_the_function(f, sin) || is_ex_the_function(f, cos) ||
            is_ex_the_function(f, sinh) || is_ex_the_function(f, cosh) || is_ex_the_function(f, tanh) ||
            is_ex_the_function(f, atan) || is_ex_the_function(f, abs)) {
            (*this)(f.op(0));
            return;
        }
        if (is_ex_the_function(f, log)) {
            (*this)(f.op(0));
            require_sign(f, f.op(0), false);
            return;
        }
        undecided(f);
    }
};

}  // namespace

void require_finite_on_half_line(const ex& f, const ex& x, const std::string& what) {
    if (!GiNaC::is_a<GiNaC::symbol>(x)) throw type_error("require_finite_on_half_line: the variable is not a symbol");
    half_line_check{GiNaC::ex_to<GiNaC::symbol>(x), what}(f);
}

}  // namespace symrep::num
