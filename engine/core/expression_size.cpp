// symrep/core/expression_size.cpp
#include "symrep/core/expression_size.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

#include "symrep/core/error.h"
#include "symrep/core/interrupt.h"

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

}  // namespace

double expanded_terms(const GiNaC::ex& e, bool fractions) {
    counter c{fractions};
    const fraction f = c.terms(e);
    if (c.nodes > max_nodes) return saturated;
    const double den = f.den.empty() ? 0 : f.den_terms();
    return sat(sat(f.num + den) + c.inner);
}

namespace {

// Collects the symbols of e; false when e is not a polynomial in them with
// numeric coefficients (a function call, a non-integer or negative power, a
// float, a matrix), where the monomial count bounds nothing.
bool polynomial_symbols(const GiNaC::ex& e, GiNaC::exset& symbols) {
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
        symbols.insert(e);
        return true;
    }
    if (GiNaC::is_a<GiNaC::numeric>(e)) return GiNaC::ex_to<GiNaC::numeric>(e).is_crational();
    if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
        for (std::size_t i = 0; i < e.nops(); ++i)
            if (!polynomial_symbols(e.op(i), symbols)) return false;
        return true;
    }
    if (GiNaC::is_a<GiNaC::power>(e)) {
        const GiNaC::ex& k = e.op(1);
        if (!GiNaC::is_a<GiNaC::numeric>(k) || !GiNaC::ex_to<GiNaC::numeric>(k).is_nonneg_integer()) return false;
        return polynomial_symbols(e.op(0), symbols);
    }
    return false;
}

}  // namespace

double product_terms(const std::vector<GiNaC::ex>& factors) {
    GiNaC::ex all = 1;
    for (const auto& f : factors) all *= f;
    const double coarse = expanded_terms(all, false);
    if (expression_nodes(all) >= max_nodes) return coarse;
    GiNaC::exset symbols;
    for (const auto& f : factors)
        if (!polynomial_symbols(f, symbols)) return coarse;
    double monomials = 1;
    for (const auto& x : symbols) {
        double degree = 0;
        for (const auto& f : factors) degree += f.degree(x);
        monomials = sat(monomials * (degree + 1));
    }
    return std::min(coarse, monomials);
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
    if (n > max_expanded_terms) {
        std::ostringstream os;
        os.precision(2);
        os << what << ": the expression is too large (";
        if (n >= saturated)
            os << "more than 10^30";
        else
            os << "an estimated " << n;
        os << " terms to multiply out; the limit is 10^8)";
        throw size_error(os.str());
    }
}

void guard_expansion(const GiNaC::ex& e, const char* what, bool fractions) {
    guard_terms(expanded_terms(e, fractions), what);
}

GiNaC::ex guarded_expand(const GiNaC::ex& e, const char* what) {
    guard_expansion(e, what, false);
    return GiNaC::expand(e);
}

}  // namespace symrep
