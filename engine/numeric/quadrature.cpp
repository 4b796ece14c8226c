// symrep/numeric/quadrature.cpp -- integral objects by Gauss-Kronrod (quadrature.h).
#include "numeric/quadrature.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "core/error.h"
#include "numeric/evaluator.h"
#include "numeric/reference.h"

namespace symrep::num {

using GiNaC::ex;

bool has_integral(const ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::integral>(*it)) return true;
    return false;
}

double integrate_numerically(const ex& variable, double a, double b, const ex& integrand) {
    if (!std::isfinite(a) || !std::isfinite(b))
        throw type_error("integral: the limits must be finite numbers");
    if (a == b) return 0.0;
    const compiled_function f = compile(integrand, {variable});
    bool finite = true;
    auto g = [&](double x) {
        double y;
        f.eval(&x, &y);
        if (!std::isfinite(y)) finite = false;
        return y;
    };
    double error = 0, l1 = 0;
    const double value = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(g, a, b, 15, 1e-14, &error, &l1);
    if (!finite)
        throw domain_error("integral: the integrand is not finite on [" + std::to_string(a) + ", " + std::to_string(b) + "]");
    if (!(error <= 1e-8 * std::max(l1, std::numeric_limits<double>::min()))) {
        std::ostringstream os;
        os << "integral: the quadrature over [" << a << ", " << b << "] did not converge (error estimate " << error
           << " for the value " << value << ")";
        throw domain_error(os.str());
    }
    return value;
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
        for (auto it = f.preorder_begin(); it != f.preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::symbol>(*it) && !it->is_equal(x)) return e;
        return GiNaC::numeric(integrate_numerically(x, A, B, f));
    }
    return e.map([](const ex& c) { return integrals_as_numbers(c); });
}

}  // namespace symrep::num
