// symrep/numeric/quadrature.cpp -- integral objects by Gauss-Kronrod (quadrature.h).
#include "numeric/quadrature.h"

#include <algorithm>
#include <cmath>
#include <vector>
#include <limits>
#include <sstream>
#include <string>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "core/error.h"
#include "scalar/scalar.h"
#include "numeric/evaluator.h"
#include "numeric/reference.h"

namespace symrep::num {

using GiNaC::ex;

bool has_integral(const ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::integral>(*it)) return true;
    return false;
}

namespace {

// Gauss-Kronrod (61 points, adaptive to depth 15, 1e-14 of the L1 norm) on a double function.
// Boost's error estimate (QUADPACK's rescaled |K - G|) is pessimistic for a smooth integrand
// on a short interval: 2e-14 for int_0^0.002 sin(x + x^2/2) = 2.08e-6, when the value is right
// to the last digits. When it stays above 1e-8 of the L1 norm, the two halves are integrated
// again: their sum agreeing with the whole to 1e-12 confirms the value; otherwise it is refused.
template <class F>
double gauss_kronrod(F&& g, double a, double b, bool& finite, double* l1_out = nullptr) {
    using rule = boost::math::quadrature::gauss_kronrod<double, 61>;
    if (l1_out) *l1_out = 0.0;
    if (a == b) return 0.0;
    auto not_finite = [&] {
        return domain_error("integral: the integrand is not finite on [" + std::to_string(a) + ", " +
                            std::to_string(b) + "]");
    };
    const double floor = std::numeric_limits<double>::min();
    // one 61-point rule, then the two halves: agreeing to 1e-13 of the L1 norm they settle a
    // smooth integrand in 183 evaluations (the adaptive rule would chase an unreachable estimate)
    double error = 0, l1 = 0;
    const double whole = rule::integrate(g, a, b, 0, 0.0, &error, &l1);
    if (!finite) throw not_finite();
    if (l1_out) *l1_out = l1;
    if (error <= 1e-14 * std::max(l1, floor)) return whole;
    const double m = a + (b - a) / 2;
    double e1 = 0, e2 = 0, n1 = 0, n2 = 0;
    const double halves = rule::integrate(g, a, m, 0, 0.0, &e1, &n1) + rule::integrate(g, m, b, 0, 0.0, &e2, &n2);
    if (!finite) throw not_finite();
    if (std::abs(halves - whole) <= 1e-13 * std::max({l1, n1 + n2, floor})) {
        if (l1_out) *l1_out = n1 + n2;
        return halves;
    }
    // otherwise adaptively, to depth 15
    const double value = rule::integrate(g, a, b, 15, 1e-14, &error, &l1);
    if (!finite) throw not_finite();
    if (l1_out) *l1_out = l1;
    if (error <= 1e-8 * std::max(l1, floor)) return value;
    std::ostringstream os;
    os << "integral: the quadrature over [" << a << ", " << b << "] did not converge (error estimate " << error
       << " for the value " << value << ")";
    throw domain_error(os.str());
}

}  // namespace

double integrate_numerically(const ex& variable, double a, double b, const ex& integrand, double* l1) {
    if (!std::isfinite(a) || !std::isfinite(b))
        throw type_error("integral: the limits must be finite numbers");
    if (l1) *l1 = 0.0;
    if (a == b) return 0.0;
    const compiled_function f = compile(integrand, {variable});
    bool finite = true;
    auto g = [&](double x) {
        double y;
        f.eval(&x, &y);
        if (!std::isfinite(y)) finite = false;
        return y;
    };
    return gauss_kronrod(g, a, b, finite, l1);
}

double integrate_nested(const ex& x, double a, double b, const ex& f, double* l1) {
    // the inner integrals int_c^x g(s) ds (c a number, g in s alone) become the variables y_j
    std::vector<ex> vars{x};
    std::vector<compiled_function> inner;
    std::vector<double> lower;
    GiNaC::exmap to_y;
    for (auto it = f.preorder_begin(); it != f.preorder_end(); ++it) {
        if (!GiNaC::is_a<GiNaC::integral>(*it) || to_y.count(*it)) continue;
        const ex s = it->op(0), c = it->op(1), g = it->op(3);
        auto refuse = [&] {
            return domain_error("integral: the nested integral " + message_text(*it) + " is not of the form int_c^" +
                                message_text(x) + " g(s) ds with g in its own variable s and a number c");
        };
        if (!GiNaC::is_a<GiNaC::symbol>(s) || s.is_equal(x) || !it->op(2).is_equal(x) || has_integral(g)) throw refuse();
        for (auto jt = c.preorder_begin(); jt != c.preorder_end(); ++jt)
            if (GiNaC::is_a<GiNaC::symbol>(*jt)) throw refuse();
        for (auto jt = g.preorder_begin(); jt != g.preorder_end(); ++jt)
            if (GiNaC::is_a<GiNaC::symbol>(*jt) && !jt->is_equal(s)) throw refuse();
        const GiNaC::symbol y;
        to_y[*it] = y;
        vars.push_back(y);
        inner.push_back(compile(g, {s}));
        lower.push_back(accurate_double(c));
    }
    const ex outer = f.subs(to_y, GiNaC::subs_options::no_pattern);
    for (auto it = outer.preorder_begin(); it != outer.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::integral>(*it) ||
            (GiNaC::is_a<GiNaC::symbol>(*it) && std::find(vars.begin(), vars.end(), *it) == vars.end()))
            throw domain_error("integral: the integrand " + message_text(f) + " has symbols without values");
    const compiled_function F = compile(outer, vars);
    bool finite = true;
    auto h = [&](double t) {
        // each inner integral by the same rule at this node of the outer one
        std::vector<double> at(vars.size());
        at[0] = t;
        for (std::size_t j = 0; j < inner.size(); ++j) {
            const compiled_function& g = inner[j];
            at[j + 1] = gauss_kronrod(
                [&](double s) {
                    double y;
                    g.eval(&s, &y);
                    if (!std::isfinite(y)) finite = false;
                    return y;
                },
                lower[j], t, finite);
        }
        double y;
        F.eval(at.data(), &y);
        if (!std::isfinite(y)) finite = false;
        return y;
    };
    return gauss_kronrod(h, a, b, finite, l1);
}

ex integrals_as_numbers(const ex& e) {
    if (!has_integral(e)) return e;
    if (GiNaC::is_a<GiNaC::integral>(e)) {
        const ex x = e.op(0);
        const ex f = integrals_as_numbers(e.op(3));
        const ex a = e.op(1), b = e.op(2);
        if (!GiNaC::is_a<GiNaC::symbol>(x)) return e;
        // the limits as doubles (exact expressions such as 7/3 or pi)
        auto limit = [&](const ex& l, double& out) {
            if (l.has(x)) return false;
            for (auto it = l.preorder_begin(); it != l.preorder_end(); ++it)
                if (GiNaC::is_a<GiNaC::symbol>(*it)) return false;
            out = accurate_double(l);
            return true;
        };
        double A, B;
        if (!limit(a, A) || !limit(b, B)) return e;
        if (has_integral(f)) return GiNaC::numeric(integrate_nested(x, A, B, f));
        for (auto it = f.preorder_begin(); it != f.preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::symbol>(*it) && !it->is_equal(x)) return e;
        return GiNaC::numeric(integrate_numerically(x, A, B, f));
    }
    return e.map([](const ex& c) { return integrals_as_numbers(c); });
}

}  // namespace symrep::num
