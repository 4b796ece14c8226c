// symrep/scalar/limit.cpp -- the limit at a removable singularity (see limit.h).
#include "scalar/limit.h"

#include <cstdint>
#include <iomanip>
#include <new>
#include <sstream>
#include <string>

#include "core/error.h"
#include "scalar/equality.h"
#include "scalar/scalar.h"

namespace symrep {

namespace {

const char* const no_expansion = "no power-series expansion";

/// The direction of line j: a nonzero rational per parameter from a fixed
/// pseudo-random sequence (deterministic; no two lines parallel in practice).
std::vector<GiNaC::numeric> direction(std::size_t j, std::size_t n) {
    std::uint64_t s = 0x9E3779B97F4A7C15ull * (j + 1);
    std::vector<GiNaC::numeric> d;
    for (std::size_t i = 0; i < n; ++i) {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        const int p = int((s >> 33) % 29) + 1, q = int((s >> 17) % 13) + 1;
        d.push_back(GiNaC::numeric(((s >> 9) & 1) ? -p : p, q));
    }
    return d;
}

/// A short numeric rendering of a limit for messages ("" when it is not a number).
std::string approx(const GiNaC::ex& x) {
    GiNaC::numeric v;
    if (!evaluate_numeric(x, 20, v) || !v.is_real()) return "";
    std::ostringstream os;
    os << std::setprecision(10) << v.to_double();
    return os.str();
}

struct line_outcome {
    bool on_singular_set = false;  ///< the line lies in the singular set (the expression divides by zero on it)
    unsigned rows = 0;             ///< the rows of a matrix expression (0: a scalar)
    std::vector<GiNaC::ex> limits; ///< one per entry, row by row
};

/// B^q (q a non-integer rational) with B a polynomial in mu of lowest degree L > 0
/// (B vanishes at mu = 0) as mu^(L q) (B/mu^L)^q, for L q an integer (true for mu > 0).
/// GiNaC expands a function of such a root by Taylor's formula, whose derivatives divide
/// by B at 0 (sin(sqrt(4 k - c^2) t/2) on a line through c = 2, k = 1): so it cannot.
struct roots_out_of_mu : GiNaC::map_function {
    const GiNaC::symbol& mu;
    explicit roots_out_of_mu(const GiNaC::symbol& m) : mu(m) {}
    GiNaC::ex operator()(const GiNaC::ex& x) override {
        const GiNaC::ex y = x.map(*this);
        if (!GiNaC::is_a<GiNaC::power>(y) || !GiNaC::is_a<GiNaC::numeric>(y.op(1)) || !y.op(0).has(mu)) return y;
        const GiNaC::numeric q = GiNaC::ex_to<GiNaC::numeric>(y.op(1));
        if (!q.is_rational() || q.is_integer()) return y;
        const GiNaC::ex b = GiNaC::expand(y.op(0));
        if (!b.is_polynomial(mu)) return y;
        const int L = b.ldegree(mu);
        if (L <= 0 || !(q * L).is_integer()) return y;
        return GiNaC::pow(mu, q * L) * GiNaC::pow(GiNaC::expand(b / GiNaC::pow(mu, L)), q);
    }
};

/// sin, cos, sinh, cosh of a + i b (a, b free of i) in real functions of a and b:
/// sin(a + i b) = sin a cosh b + i cos a sinh b, ... The series of a form whose square
/// root is imaginary on one side (sqrt(4 k m - c^2) at k = 0) has coefficients such as
/// 1 - e^(-9/8) (cos(9 i/8) - i sin(9 i/8)), 0, which the zero test proves only in this form.
struct real_arguments : GiNaC::map_function {
    GiNaC::ex operator()(const GiNaC::ex& x) override {
        const GiNaC::ex y = x.map(*this);
        const bool sin = GiNaC::is_the_function<GiNaC::sin_SERIAL>(y), cos = GiNaC::is_the_function<GiNaC::cos_SERIAL>(y),
                   sinh = GiNaC::is_the_function<GiNaC::sinh_SERIAL>(y),
                   cosh = GiNaC::is_the_function<GiNaC::cosh_SERIAL>(y);
        if (!(sin || cos || sinh || cosh) || !y.op(0).has(GiNaC::I)) return y;
        const GiNaC::ex u = GiNaC::expand(y.op(0));
        GiNaC::ex a = 0, b = 0;
        for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(u) ? u.nops() : 1); ++i) {
            const GiNaC::ex term = GiNaC::is_a<GiNaC::add>(u) ? u.op(i) : u;
            if (!term.has(GiNaC::I)) {
                a += term;
                continue;
            }
            const GiNaC::ex v = GiNaC::expand(-GiNaC::I * term);
            if (v.has(GiNaC::I)) return y;
            b += v;
        }
        if (sin) return GiNaC::sin(a) * GiNaC::cosh(b) + GiNaC::I * GiNaC::cos(a) * GiNaC::sinh(b);
        if (cos) return GiNaC::cos(a) * GiNaC::cosh(b) - GiNaC::I * GiNaC::sin(a) * GiNaC::sinh(b);
        // sinh(a + i b) = sinh a cos b + i cosh a sin b, cosh(a + i b) = cosh a cos b + i sinh a sin b
        if (sinh) return GiNaC::sinh(a) * GiNaC::cos(b) + GiNaC::I * GiNaC::cosh(a) * GiNaC::sin(b);
        return GiNaC::cosh(a) * GiNaC::cos(b) + GiNaC::I * GiNaC::sinh(a) * GiNaC::sin(b);
    }
};

