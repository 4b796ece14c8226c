// symrep/scalar/limit.cpp -- the limit at a removable singularity (see limit.h).
#include "symrep/scalar/limit.h"

#include <algorithm>
#include <cstdint>
#include <iomanip>
#include <new>
#include <optional>
#include <sstream>
#include <string>

#include "symrep/core/error.h"
#include "symrep/scalar/equality.h"
#include "symrep/scalar/scalar.h"

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

/// sqrt(c P^2 R) as |P| sqrt(c R) near the point, |P| = sign(P(0)) P where P(0) != 0
/// (P keeps its sign in a neighbourhood): the coefficients of an expansion with the
/// other offsets symbolic meet sqrt(-(3 + e)^2), which is i (3 + e) there.
struct roots_near_point : GiNaC::map_function {
    const GiNaC::exmap& zero;
    explicit roots_near_point(const GiNaC::exmap& z) : zero(z) {}
    GiNaC::ex operator()(const GiNaC::ex& x) override {
        const GiNaC::ex y = x.map(*this);
        if (!GiNaC::is_a<GiNaC::power>(y) || !GiNaC::is_a<GiNaC::numeric>(y.op(1))) return y;
        const GiNaC::numeric k = GiNaC::ex_to<GiNaC::numeric>(y.op(1));
        if (!k.is_rational() || k.is_integer() || k.denom() != 2) return y;
        GiNaC::ex f;
        try {
            f = GiNaC::factor(GiNaC::expand(y.op(0)));
        } catch (const std::exception&) {
            return y;
        }
        GiNaC::ex out = 1, rest = 1;
        bool pulled = false;
        for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::mul>(f) ? f.nops() : 1); ++i) {
            const GiNaC::ex p = GiNaC::is_a<GiNaC::mul>(f) ? f.op(i) : f;
            if (GiNaC::is_a<GiNaC::power>(p) && GiNaC::is_a<GiNaC::numeric>(p.op(1)) &&
                GiNaC::ex_to<GiNaC::numeric>(p.op(1)).is_integer() && GiNaC::ex_to<GiNaC::numeric>(p.op(1)) >= 2) {
                const GiNaC::ex P0 = p.op(0).subs(zero);
                const int m = GiNaC::ex_to<GiNaC::numeric>(p.op(1)).to_int();
                if (GiNaC::is_a<GiNaC::numeric>(P0) && GiNaC::ex_to<GiNaC::numeric>(P0).is_real() && !P0.is_zero()) {
                    const GiNaC::ex absP = GiNaC::ex_to<GiNaC::numeric>(P0).is_positive() ? p.op(0) : -p.op(0);
                    out *= GiNaC::pow(absP, (m / 2) * 2 * k);
                    rest *= GiNaC::pow(p.op(0), m % 2);
                    pulled = true;
                    continue;
                }
            }
            rest *= p;
        }
        return pulled ? out * GiNaC::pow(rest, k) : y;
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

