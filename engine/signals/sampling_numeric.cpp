// symrep/signals/sampling_numeric.cpp -- see sampling_numeric.h.
#include "symrep/signals/sampling_numeric.h"

#include <cmath>
#include <complex>
#include <sstream>
#include <vector>

#include <cln/real.h>
#include <cln/rational.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include "symrep/core/error.h"
#include "symrep/numeric/reference.h"
#include "symrep/scalar/equality.h"
#include "symrep/scalar/scalar.h"

namespace symrep::signals {

using GiNaC::ex;
using GiNaC::numeric;

namespace {


numeric to_float(const numeric& x) { return GiNaC::ex_to<numeric>(ex(x).evalf()); }

numeric ten_to(long k) { return GiNaC::pow(numeric(10), numeric(k)); }

// p and p' at z (c: the coefficients c_0 .. c_n)
void horner(const std::vector<numeric>& c, const numeric& z, numeric& p, numeric& dp) {
    p = 0;
    dp = 0;
    for (std::size_t k = c.size(); k-- > 0;) {
        dp = dp * z + p;
        p = p * z + c[k];
    }
}

// The coefficients of prod (l - x_i), lowest first.
std::vector<numeric> from_roots(const std::vector<numeric>& x) {
    std::vector<numeric> e{numeric(1)};
    for (const numeric& r : x) {
        std::vector<numeric> next(e.size() + 1, numeric(0));
        for (std::size_t k = 0; k < e.size(); ++k) {
            next[k + 1] += e[k];
            next[k] -= r * e[k];
        }
        e = std::move(next);
    }
    return e;
}

struct numeric_result {
    std::vector<numeric> q;      ///< coefficients of q(l), real, lowest first
    std::vector<numeric> shift;  ///< coefficients of the interpolant c(z) of e^(h z), real
    numeric bound;               ///< on every coefficient of q
    bool separated_mu = false;   ///< the disks around the e^(h r_i) are pairwise disjoint
};

[[noreturn]] void not_separated() {
    throw algebra_error("sampling: the roots of p cannot be separated at 90 digits (a repeated or nearly repeated "
                        "root): the numeric form is refused");
}

numeric_result compute(const std::vector<numeric>& exact_c, const numeric& h_exact, long digits) {
    const num::digits_scope scope(digits);
    const std::size_t n = exact_c.size() - 1;
    std::vector<numeric> c;
    for (const numeric& x : exact_c) c.push_back(to_float(x));
    const numeric h = to_float(h_exact);
    // initial roots: the eigenvalues of the companion matrix (double)
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(Eigen::Index(n), Eigen::Index(n));
    for (std::size_t j = 0; j + 1 < n; ++j) C(Eigen::Index(j + 1), Eigen::Index(j)) = 1;
    for (std::size_t k = 0; k < n; ++k) C(Eigen::Index(k), Eigen::Index(n - 1)) = -c[k].to_double();
    const Eigen::VectorXcd ev = Eigen::EigenSolver<Eigen::MatrixXd>(C, false).eigenvalues();
    std::vector<numeric> r, radius;
    const numeric slack = ten_to(5 - digits);  // the rounding of the evaluation itself
    for (Eigen::Index i = 0; i < ev.size(); ++i) {
        numeric z = to_float(num::exact_rational(ev[i].real())) +
                    GiNaC::ex_to<numeric>(GiNaC::I) * to_float(num::exact_rational(ev[i].imag()));
        numeric p, dp;
        for (int it = 0; it < 200; ++it) {
            horner(c, z, p, dp);
            if (dp.is_zero()) not_separated();
            const numeric step = p / dp;
            z -= step;
            if (GiNaC::abs(step) <= ten_to(-digits) * std::max(numeric(1), GiNaC::abs(z))) break;
        }
        horner(c, z, p, dp);
        if (dp.is_zero()) not_separated();
        r.push_back(z);
        radius.push_back(numeric(long(n)) * GiNaC::abs(p / dp) + slack * std::max(numeric(1), GiNaC::abs(z)));
    }
    // disjoint disks: each holds exactly one root
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            if (GiNaC::abs(r[i] - r[j]) <= radius[i] + radius[j]) not_separated();
    std::vector<numeric> mu, absmu, eps;
    for (std::size_t i = 0; i < n; ++i) {
        mu.push_back(GiNaC::exp(h * r[i]));
        absmu.push_back(GiNaC::abs(mu.back()));
        eps.push_back(absmu.back() * (GiNaC::exp(GiNaC::abs(h) * radius[i]) - 1) + slack * absmu.back());
    }
    numeric_result out;
    out.separated_mu = true;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            if (GiNaC::abs(mu[i] - mu[j]) <= eps[i] + eps[j]) out.separated_mu = false;
    // q = prod (l - mu_i): real coefficients (the roots come in conjugate pairs)
    for (const numeric& x : from_roots(mu)) out.q.push_back(x.real());
    // the bound: prod (l + |mu_i| + eps_i) - prod (l + |mu_i|), coefficient by coefficient
    std::vector<numeric> up, base;
    for (std::size_t i = 0; i < n; ++i) {
        up.push_back(-(absmu[i] + eps[i]));
        base.push_back(-absmu[i]);
    }
    const std::vector<numeric> U = from_roots(up), B = from_roots(base);
    out.bound = 0;
    for (std::size_t k = 0; k < U.size(); ++k) out.bound = std::max(out.bound, GiNaC::abs(U[k] - B[k]) + slack);
    // the interpolant of e^(h z) at the roots (Newton's divided differences), real coefficients
    std::vector<numeric> dd = mu;
    for (std::size_t j = 1; j < n; ++j)
        for (std::size_t i = n - 1; i >= j; --i) dd[i] = (dd[i] - dd[i - 1]) / (r[i] - r[i - j]);
    std::vector<numeric> poly{dd[n - 1]};  // Horner on the Newton form, lowest first
    for (std::size_t k = n - 1; k-- > 0;) {
        std::vector<numeric> next(poly.size() + 1, numeric(0));
        for (std::size_t m = 0; m < poly.size(); ++m) {
            next[m + 1] += poly[m];
            next[m] -= r[k] * poly[m];
        }
        next[0] += dd[k];
        poly = std::move(next);
    }
    for (const numeric& x : poly) out.shift.push_back(x.real());
    return out;
}

// x rounded to `digits` significant digits, as a float that prints with them.
ex rounded(const numeric& x, long digits) { return num::round_digits(ex(x), digits); }

// x > 0 rounded up to 3 significant digits: the exact m 10^k (m = 100 .. 1000) and its text "d.dde-K".
numeric round_up(const numeric& x, std::string& text) {
    const long e = long(std::floor(std::log10(x.to_double())));
    const numeric scale = ten_to(2 - e);
    const cln::cl_I m = cln::ceiling1(cln::the<cln::cl_R>((x * scale).to_cl_N()));
    const numeric mn(m);
    std::ostringstream os;
    const long mi = mn.to_long();
    os << mi / 100 << "." << (mi % 100 < 10 ? "0" : "") << mi % 100 << "e" << e;
    text = os.str();
    return mn / scale;
}

}  // namespace

sampling sample_numerically(const representation& R, const ex& h, const GiNaC::symbol& l, const std::string& why) {
    numeric hv;
    if (!evaluate_numeric(h, 120, hv) || !hv.is_real())
        throw domain_error("sampling: " + why + "; the numeric form needs a real number as the step, not " +
                           message_text(h));
    const ex p = GiNaC::expand(R.p);
    const int n = p.degree(R.X);
    std::vector<numeric> c;
    for (int k = 0; k <= n; ++k) {
        numeric v;
        if (!evaluate_numeric(p.coeff(R.X, k), 120, v) || !v.is_real())
            throw domain_error("sampling: " + why + "; the numeric form needs real numbers as the coefficients of p, "
                               "not " + message_text(p.coeff(R.X, k)));
        c.push_back(v);
    }
    const numeric_result low = compute(c, hv, 60), high = compute(c, hv, 90);
    // exp(h d) to 30 digits where 60 and 90 digits agree to 35
    const numeric agree = ten_to(-35);
    coeffs shift(R.A->dim(), ex(0)), dk = R.A->unit();
    for (int k = 0; k < n; ++k) {
        const numeric a = low.shift[std::size_t(k)], b = high.shift[std::size_t(k)];
        if (GiNaC::abs(a - b) > agree * std::max(numeric(1), GiNaC::abs(b)))
            throw algebra_error("sampling: exp(h d) is ill-conditioned at these roots (60 and 90 digits disagree): the "
                                "numeric form is refused");
        shift = R.A->add(shift, R.A->scale(rounded(b, 30), dk));
        if (k + 1 < n) dk = R.A->multiply(dk, R.d);
    }
    sampling s;
    s.shift = shift;
    ex q = 0;
    numeric largest = 0;
    for (int k = 0; k <= n; ++k) {
        const numeric x = high.q[std::size_t(k)];
        largest = std::max(largest, GiNaC::abs(x));
        q += (k == n ? ex(1) : rounded(x, 30)) * GiNaC::pow(l, k);
    }
    s.q = q;
    // the bound: the numeric error and the rounding to 30 digits
    std::string bound_text;
    s.error_bound = round_up(high.bound + largest * ten_to(-29), bound_text);
    s.numeric = true;
    s.aliasing = high.separated_mu ? truth::no : truth::unknown;
    std::ostringstream os;
    os << "numeric (" << why << "): q(l) and exp(h d) from the roots of p at 90 digits, printed with 30; every "
       << "coefficient of q is within " << bound_text
       << " of the exact one; "
       << (high.separated_mu ? "no aliasing at step " + message_text(h) + ": the e^(h r) are distinct"
                             : "aliasing at step " + message_text(h) + " not decided (numeric roots)");
    s.report = os.str();
    return s;
}

}  // namespace symrep::signals