/// The mu^0 coefficient of x's series at mu = 0; the negative powers must be proved 0.
GiNaC::ex limit_along(const GiNaC::ex& x0, const GiNaC::symbol& mu) {
    GiNaC::ex s;
    try {
        roots_out_of_mu pull(mu);
        const GiNaC::ex x = pull(x0);
        s = x.series(mu == 0, 1);
    } catch (const error&) {  // an interruption, the time limit
        throw;
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception&) {
        throw domain_error(std::string("the limit cannot be found: the expression has ") + no_expansion +
                           " along a line through the point (an essential singularity, or a root that is not a series)");
    }
    if (!GiNaC::is_a<GiNaC::pseries>(s)) return s;  // no mu in it
    const GiNaC::pseries& ps = GiNaC::ex_to<GiNaC::pseries>(s);
    GiNaC::ex value = 0;
    bool order_beyond = ps.is_terminating();
    for (std::size_t i = 0; i < ps.nops(); ++i) {
        real_arguments real;
        const GiNaC::ex c = real(ps.coeffop(i));
        const int k = GiNaC::ex_to<GiNaC::numeric>(ps.exponop(i)).to_int();
        if (GiNaC::is_order_function(c)) {
            if (k >= 1) order_beyond = true;
            continue;
        }
        if (k == 0) value = c;
        if (k < 0 && !c.is_zero() && !is_zero_scalar(c)) {
            const zero_decision z = decide_zero(c);
            if (z.is_zero == truth::no)
                throw domain_error("there is no limit: the expression is unbounded near the point (a pole, not a removable "
                                   "singularity)");
            if (z.is_zero == truth::unknown)
                throw domain_error("the limit cannot be found: whether a term that grows near the point vanishes "
                                   "cannot be decided");
        }
    }
    if (!order_beyond)
        throw domain_error("the limit cannot be found: the expansion along a line through the point stops before "
                           "its constant term");
    return value;
}