namespace {

GiNaC::ex lines_limit(std::size_t n, const near_point& near) {
    // lambda = mu first (half the degrees: faster); where a root of a quantity that
    // vanishes linearly makes that a Puiseux series, lambda = mu^2
    try {
        return limit_on_lines(n, near, 1);
    } catch (const domain_error& x) {
        if (std::string(x.what()).find(no_expansion) == std::string::npos) throw;
    }
    return limit_on_lines(n, near, 2);
}

/// x at the point (every offset 0), or nothing where that divides by zero.
std::optional<GiNaC::ex> at_point(const GiNaC::ex& x, const GiNaC::exmap& zero) {
    try {
        return subs_checked(x, zero);
    } catch (const std::exception& e) {
        if (is_division_by_zero(e)) return std::nullopt;
        throw;
    }
}

/// The bases of the negative powers in x that contain an offset and vanish at the point.
void vanishing_bases(const GiNaC::ex& x, const GiNaC::lst& offsets, const GiNaC::exmap& zero, GiNaC::exset& out) {
    for (auto it = x.preorder_begin(); it != x.preorder_end(); ++it) {
        if (!GiNaC::is_a<GiNaC::power>(*it) || !GiNaC::is_a<GiNaC::numeric>(it->op(1)) ||
            !GiNaC::ex_to<GiNaC::numeric>(it->op(1)).real().is_negative())
            continue;
        const GiNaC::ex& b = it->op(0);
        if (std::none_of(offsets.begin(), offsets.end(), [&](const GiNaC::ex& e) { return b.has(e); })) continue;
        const auto b0 = at_point(b, zero);
        if (!b0 || proved_zero(*b0)) out.insert(b);
    }
}

/// The proof of a limit in several parameters (see limit.h): the singular bases
/// are one quantity Q (up to constant factors); with Q = q (and, where that alone
/// does not, one parameter v eliminated by Q(v) = q, v an analytic function of q
/// by the implicit function theorem: dQ/dv != 0 at the point), the expression G is
/// regular in the offsets and q^(1/2) away from q itself, and its expansion in
/// mu, q = +-mu^2, has no negative powers, identically in the other offsets: G
/// is then bounded near the point and its limit is the mu^0 coefficient at the
/// point, the same from both signs of q. Nothing where that is not shown.
std::optional<GiNaC::ex> limit_through_quantity(const GiNaC::ex& x, const GiNaC::lst& offsets,
                                                const GiNaC::exmap& zero) {
    GiNaC::exset bases;
    vanishing_bases(x, offsets, zero, bases);
    if (bases.empty()) return std::nullopt;  // singular through a function (log 0, tan at a pole)
    const GiNaC::ex Q0 = GiNaC::expand(*bases.begin());
    const GiNaC::symbol q("q");
    GiNaC::exmap zq = zero;
    zq[q] = 0;
    const GiNaC::possymbol mu("mu");
    const auto regular_away_from_mu = [&](const GiNaC::ex& G) {
        // a negative power's base is nonzero at the point, or mu^L times a polynomial in mu
        // that is nonzero there; every function's argument is finite at the point
        GiNaC::exmap zm = zq;
        zm[mu] = 0;
        for (auto it = G.preorder_begin(); it != G.preorder_end(); ++it) {
            if (GiNaC::is_a<GiNaC::power>(*it) && GiNaC::is_a<GiNaC::numeric>(it->op(1)) &&
                GiNaC::ex_to<GiNaC::numeric>(it->op(1)).real().is_negative()) {
                GiNaC::ex B = it->op(0);
                if (B.has(mu)) {
                    B = GiNaC::expand(B);
                    if (!B.is_polynomial(mu)) return false;
                    B = B.coeff(mu, B.ldegree(mu));
                }
                const auto b0 = at_point(B, zm);
                if (!b0 || proved_zero(*b0)) return false;
            }
            if (GiNaC::is_a<GiNaC::function>(*it) || (GiNaC::is_a<GiNaC::power>(*it) && !GiNaC::is_a<GiNaC::numeric>(it->op(1))))
                for (std::size_t i = 0; i < it->nops(); ++i)
                    if (!at_point(it->op(i), zm)) return false;
        }
        return true;
    };
    const auto proved = [&](const GiNaC::ex& G) -> std::optional<GiNaC::ex> {
        std::optional<GiNaC::ex> side[2];
        for (int s = 0; s < 2; ++s) {
            GiNaC::ex series;
            try {
                roots_out_of_mu pull(mu);
                const GiNaC::ex Gm = pull(G.subs(q == (s == 0 ? 1 : -1) * mu * mu));
                if (!regular_away_from_mu(Gm)) return std::nullopt;
                series = Gm.series(mu == 0, 1);
            } catch (const error&) {
                throw;
            } catch (const std::bad_alloc&) {
                throw;
            } catch (const std::exception&) {
                return std::nullopt;
            }
            GiNaC::ex a0 = series;
            if (GiNaC::is_a<GiNaC::pseries>(series)) {
                const GiNaC::pseries& ps = GiNaC::ex_to<GiNaC::pseries>(series);
                a0 = 0;
                bool beyond = ps.is_terminating();
                for (std::size_t i = 0; i < ps.nops(); ++i) {
                    real_arguments real;
                    roots_near_point near_roots(zero);
                    const GiNaC::ex c0 = ps.coeffop(i);
                    const int k = GiNaC::ex_to<GiNaC::numeric>(ps.exponop(i)).to_int();
                    if (GiNaC::is_order_function(c0)) {
                        if (k >= 1) beyond = true;
                        continue;
                    }
                    const GiNaC::ex c = real(near_roots(c0));
                    if (k == 0) a0 = c;
                    if (k < 0 && !proved_zero(c)) return std::nullopt;  // identically in the offsets
                }
                if (!beyond) return std::nullopt;
            }
            side[s] = at_point(a0, zq);
            if (!side[s]) return std::nullopt;
        }
        if (!proved_zero(*side[0] - *side[1])) return std::nullopt;
        return side[0];
    };
    // the quantity: Q itself, or its one irreducible factor F that vanishes at the point
    // (Q = F^m C, C != 0 there: w^2 - u^2 = (w - u)(w + u) at w = u = 2)
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> quantities;  // (F, Q/F^m as a function of q = F)
    quantities.emplace_back(Q0, q);
    try {
        const GiNaC::ex f = GiNaC::factor(Q0);
        GiNaC::ex F = 0;
        int m = 0, vanishing = 0;
        for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::mul>(f) ? f.nops() : 1); ++i) {
            const GiNaC::ex p = GiNaC::is_a<GiNaC::mul>(f) ? f.op(i) : f;
            const bool pw = GiNaC::is_a<GiNaC::power>(p) && GiNaC::is_a<GiNaC::numeric>(p.op(1));
            const GiNaC::ex base = pw ? p.op(0) : p;
            if (GiNaC::is_a<GiNaC::numeric>(base)) continue;
            const auto b0 = at_point(base, zero);
            if (b0 && !proved_zero(*b0)) continue;
            ++vanishing;
            F = GiNaC::expand(base);
            m = pw ? GiNaC::ex_to<GiNaC::numeric>(p.op(1)).to_int() : 1;
        }
        if (vanishing == 1 && m >= 1 && !GiNaC::is_a<GiNaC::numeric>(GiNaC::normal(F / Q0)))
            quantities.emplace_back(F, GiNaC::pow(q, m) * GiNaC::normal(Q0 / GiNaC::pow(F, m)));
    } catch (const error&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception&) {
    }
    for (const auto& [Q, Qq] : quantities) {
        GiNaC::exmap to_q;
        bool one = true;
        for (const GiNaC::ex& b : bases) {
            const GiNaC::ex r = GiNaC::normal(GiNaC::expand(b) / Q0);
            if (!GiNaC::is_a<GiNaC::numeric>(r)) one = false;  // two quantities vanish at once
            to_q[b] = r * Qq;
        }
        if (!one) return std::nullopt;
        GiNaC::ex G = x.subs(to_q);
        // Q = a v^2 + c (|w|^2): v^2 = (q - c)/a wherever it appears (|w|^2 written out in
        // 12 - w1^2 - w2^2 - w3^2); odd powers of v stay v (a stronger claim)
        for (const GiNaC::ex& v : offsets)
            if (Q.has(v) && Q.is_polynomial(v) && Q.degree(v) == 2 && Q.coeff(v, 1).is_zero() &&
                GiNaC::is_a<GiNaC::numeric>(Q.coeff(v, 2))) {
                G = G.subs(GiNaC::pow(v, 2) == (q - Q.coeff(v, 0)) / Q.coeff(v, 2), GiNaC::subs_options::algebraic);
                break;
            }
        if (auto L = proved(G)) return L;
        // one parameter eliminated: Q = a v^2 + b v + c with b != 0 at the point
        for (const GiNaC::ex& v : offsets) {
            if (!Q.has(v) || !Q.is_polynomial(v) || Q.degree(v) > 2) continue;
            const GiNaC::ex a = Q.coeff(v, 2), b = Q.coeff(v, 1), c = Q.coeff(v, 0);
            const auto b0 = at_point(b, zero);
            if (!b0 || proved_zero(*b0)) continue;
            GiNaC::ex sol;
            if (a.is_zero()) {
                sol = (q - c) / b;
            } else {
                if (!GiNaC::is_a<GiNaC::numeric>(a) || !GiNaC::is_a<GiNaC::numeric>(*b0)) continue;
                // the root that is 0 at the point: -b + sign(b0) |b0| = 0
                const int sgn = GiNaC::ex_to<GiNaC::numeric>(*b0).is_positive() ? 1 : -1;
                sol = (-b + sgn * GiNaC::sqrt(GiNaC::expand(b * b - 4 * a * (c - q)))) / (2 * a);
            }
            if (auto L = proved(G.subs(v == sol))) return L;
        }
    }
    return std::nullopt;
}

}  // namespace

