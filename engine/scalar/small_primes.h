// symrep/scalar/small_primes.h -- an integer over the primes below 2^16: the factoring
// behind the canonical radicals (sqrt(12) = 2 sqrt(3)) and the logarithms of rationals
// over primes (log(12) = 2 log(2) + log(3)) of scalar.h.
#pragma once

#include <utility>
#include <vector>

#include <ginac/ginac.h>

namespace symrep {

/// n (an integer >= 1) = prod p^e * cofactor over the primes p below 2^16, the cofactor
/// free of them (1 when n factors completely). A gcd with the product of each block of
/// primes skips the trial divisions that cannot succeed (a 100-digit numerator of the exact
/// value of a double would otherwise cost 65 536 divisions per look), and results are
/// remembered (the same numbers recur throughout a derivation).
struct small_factorization {
    std::vector<std::pair<long, int>> factors;  ///< (p, e), p ascending, e >= 1
    GiNaC::numeric cofactor = 1;
};
small_factorization small_prime_factors(const GiNaC::numeric& n);

}  // namespace symrep