/// The limits of every entry along the half-line p0 + sign mu^power d.
line_outcome along_line(std::size_t n, const near_point& near, const std::vector<GiNaC::numeric>& d, int sign,
                        const GiNaC::symbol& mu, int power) {
    std::vector<GiNaC::ex> offsets;
    for (std::size_t i = 0; i < n; ++i) offsets.push_back(sign * d[i] * GiNaC::pow(mu, power));
    line_outcome out;
    GiNaC::ex x;
    try {
        x = near(offsets);
    } catch (const std::exception& e) {
        if (!is_division_by_zero(e)) throw;
        out.on_singular_set = true;
        return out;
    }
    if (GiNaC::is_a<GiNaC::matrix>(x)) out.rows = GiNaC::ex_to<GiNaC::matrix>(x).rows();
    if (GiNaC::is_a<GiNaC::matrix>(x))
        for (std::size_t i = 0; i < x.nops(); ++i) out.limits.push_back(limit_along(x.op(i), mu));
    else
        out.limits.push_back(limit_along(x, mu));
    return out;
}

}  // namespace

bool is_division_by_zero(const std::exception& x) {
    if (dynamic_cast<const GiNaC::pole_error*>(&x)) return true;
    return dynamic_cast<const domain_error*>(&x) && std::string(x.what()).find("division by zero") != std::string::npos;
}

namespace {

GiNaC::ex limit_on_lines(std::size_t n, const near_point& near, int power) {
    const GiNaC::possymbol mu("mu");
    // the first direction from both sides (a limit that differs between the sides:
    // |k|/k), a second one from one side (one that depends on the direction:
    // x y/(x^2 + y^2)); a direction whose line lies in the singular set (the
    // expression divides by zero all along it) is replaced by the next one
    std::vector<std::vector<GiNaC::ex>> found;
    std::size_t directions = 0;
    unsigned rows = 0;
    for (std::size_t j = 0; j < 6 && directions < 2; ++j) {
        const std::vector<GiNaC::numeric> d = direction(j, n);
        const line_outcome plus = along_line(n, near, d, 1, mu, power);
        if (plus.on_singular_set) continue;
        if (directions == 0) {
            const line_outcome minus = along_line(n, near, d, -1, mu, power);
            if (minus.on_singular_set) continue;
            found.push_back(minus.limits);
        }
        rows = plus.rows;
        found.push_back(plus.limits);
        ++directions;
    }
    if (directions < 2)
        throw domain_error("the limit cannot be found: the expression divides by zero on every line tried through "
                           "the point");
    for (std::size_t k = 1; k < found.size(); ++k)
        for (std::size_t i = 0; i < found[0].size(); ++i) {
            const GiNaC::ex diff = found[k][i] - found[0][i];
            if (diff.is_zero() || is_zero_scalar(diff)) continue;
            const zero_decision z = decide_zero(diff);
            if (z.is_zero == truth::yes) continue;
            if (z.is_zero == truth::no) {
                const std::string a = approx(found[0][i]), b = approx(found[k][i]);
                throw domain_error(std::string("there is no limit: it depends on the direction of approach") +
                                   (a.empty() || b.empty() ? std::string()
                                                           : " (" + a + " along one half-line, " + b + " along another)"));
            }
            throw domain_error("the limit cannot be found: whether the limits along different lines through the "
                               "point agree cannot be decided");
        }
    if (rows == 0) return found[0][0];
    GiNaC::matrix m(rows, unsigned(found[0].size()) / rows);
    for (std::size_t i = 0; i < found[0].size(); ++i) m(unsigned(i) / m.cols(), unsigned(i) % m.cols()) = found[0][i];
    return m;
}

}  // namespace

GiNaC::ex limit_at_point(std::size_t n, const near_point& near) {
    // lambda = mu first (half the degrees: faster); where a root of a quantity that
    // vanishes linearly makes that a Puiseux series, lambda = mu^2
    try {
        return limit_on_lines(n, near, 1);
    } catch (const domain_error& x) {
        if (std::string(x.what()).find(no_expansion) == std::string::npos) throw;
    }
    return limit_on_lines(n, near, 2);
}

}  // namespace symrep