GiNaC::ex limit_at_point(std::size_t n, const near_point& near) {
    // the parameters the expression depends on: with one, the two sides of the
    // point are all there is, and the lines decide; with several, agreement along
    // lines is not a proof (x^2 y/(x^4 + y^2) is 0 on every line through 0 and 1/2
    // on y = x^2): the lines refute (a pole, a direction dependence) and propose
    // the value, and limit_through_quantity must prove it, or it is refused
    GiNaC::lst offsets;
    std::vector<GiNaC::ex> offs;
    for (std::size_t i = 0; i < n; ++i) {
        const GiNaC::symbol e("e" + std::to_string(i));
        offsets.append(e);
        offs.push_back(e);
    }
    GiNaC::ex xs;
    try {
        xs = near(offs);
    } catch (const std::exception& e) {
        if (!is_division_by_zero(e)) throw;
        // which parameters it depends on is not known: lines are a proof with one only
        if (n == 1) return lines_limit(n, near);
        throw domain_error("the limit cannot be found: the expression divides by zero near the point as well, "
                           "and with several parameters approaching it the lines alone are not a proof");
    }
    GiNaC::lst present;
    GiNaC::exmap zero;
    for (const GiNaC::ex& e : offsets)
        if (xs.has(e)) {
            present.append(e);
            zero[e] = 0;
        }
    const GiNaC::ex value = lines_limit(n, near);
    if (present.nops() <= 1) return value;
    const std::vector<GiNaC::ex> entries =
        GiNaC::is_a<GiNaC::matrix>(xs) ? std::vector<GiNaC::ex>(xs.begin(), xs.end()) : std::vector<GiNaC::ex>{xs};
    std::vector<GiNaC::ex> values =
        GiNaC::is_a<GiNaC::matrix>(value) ? std::vector<GiNaC::ex>(value.begin(), value.end()) : std::vector<GiNaC::ex>{value};
    for (std::size_t i = 0; i < entries.size() && i < values.size(); ++i) {
        if (at_point(entries[i], zero)) continue;  // regular there: its value is the lines' one
        const auto L = limit_through_quantity(entries[i], present, zero);
        if (!L)
            throw domain_error("the limit cannot be found: it is " + (approx(values[i]).empty() ? message_text(values[i]) : approx(values[i])) +
                               " along every line tried through the point, but with several parameters approaching "
                               "it that is not a proof (x^2 y/(x^4 + y^2) is 0 on lines through 0 and 1/2 on y = x^2), "
                               "and the expression is not shown to be a regular function of one vanishing quantity "
                               "there");
        if (!proved_zero(*L - values[i]))
            throw domain_error("the limit cannot be found: the limits along lines and through the vanishing quantity "
                               "are not proved equal");
    }
    return value;
}

}  // namespace symrep
