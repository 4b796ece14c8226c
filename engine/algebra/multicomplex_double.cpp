// symrep/algebra/multicomplex_double.cpp -- the double-precision multicomplex path.
#include "symrep/algebra/multicomplex_double.h"

#include "symrep/algebra/batched_exp.h"

#include <algorithm>
#include <mutex>
#include <sstream>
#include <unistd.h>

#include "symrep/algebra/multicomplex_indexing.h"
#include "symrep/algebra/multicomplex_transform.h"
#include "symrep/core/error.h"

namespace symrep {

struct multicomplex_d::table_cache {
    std::once_flag once;
    std::vector<std::uint32_t> table;  // entry i*dim+j: (i xor j) | sign bit 31
};

unsigned multicomplex_d::max_order() {
    const long pages = ::sysconf(_SC_PHYS_PAGES);
    const long page = ::sysconf(_SC_PAGE_SIZE);
    const double mem = (pages > 0 && page > 0) ? double(pages) * double(page) : double(1u << 30);
    unsigned n = 0;
    while (n < 40 && 5.0 * std::ldexp(1.0, int(n + 1) + 4) <= mem / 2) ++n;
    return n;
}

multicomplex_d::multicomplex_d(unsigned n) : n_(n), cache_(std::make_shared<table_cache>()) {
    const unsigned m = max_order();
    if (n > m)
        throw size_error("multicomplex_d(" + std::to_string(n) + "): n must be <= " + std::to_string(m) +
                         " on this machine (an operation needs about 5 * 2^(n+4) bytes, at most half "
                         "of the physical memory)");
}

void multicomplex_d::check_size(const vector& a, const char* what) const {
    if (a.size() != dim())
        throw algebra_error(std::string(what) + ": multicomplex(" + std::to_string(n_) +
                            ") has dimension " + std::to_string(dim()) + ", but " +
                            std::to_string(a.size()) + " coordinates were given");
}

multicomplex_d::vector multicomplex_d::unit() const {
    vector u(dim(), 0.0);
    u[0] = 1.0;
    return u;
}

multicomplex_d::vector multicomplex_d::imag_unit(unsigned k) const {
    if (k > n_)
        throw algebra_error("multicomplex(" + std::to_string(n_) + ") has the imaginary units i0..i" +
                            std::to_string(n_) + "; there is no i" + std::to_string(k));
    vector u(dim(), 0.0);
    u[multicomplex_imag_unit_index(n_, k)] = 1.0;
    return u;
}

multicomplex_d::components multicomplex_d::idempotent_components(const vector& w) const {
    check_size(w, "idempotent components");
    return multicomplex_components<double>(w, n_);
}

multicomplex_d::vector multicomplex_d::from_idempotent_components(const components& c) const {
    if (c.size() != half_dim())
        throw algebra_error("idempotent components: multicomplex(" + std::to_string(n_) + ") has " +
                            std::to_string(half_dim()) + " idempotent components, but " +
                            std::to_string(c.size()) + " were given");
    return multicomplex_from_components<double>(c, n_);
}

// (III.1.39, III.1.16) componentwise product (written out: std::complex's
// operator* checks for infinities and is several times slower).
multicomplex_d::vector multicomplex_d::multiply(const vector& a, const vector& b) const {
    check_size(a, "product");
    check_size(b, "product");
    // Scratch buffers kept per thread: fresh 2^n-element allocations each call cost
    // page faults comparable to the transforms themselves.
    thread_local components ca, cb;
    multicomplex_components_into<double>(a, n_, ca);
    multicomplex_components_into<double>(b, n_, cb);
    for (std::size_t p = 0; p < ca.size(); ++p) {
        const double x = ca[p].real(), y = ca[p].imag(), u = cb[p].real(), v = cb[p].imag();
        ca[p] = {x * u - y * v, x * v + y * u};
    }
    return multicomplex_from_components_inplace<double>(ca, n_);
}

const std::vector<std::uint32_t>& multicomplex_d::structure_table() const {
    std::call_once(cache_->once, [this] {
        const std::size_t D = dim();
        cache_->table.resize(D * D);
        for (std::size_t i = 0; i < D; ++i)
            for (std::size_t j = 0; j < D; ++j)  // (III.1.7) gamma_ij = (-1)^{<i,j>} at i xor j
                cache_->table[i * D + j] = static_cast<std::uint32_t>(i ^ j) |
                                           (multicomplex_product_sign(i, j) < 0 ? 0x80000000u : 0u);
    });
    return cache_->table;
}

// (III.1.7) sum_{i,j} a_i b_j gamma_ij.
multicomplex_d::vector multicomplex_d::multiply_structure(const vector& a, const vector& b) const {
    if (n_ > structure_max_order)
        throw size_error("multiply_structure: the structure-constant table is limited to n <= " +
                         std::to_string(structure_max_order) + " (4^(n+1) entries); n = " +
                         std::to_string(n_) + " was asked");
    check_size(a, "product");
    check_size(b, "product");
    const auto& T = structure_table();
    const std::size_t D = dim();
    vector r(D, 0.0);
    for (std::size_t i = 0; i < D; ++i) {
        if (a[i] == 0.0) continue;
        const std::uint32_t* row = T.data() + i * D;
        for (std::size_t j = 0; j < D; ++j) {
            const double x = a[i] * b[j];
            const std::uint32_t e = row[j];
            r[e & 0x7fffffffu] += (e & 0x80000000u) ? -x : x;
        }
    }
    return r;
}

namespace {
// (III.1.55) ranks of the components with |c_p| <= rel_tol * max_q |c_q|.
std::vector<std::size_t> vanishing_ranks(const multicomplex_d::components& c, double rel_tol) {
    double m2 = 0.0;  // squared moduli: no hypot per component
    for (const auto& z : c) m2 = std::max(m2, std::norm(z));
    const double t2 = rel_tol * rel_tol * m2;
    std::vector<std::size_t> r;
    for (std::size_t p = 0; p < c.size(); ++p)
        if (std::norm(c[p]) <= t2) r.push_back(p);
    return r;
}
}  // namespace

std::vector<std::size_t> multicomplex_d::zero_divisor_ranks(const vector& w, double rel_tol) const {
    return vanishing_ranks(idempotent_components(w), rel_tol);
}

namespace {
[[noreturn]] void throw_zero_divisor(unsigned n, const char* what, std::vector<std::size_t> ranks) {
    std::ostringstream os;
    os << what << " of a zero divisor in multicomplex(" << n
       << "): the idempotent component(s) of rank ";
    for (std::size_t k = 0; k < ranks.size() && k < 16; ++k) os << (k ? ", " : "") << ranks[k];
    if (ranks.size() > 16) os << ", ... (" << ranks.size() << " in all)";
    os << " vanish (a_k = b_k = 0, III.1.55), so w e_k = 0 (III.1.56)";
    const std::string msg = os.str();
    throw zero_divisor_error(msg, std::move(ranks));
}
}  // namespace

// (III.1.57)
multicomplex_d::vector multicomplex_d::inverse(const vector& w, double rel_tol) const {
    auto c = idempotent_components(w);
    auto ranks = vanishing_ranks(c, rel_tol);
    if (!ranks.empty()) throw_zero_divisor(n_, "inverse", std::move(ranks));
    for (auto& z : c) z = multicomplex_component_inverse<double>(z.real(), z.imag());
    return multicomplex_from_components<double>(std::move(c), n_);
}

// (III.1.45-52)
// The componentwise exponentials in SIMD blocks (batched_exp.h), on the thread's scratch
// buffer as in multiply().
multicomplex_d::vector multicomplex_d::exp(const vector& w, double t) const {
    check_size(w, "exp");
    thread_local components c;
    multicomplex_components_into<double>(w, n_, c);
    exp_components(c.data(), c.size(), t);
    return multicomplex_from_components_inplace<double>(c, n_);
}

// (III.1.53). Steps as in inverse() (the zero-divisor ranks, then a map of the
// components); only the map differs.
multicomplex_d::vector multicomplex_d::log(const vector& w, double rel_tol) const {
    auto c = idempotent_components(w);
    auto ranks = vanishing_ranks(c, rel_tol);
    if (!ranks.empty()) throw_zero_divisor(n_, "logarithm", std::move(ranks));
    for (auto& z : c) z = multicomplex_component_log<double>(z.real(), z.imag());
    return multicomplex_from_components<double>(std::move(c), n_);
}

}  // namespace symrep
