// symrep/algebra/expression_size.cpp
#include "algebra/expression_size.h"

#include <chrono>
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

#include "io/error.h"

namespace symrep {

namespace {

constexpr double saturated = 1e30;
constexpr long max_nodes = 10000000;

double sat(double x) { return x > saturated ? saturated : x; }

/// C(k + m - 1, m - 1): the terms of (a sum of m terms)^k.
double multinomial_terms(double m, double k) {
    if (m <= 1 || k == 0) return 1;
    if (k == 1) return m;
    const double l = std::lgamma(k + m) - std::lgamma(k + 1) - std::lgamma(m);
    return l > std::log(saturated) ? saturated : std::exp(l);
}

/// The terms of a numerator, and the factors of the denominator: base -> (terms
/// of the base, exponent); equal bases share one entry, as in normal()'s common
/// denominators.
struct fraction {
    double num = 1;
    std::map<GiNaC::ex, std::pair<double, double>, GiNaC::ex_is_less> den;
    double den_terms() const {
        double p = 1;
        for (const auto& [base, f] : den) p = sat(p * multinomial_terms(f.first, f.second));
        return p;
    }
};

struct counter {
    bool fractions;    // negative powers are denominators to multiply out (normal), not atoms (expand)
    double inner = 0;  // terms of the parts multiplied out on their own
    long nodes = 0;
    fraction terms(const GiNaC::ex& e) {
        if (++nodes > max_nodes) return {saturated, {}};
        if (GiNaC::is_a<GiNaC::add>(e)) {
            // over the common denominator (the lcm): sum_i num_i * lcm / den_i
            std::vector<fraction> t;
            fraction f{0, {}};
            for (std::size_t i = 0; i < e.nops(); ++i) {
                t.push_back(terms(e.op(i)));
                for (const auto& [base, g] : t.back().den) {
                    auto& h = f.den[base];
                    h = {g.first, std::max(h.second, g.second)};
                }
            }
            const double lcm = f.den_terms();
            for (const fraction& x : t) f.num = sat(f.num + x.num * (lcm / x.den_terms()));
            return f;
        }
        if (GiNaC::is_a<GiNaC::mul>(e)) {
            fraction f;
            for (std::size_t i = 0; i < e.nops(); ++i) {
                const fraction x = terms(e.op(i));
                f.num = sat(f.num * x.num);
                for (const auto& [base, g] : x.den) {
                    auto& h = f.den[base];
                    h = {g.first, h.second + g.second};
                }
            }
            return f;
        }
        if (GiNaC::is_a<GiNaC::power>(e)) {
            fraction b = terms(e.op(0));
            const GiNaC::ex& k = e.op(1);
            if (GiNaC::is_a<GiNaC::numeric>(k) && GiNaC::ex_to<GiNaC::numeric>(k).is_integer()) {
                const double n = std::fabs(GiNaC::ex_to<GiNaC::numeric>(k).to_double());
                if (GiNaC::ex_to<GiNaC::numeric>(k).is_positive()) {
                    b.num = multinomial_terms(b.num, n);
                    for (auto& [base, g] : b.den) g.second *= n;
                    return b;
                }
                if (fractions) return {multinomial_terms(b.den_terms(), n), {{e.op(0), {b.num, n}}}};
            }
            inner = sat(inner + sat(b.num * b.den_terms()) + terms(k).num);
            return {};
        }
        // symbols, numbers, function calls, matrices, lists: one term; their parts on their own
        for (std::size_t i = 0; i < e.nops(); ++i) {
            const fraction x = terms(e.op(i));
            inner = sat(inner + sat(x.num * x.den_terms()));
        }
        return {};
    }
};

using degrees = std::map<GiNaC::ex, double, GiNaC::ex_is_less>;

/// Upper bounds of the degrees of e in its variables (symbols, and the atoms that
/// normal() treats as variables: function calls, non-integer powers).
degrees degrees_of(const GiNaC::ex& e) {
    degrees d;
    if (GiNaC::is_a<GiNaC::numeric>(e)) return d;
    if (GiNaC::is_a<GiNaC::add>(e)) {
        for (std::size_t i = 0; i < e.nops(); ++i)
            for (const auto& [v, k] : degrees_of(e.op(i))) d[v] = std::max(d[v], k);
        return d;
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
        for (std::size_t i = 0; i < e.nops(); ++i)
            for (const auto& [v, k] : degrees_of(e.op(i))) d[v] += k;
        return d;
    }
    if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)) &&
        GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_integer()) {
        const double n = std::fabs(GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_double());
        for (const auto& [v, k] : degrees_of(e.op(0))) d[v] = sat(k * n);
        return d;
    }
    d[e] = 1;
    return d;
}

