// symrep/scalar/small_primes.cpp -- the factors of an integer over the primes below 2^16
// (small_primes.h), shared by the radicals and logarithms of rationals.
#include "symrep/scalar/small_primes.h"

#include <algorithm>
#include <map>

namespace symrep {

bool is_positive_rational(const GiNaC::ex& x) {
    return GiNaC::is_a<GiNaC::numeric>(x) && GiNaC::ex_to<GiNaC::numeric>(x).is_rational() &&
           GiNaC::ex_to<GiNaC::numeric>(x).is_positive();
}

namespace {

constexpr long bound = 65536;

struct prime_blocks {
    std::vector<long> primes;                 // the primes below 2^16, ascending
    std::vector<GiNaC::numeric> products;     // the product of each block of `width` primes
    static constexpr std::size_t width = 128;
    prime_blocks() {
        std::vector<bool> composite(bound, false);
        for (long p = 2; p < bound; ++p) {
            if (composite[p]) continue;
            primes.push_back(p);
            for (long q = p * p; q < bound; q += p) composite[q] = true;
        }
        for (std::size_t i = 0; i < primes.size(); i += width) {
            GiNaC::numeric m = 1;
            for (std::size_t j = i; j < primes.size() && j < i + width; ++j) m *= primes[j];
            products.push_back(m);
        }
    }
};

bool is_rational_radical(const GiNaC::ex& y) {
    return GiNaC::is_a<GiNaC::power>(y) && is_positive_rational(y.op(0)) && GiNaC::is_a<GiNaC::numeric>(y.op(1)) &&
           GiNaC::ex_to<GiNaC::numeric>(y.op(1)).is_rational() && !GiNaC::ex_to<GiNaC::numeric>(y.op(1)).is_integer();
}

const prime_blocks& blocks() {
    static const prime_blocks b;
    return b;
}

}  // namespace

small_factorization small_prime_factors(const GiNaC::numeric& n_in) {
    // the same integers recur many times in one derivation (the square root of |w|^2, the
    // numerators of the values): remembered, bounded
    static std::map<GiNaC::numeric, small_factorization, numeric_less> memo;  // not thread safe, as GiNaC
    const auto hit = memo.find(n_in);
    if (hit != memo.end()) return hit->second;
    small_factorization out;
    GiNaC::numeric n = n_in;
    if (n > 1) {
        const prime_blocks& b = blocks();
        // a gcd with the product of a block of primes skips the blocks without a divisor of n
        // (one gcd instead of 128 trial divisions of a number of hundreds of digits)
        for (std::size_t k = 0; k < b.products.size() && n > 1; ++k) {
            GiNaC::numeric g = GiNaC::gcd(n, b.products[k]);
            for (std::size_t j = k * b.width; g > 1 && j < b.primes.size() && j < (k + 1) * b.width; ++j) {
                const GiNaC::numeric p(b.primes[j]);
                if (!GiNaC::irem(g, p).is_zero()) continue;
                g = GiNaC::iquo(g, p);
                int e = 0;
                while (GiNaC::irem(n, p).is_zero()) {
                    n = GiNaC::iquo(n, p);
                    ++e;
                }
                out.factors.emplace_back(b.primes[j], e);
            }
        }
    }
    out.cofactor = n;
    if (memo.size() > 4096) memo.clear();
    memo.emplace(n_in, out);
    return out;
}

cofactor_bases refine_cofactors(const GiNaC::ex& e) {
    cofactor_bases out;
    std::vector<GiNaC::numeric> cofactors;
    auto note = [&](const GiNaC::numeric& r) {
        for (const GiNaC::numeric& n : {r.numer(), r.denom()}) {
            const GiNaC::numeric c = small_prime_factors(n).cofactor;
            if (c > 1 && !out.count(c)) {
                out[c] = {};
                cofactors.push_back(c);
            }
        }
    };
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
        if (is_rational_radical(*it)) note(GiNaC::ex_to<GiNaC::numeric>(it->op(0)));
        else if (GiNaC::is_the_function<GiNaC::log_SERIAL>(*it))
            for (auto jt = it->op(0).preorder_begin(); jt != it->op(0).preorder_end(); ++jt)
                if (is_positive_rational(*jt)) note(GiNaC::ex_to<GiNaC::numeric>(*jt));
    }
    if (cofactors.empty()) return out;
    std::vector<GiNaC::numeric> bases;
    for (const GiNaC::numeric& c : cofactors) {
        std::vector<GiNaC::numeric> pending{c};
        while (!pending.empty()) {
            const GiNaC::numeric x = pending.back();
            pending.pop_back();
            if (x == 1) continue;
            bool placed = false;
            for (std::size_t i = 0; i < bases.size() && !placed; ++i) {
                const GiNaC::numeric g = GiNaC::gcd(x, bases[i]);
                if (g == 1) continue;
                placed = true;
                if (x == bases[i]) break;  // already a base
                const GiNaC::numeric b = bases[i];
                bases.erase(bases.begin() + long(i));
                pending.push_back(g);
                pending.push_back(b / g);
                pending.push_back(x / g);
            }
            if (!placed) bases.push_back(x);
        }
    }
    std::sort(bases.begin(), bases.end(), numeric_less());
    for (const GiNaC::numeric& c : cofactors) {
        GiNaC::numeric rest = c;
        std::vector<std::pair<GiNaC::numeric, long>> f;
        for (const GiNaC::numeric& b : bases) {
            long k = 0;
            while (GiNaC::irem(rest, b).is_zero()) {
                rest = GiNaC::iquo(rest, b);
                ++k;
            }
            if (!k) continue;
            GiNaC::numeric root = b;
            for (GiNaC::numeric r = GiNaC::isqrt(root); r > 1 && r * r == root; r = GiNaC::isqrt(root)) {
                root = r;
                k *= 2;
            }
            f.emplace_back(root, k);
        }
        if (rest != 1) f = {{c, 1}};  // cannot happen (the bases generate every cofactor); stay as it was
        out[c] = f;
    }
    return out;
}

}  // namespace symrep
