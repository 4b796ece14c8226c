// symrep/scalar/small_primes.cpp -- the factors of an integer over the primes below 2^16
// (small_primes.h), shared by the radicals and logarithms of rationals.
#include "scalar/small_primes.h"

#include <map>

namespace symrep {

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

struct numeric_less {
    bool operator()(const GiNaC::numeric& a, const GiNaC::numeric& b) const { return a.compare(b) < 0; }
};

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

}  // namespace symrep
