// symrep/scalar/small_primes.h -- an integer over the primes below 2^16: the factoring
// behind the canonical radicals (sqrt(12) = 2 sqrt(3)) and the logarithms of rationals
// over primes (log(12) = 2 log(2) + log(3)) of scalar.h.
#pragma once

#include <map>
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

struct numeric_less {
    bool operator()(const GiNaC::numeric& a, const GiNaC::numeric& b) const { return a.compare(b) < 0; }
};
/// Per cofactor: its factors b^k over one coprime base.
using cofactor_bases = std::map<GiNaC::numeric, std::vector<std::pair<GiNaC::numeric, long>>, numeric_less>;

/// The cofactors (no prime factor below 2^16) of the integers under the radicals (r^q, r a
/// positive rational, q not an integer) and inside the logarithms of e, written over one
/// coprime base (factor refinement: a gcd splits any two that share a factor; a base that is
/// a perfect square is its root twice). Cofactors that share a large prime or differ by a
/// large square then meet: sqrt(3 P) and sqrt(3 P q^2) (P, q primes above 2^16), which the
/// primes below 2^16 leave as unrelated atoms, become sqrt(3 P) and q sqrt(3 P), so that
/// their sum can cancel (the radicals of scenes with the exact rationals of doubles:
/// |B| = sqrt(B . B) next to q |B|/m).
cofactor_bases refine_cofactors(const GiNaC::ex& e);

/// True for a positive rational number (the bases whose radicals and logarithms are written
/// over primes).
bool is_positive_rational(const GiNaC::ex& x);

}  // namespace symrep