/// The work of the gcd that normal() computes to cancel a fraction: the size of
/// the dense polynomial of the denominator's degrees, prod_v (deg_v + 1) (the
/// multivariate gcd of GiNaC works variable by variable).
double gcd_work(const fraction& f) {
    if (f.den.empty()) return 0;
    degrees d;
    for (const auto& [base, g] : f.den)
        for (const auto& [v, k] : degrees_of(base)) d[v] = sat(d[v] + k * g.second);
    double p = 1;
    for (const auto& [v, k] : d) p = sat(p * (k + 1));
    return p;
}

}  // namespace

double expanded_terms(const GiNaC::ex& e, bool fractions) {
    counter c{fractions};
    const fraction f = c.terms(e);
    if (c.nodes > max_nodes) return saturated;
    const double den = f.den.empty() ? 0 : f.den_terms();
    return sat(std::max(sat(f.num + den), fractions ? gcd_work(f) : 0.0) + c.inner);
}

double factor_work(const GiNaC::ex& e) {
    const double t = expanded_terms(e, true);  // also bounds the pass over e below
    if (t >= saturated) return saturated;
    double dense = 1;
    for (const auto& [v, k] : degrees_of(e)) dense = sat(dense * (k + 1));
    return sat(t + 50 * dense);
}

double expression_nodes(const GiNaC::ex& e) {
    long n = 0;
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (++n > max_nodes) return saturated;
    return double(n);
}

double determinant_terms(const GiNaC::matrix& m, bool charpoly) {
    double p = 1;
    for (unsigned i = 0; i < m.rows(); ++i) {
        double row = charpoly ? 1 : 0;  // the - X of the diagonal
        bool number = false;
        for (unsigned j = 0; j < m.cols(); ++j) {
            const GiNaC::ex& x = m(i, j);
            if (GiNaC::is_a<GiNaC::numeric>(x))
                number = number || !x.is_zero();  // numbers of a row make one term together
            else
                row = sat(row + expanded_terms(x, true));
        }
        p = sat(p * (row + (number ? 1 : 0)));
    }
    return p;
}

void guard_terms(double n, const char* what) {
    check_interrupt();
    std::ostringstream os;
    os.precision(2);
    if (n > max_expanded_terms) {
        os << what << ": the expression is too large (";
        if (n >= saturated)
            os << "more than 10^30";
        else
            os << "an estimated " << n;
        os << " terms to multiply out; the limit is 10^8)";
        throw size_error(os.str());
    }
    const long long deadline = deadline_ticks().load(std::memory_order_relaxed);
    if (deadline == 0 || n < 1000) return;
    const auto left = std::chrono::steady_clock::duration(deadline) - std::chrono::steady_clock::now().time_since_epoch();
    if (n <= std::chrono::duration<double>(left).count() * expanded_terms_per_second) return;
    os << "time limit: " << what << " would not end within the statement's time limit (--time-limit): "
       << "the expression is too large (an estimated " << n << " terms to multiply out)";
    throw error(os.str());
}

void guard_expansion(const GiNaC::ex& e, const char* what, bool fractions) {
    guard_terms(expanded_terms(e, fractions), what);
}

GiNaC::ex guarded_expand(const GiNaC::ex& e, const char* what) {
    guard_expansion(e, what, false);
    return GiNaC::expand(e);
}

}  // namespace symrep
