// symrep/numeric/spectral_evaluator.cpp -- see spectral_evaluator.h.
#include "symrep/numeric/spectral_evaluator.h"

#include <algorithm>
#include <cln/float.h>
#include <cln/real.h>
#include <cmath>
#include <numeric>
#include <sstream>

#include "symrep/core/error.h"
#include "symrep/scalar/scalar.h"
#include "symrep/numeric/reference.h"

namespace symrep::num {

namespace {

using GiNaC::ex;
using GiNaC::numeric;
using namespace GiNaC;

/// cos, sin, cosh, sinh written with exp (the exponents are then read off the product terms).
struct exponential_form : GiNaC::map_function {
    ex operator()(const ex& e) override {
        using GiNaC::I;
        if (GiNaC::is_a<GiNaC::function>(e)) {
            if (is_ex_the_function(e, sin)) {
                const ex x = (*this)(e.op(0));
                return (GiNaC::exp(I * x) - GiNaC::exp(-I * x)) / (2 * I);
            }
            if (is_ex_the_function(e, cos)) {
                const ex x = (*this)(e.op(0));
                return (GiNaC::exp(I * x) + GiNaC::exp(-I * x)) / 2;
            }
            if (is_ex_the_function(e, sinh)) {
                const ex x = (*this)(e.op(0));
                return (GiNaC::exp(x) - GiNaC::exp(-x)) / 2;
            }
            if (is_ex_the_function(e, cosh)) {
                const ex x = (*this)(e.op(0));
                return (GiNaC::exp(x) + GiNaC::exp(-x)) / 2;
            }
        }
        return e.map(*this);
    }
};

/// One term c t^m e^(lambda t) of output `output`.
struct term {
    std::size_t output;
    unsigned m;
    ex coefficient, exponent;
};

std::vector<term> terms_of(const std::vector<ex>& outputs, const ex& t) {
    std::vector<term> terms;
    exponential_form to_exp;
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const ex e = to_exp(exact_floats_of(outputs[i])).expand();
        const auto each = [&](const ex& product) {
            ex coefficient = 1, argument = 0;
            unsigned m = 0;
            const auto factor = [&](const ex& f) {
                if (!f.has(t)) {
                    coefficient *= f;
                } else if (f.is_equal(t)) {
                    ++m;
                } else if (GiNaC::is_a<GiNaC::power>(f) && f.op(0).is_equal(t) && f.op(1).info(GiNaC::info_flags::posint)) {
                    m += GiNaC::ex_to<numeric>(f.op(1)).to_int();
                } else if (is_ex_the_function(f, exp)) {
                    argument += f.op(0);
                } else if (GiNaC::is_a<GiNaC::power>(f) && is_ex_the_function(f.op(0), exp) &&
                           f.op(1).info(GiNaC::info_flags::integer)) {
                    argument += f.op(1) * f.op(0).op(0);
                } else {
                    throw type_error("spectral evaluator: output " + std::to_string(i + 1) +
                                     " is not a quasi-polynomial in " + message_text(t) + ": the factor " + message_text(f));
                }
            };
            if (GiNaC::is_a<GiNaC::mul>(product))
                for (const ex& f : product) factor(f);
            else
                factor(product);
            argument = argument.expand();
            if (!argument.is_polynomial(t) || argument.degree(t) > 1)
                throw type_error("spectral evaluator: output " + std::to_string(i + 1) + ": the exponent " +
                                 message_text(argument) + " is not linear in " + message_text(t));
            const ex rest = argument.coeff(t, 0);
            terms.push_back({i, m, rest.is_zero() ? coefficient : coefficient * GiNaC::exp(rest), argument.coeff(t, 1)});
        };
        if (GiNaC::is_a<GiNaC::add>(e))
            for (const ex& p : e) each(p);
        else if (!e.is_zero())
            each(e);
    }
    return terms;
}

numeric value_of(const ex& e, long digits, const char* what) {
    const ex v = evalf_reduced(e, digits);
    if (!GiNaC::is_a<numeric>(v))
        throw type_error(std::string("spectral evaluator: the ") + what + " " + message_text(e) +
                         " is not a number (a symbol other than t has no value)");
    return GiNaC::ex_to<numeric>(v);
}

double dbl(const numeric& x) { return cln::double_approx(cln::the<cln::cl_R>(x.to_cl_N())); }

/// x split into hi + lo (hi the double nearest x, lo the double nearest x - hi).
std::pair<double, double> split(const numeric& x) {
    const double hi = dbl(x);
    const double lo = dbl(x - numeric(cln::cl_N(cln::rational(cln::cl_DF(hi)))));
    return {hi, lo};
}
numeric exact(double x) { return numeric(cln::cl_N(cln::rational(cln::cl_DF(x)))); }

double log10_of(const numeric& x) {
    if (x.is_zero()) return -1e300;
    const cln::cl_R r = cln::the<cln::cl_R>(x.to_cl_N());
    // through the binary exponent: no overflow for 1e-500
    const long e = cln::float_exponent(cln::cl_float(r, cln::float_format(20)));
    const double mant = cln::double_approx(cln::scale_float(cln::cl_float(r, cln::float_format(20)), -e));
    return (double(e) * std::log(2.0) + std::log(std::fabs(mant))) / std::log(10.0);
}

using cluster = detail::spectral_cluster;
using level = detail::spectral_level;
using polynomials = std::vector<std::vector<numeric>>;  // [output][m]: the coefficients of t^m

/// The exponents at `digits` digits, equal ones (within tiny) merged, with their polynomials.
struct exponent_table {
    std::vector<numeric> lambda;
    std::vector<polynomials> poly;  // [exponent]
};

exponent_table merge_exponents(const std::vector<term>& terms, std::size_t n_out, long digits, const numeric& tiny) {
    exponent_table x;
    for (const term& k : terms) {
        const numeric l = value_of(k.exponent, digits, "exponent");
        const numeric c = value_of(k.coefficient, digits, "coefficient");
        std::size_t j = 0;
        while (j < x.lambda.size() && GiNaC::abs(x.lambda[j] - l) > tiny * std::max(numeric(1), GiNaC::abs(l))) ++j;
        if (j == x.lambda.size()) {
            x.lambda.push_back(l);
            x.poly.emplace_back(n_out);
        }
        auto& p = x.poly[j][k.output];
        if (p.size() <= k.m) p.resize(k.m + 1, numeric(0));
        p[k.m] += c;
    }
    return x;
}

/// The outputs are real: the exponent j off the real axis has its conjugate, with the conjugate
/// coefficients (to `loose`); domain_error naming it otherwise.
void check_conjugate_partner(const exponent_table& x, std::size_t j, std::size_t n_out, const numeric& tiny,
                             const numeric& loose) {
    const numeric im = x.lambda[j].imag();
    std::size_t q = 0;
    const numeric conj_l = x.lambda[j].real() - GiNaC::I * im;
    while (q < x.lambda.size() &&
           GiNaC::abs(x.lambda[q] - conj_l) > tiny * std::max(numeric(1), GiNaC::abs(conj_l)))
        ++q;
    bool ok = q < x.lambda.size();
    for (std::size_t i = 0; ok && i < n_out; ++i) {
        const auto& a = x.poly[j][i];
        const auto& b = x.poly[q][i];
        for (std::size_t m = 0; m < std::max(a.size(), b.size()); ++m) {
            const numeric u = m < a.size() ? a[m] : numeric(0), y = m < b.size() ? b[m] : numeric(0);
            const numeric yc = y.real() - GiNaC::I * y.imag();
            if (GiNaC::abs(u - yc) > loose * std::max(GiNaC::abs(u), GiNaC::abs(y))) ok = false;
        }
    }
    if (!ok)
        throw domain_error("spectral evaluator: an output is not real (the exponent " + message_text(x.lambda[j]) +
                           " has no conjugate partner)");
}

/// Every exponent (all are clustered: a cluster near the real axis must hold both halves for
/// its cancellation to happen in the moments), those on the real axis made real with real
/// polynomials; a cluster in the lower half plane is the mirror image of one in the upper,
/// which is evaluated twice over (Re 2 G) instead.
struct spectrum {
    std::vector<numeric> upper;
    std::vector<polynomials> folded;
    std::size_t n_out = 0, max_m = 0;  // outputs; the longest polynomial
    numeric tiny;                      // exponents closer than this (relative) are equal
};

spectrum fold_real(const exponent_table& x, std::size_t n_out, const numeric& tiny, const numeric& loose) {
    spectrum s;
    s.n_out = n_out;
    s.tiny = tiny;
    for (std::size_t j = 0; j < x.lambda.size(); ++j) {
        const numeric im = x.lambda[j].imag();
        const bool real_axis = GiNaC::abs(im) <= tiny * std::max(numeric(1), GiNaC::abs(x.lambda[j]));
        if (!real_axis) check_conjugate_partner(x, j, n_out, tiny, loose);
        s.upper.push_back(real_axis ? x.lambda[j].real() : x.lambda[j]);
        s.folded.push_back(x.poly[j]);
        for (std::size_t i = 0; i < n_out; ++i) {
            auto& p = s.folded.back()[i];
            if (real_axis)
                for (numeric& c : p) {
                    if (GiNaC::abs(c.imag()) > loose * GiNaC::abs(c))
                        throw domain_error("spectral evaluator: output " + std::to_string(i + 1) + " is not real");
                    c = c.real();
                }
            s.max_m = std::max(s.max_m, p.size());
        }
    }
    return s;
}

/// Which side of the real axis a centre lies on: -1, 0, 1.
int side(const spectrum& s, const numeric& centre, double spread) {
    const numeric im = centre.imag();
    if (GiNaC::abs(im) <= s.tiny * std::max(numeric(1), GiNaC::abs(centre)) + numeric(spread) * s.tiny) return 0;
    return im > 0 ? 1 : -1;
}

struct edge {
    double length;
    std::size_t a, b;
};

/// Union-find over 0 .. n-1 (path halving).
struct disjoint_sets {
    std::vector<std::size_t> parent;
    explicit disjoint_sets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
    std::size_t find(std::size_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    void join(std::size_t a, std::size_t b) {
        const std::size_t root_b = find(b);
        parent[find(a)] = root_b;
    }
};

/// The minimum spanning tree of the exponents (Kruskal; there are few).
std::vector<edge> spanning_tree(const std::vector<numeric>& upper) {
    const std::size_t L = upper.size();
    std::vector<edge> all;
    for (std::size_t a = 0; a < L; ++a)
        for (std::size_t b = a + 1; b < L; ++b) all.push_back({dbl(GiNaC::abs(upper[a] - upper[b])), a, b});
    std::sort(all.begin(), all.end(), [](const edge& x, const edge& y) { return x.length < y.length; });
    disjoint_sets sets(L);
    std::vector<edge> tree;
    for (const edge& e : all)
        if (sets.find(e.a) != sets.find(e.b)) {
            sets.join(e.a, e.b);
            tree.push_back(e);
        }
    return tree;
}

/// The tree's distinct edge lengths, descending (level j + 1 starts at R / lengths[j]).
std::vector<double> cut_lengths(const std::vector<edge>& tree) {
    std::vector<double> lengths;
    for (const edge& e : tree) lengths.push_back(e.length);
    std::sort(lengths.rbegin(), lengths.rend());
    lengths.erase(std::unique(lengths.begin(), lengths.end()), lengths.end());
    return lengths;
}

/// The clusters at a cut: the exponents joined by the tree's edges shorter than `cut`, each
/// group in index order, the groups in the order of their roots (some empty).
std::vector<std::vector<std::size_t>> groups_below(const std::vector<edge>& tree, std::size_t L, double cut) {
    disjoint_sets sets(L);
    for (const edge& e : tree)
        if (e.length < cut) sets.join(e.a, e.b);
    std::vector<std::vector<std::size_t>> members(L);
    for (std::size_t k = 0; k < L; ++k) members[sets.find(k)].push_back(k);
    return members;
}

/// A single exponent k, evaluated directly by its polynomial (doubled for a pair off the real
/// axis); false for one in the lower half plane (the mirror image of one in the upper).
bool direct_cluster(const spectrum& s, std::size_t k, cluster& c) {
    const int half = side(s, s.upper[k], 0);
    if (half < 0) return false;
    const double weight = half > 0 ? 2 : 1;
    std::tie(c.re_hi, c.re_lo) = split(s.upper[k].real());
    std::tie(c.im_hi, c.im_lo) = split(s.upper[k].imag());
    c.series = false;
    c.length = s.max_m;
    c.coeff.assign(s.n_out * s.max_m, 0.0);
    for (std::size_t i = 0; i < s.n_out; ++i)
        for (std::size_t m = 0; m < s.folded[k][i].size(); ++m)
            c.coeff[i * s.max_m + m] = {weight * dbl(s.folded[k][i][m].real()), weight * dbl(s.folded[k][i][m].imag())};
    return true;
}

/// The moments mu[i][n] of a group about `at` (header), and their magnitudes without
/// cancellation size[i][n] (the same sums of absolute values).
struct moments {
    std::vector<std::vector<numeric>> mu, size;
};

moments moments_about(const spectrum& s, const std::vector<std::size_t>& group, const numeric& at, std::size_t n_max) {
    moments out{std::vector<std::vector<numeric>>(s.n_out, std::vector<numeric>(n_max + 1, numeric(0))),
                std::vector<std::vector<numeric>>(s.n_out, std::vector<numeric>(n_max + 1, numeric(0)))};
    for (std::size_t k : group) {
        const numeric delta = s.upper[k] - at;
        const numeric delta_abs = GiNaC::abs(delta);
        std::vector<numeric> pw(n_max + 1), pa(n_max + 1);  // delta^j / j!, |delta|^j / j!
        pw[0] = 1;
        pa[0] = 1;
        for (std::size_t q = 1; q <= n_max; ++q) {
            pw[q] = pw[q - 1] * delta / numeric(static_cast<long>(q));
            pa[q] = pa[q - 1] * delta_abs / numeric(static_cast<long>(q));
        }
        for (std::size_t i = 0; i < s.n_out; ++i)
            for (std::size_t m = 0; m < s.folded[k][i].size(); ++m) {
                const numeric& cm = s.folded[k][i][m];
                if (cm.is_zero()) continue;
                const numeric cabs = GiNaC::abs(cm);
                for (std::size_t n = m; n <= n_max; ++n) {
                    out.mu[i][n] += cm * pw[n - m];
                    out.size[i][n] += cabs * pa[n - m];
                }
            }
    }
    return out;
}

/// log10 of every |mu[i][n]| and size[i][n] (-1e300 for 0).
struct log_moments {
    std::vector<std::vector<double>> mu, size;
};

log_moments logs_of(const moments& mo) {
    log_moments out;
    for (std::size_t i = 0; i < mo.mu.size(); ++i) {
        out.mu.emplace_back(mo.mu[i].size());
        out.size.emplace_back(mo.mu[i].size());
        for (std::size_t n = 0; n < mo.mu[i].size(); ++n) {
            out.mu[i][n] = log10_of(GiNaC::abs(mo.mu[i][n]));
            out.size[i][n] = log10_of(mo.size[i][n]);
        }
    }
    return out;
}

/// The digits the cancellation needs: noise 10^-digits size_n t^n against 2^-58 max_j |mu_j| t^j
/// at both ends of the level, t_lo and t_hi.
long digits_for_cancellation(const log_moments& lg, double t_lo, double t_hi) {
    long needed = 0;
    for (double tt : {t_lo, t_hi}) {
        const double lt = std::log10(tt);
        for (std::size_t i = 0; i < lg.mu.size(); ++i) {
            double top = -1e300;
            for (std::size_t n = 0; n < lg.mu[i].size(); ++n) top = std::max(top, lg.mu[i][n] + double(n) * lt);
            if (top < -1e299) continue;
            for (std::size_t n = 0; n < lg.mu[i].size(); ++n)
                if (lg.size[i][n] > -1e299)
                    needed = std::max(needed, long(std::ceil(lg.size[i][n] + double(n) * lt - top + 18)));
        }
    }
    return needed;
}

/// The terms the series needs for |t| <= bound, bounds t_hi / 2^b down to the level's start:
/// the smallest N with sum_{n >= N} |mu_n| tb^n <= 2^-60 max_n |mu_n| tb^n, for every output.
void series_lengths(const log_moments& lg, double t_hi, double start, cluster& c) {
    for (int b = 0; b < 64; ++b) {
        const double tb = std::ldexp(t_hi, -b);
        if (b > 0 && (tb < start || c.terms.back() <= 1)) break;
        const double lt = std::log10(tb);
        std::size_t need = 1;
        for (std::size_t i = 0; i < lg.mu.size(); ++i) {
            const std::vector<double>& log_mu = lg.mu[i];
            double top = -1e300;
            for (std::size_t n = 0; n < log_mu.size(); ++n) top = std::max(top, log_mu[n] + double(n) * lt);
            if (top < -1e299) continue;
            double tail = 0;
            std::size_t N = log_mu.size();
            while (N > 0) {
                const double add = std::pow(10.0, log_mu[N - 1] + double(N - 1) * lt - top);
                if (tail + add > std::ldexp(1.0, -60)) break;
                tail += add;
                --N;
            }
            need = std::max(need, N);
        }
        c.bound.push_back(tb);
        c.terms.push_back(need);
    }
}

/// A group of two or more exponents, evaluated as the Taylor series about its centre (header)
/// on the level [start, end); false for a group in the lower half plane (the mirror image of one
/// in the upper). Raises needed_digits to what its moments' cancellation needs.
bool series_cluster(const spectrum& s, const std::vector<std::size_t>& group, double start, double end,
                    long& needed_digits, cluster& c) {
    // the centre, as the double-double it will be evaluated with
    numeric centre = 0;
    for (std::size_t k : group) centre += s.upper[k];
    centre = centre / numeric(static_cast<long>(group.size()));
    double spread = 0;
    for (std::size_t k : group) spread = std::max(spread, dbl(GiNaC::abs(s.upper[k] - centre)));
    const int half = side(s, centre, spread);
    if (half < 0) return false;
    if (half == 0) centre = centre.real();  // a cluster symmetric about the real axis
    const double weight = half > 0 ? 2 : 1;
    std::tie(c.re_hi, c.re_lo) = split(centre.real());
    std::tie(c.im_hi, c.im_lo) = split(centre.imag());
    const numeric at = exact(c.re_hi) + exact(c.re_lo) + GiNaC::I * (exact(c.im_hi) + exact(c.im_lo));
    double rho = 0;
    for (std::size_t k : group) rho = std::max(rho, dbl(GiNaC::abs(s.upper[k] - at)));
    const double t_hi = end;
    const std::size_t n_max = s.max_m + 40 + static_cast<std::size_t>(std::ceil(3 * rho * t_hi));
    if (n_max > 600) throw domain_error("spectral evaluator: a cluster of exponents too wide for its series");
    const moments mo = moments_about(s, group, at, n_max);
    const log_moments lg = logs_of(mo);
    const double t_lo = std::max(start, t_hi * std::ldexp(1.0, -30));  // (down to 2^-30 t_hi at the first level)
    needed_digits = std::max(needed_digits, digits_for_cancellation(lg, t_lo, t_hi));
    series_lengths(lg, t_hi, start, c);
    c.series = true;
    c.length = c.terms.front();
    c.coeff.assign(s.n_out * c.length, 0.0);
    for (std::size_t i = 0; i < s.n_out; ++i)
        for (std::size_t n = 0; n < c.length; ++n)
            c.coeff[i * c.length + n] = {weight * dbl(mo.mu[i][n].real()), weight * dbl(mo.mu[i][n].imag())};
    return true;
}

/// Level j: from R / lengths[j - 1] (0 for j = 0) to R / lengths[j] (infinity for the last),
/// the exponents joined by the tree's edges shorter than lengths[j - 1] (all for j = 0).
level level_of(const spectrum& s, const std::vector<edge>& tree, const std::vector<double>& lengths, std::size_t j,
               double R, long& needed_digits) {
    level lv;
    lv.start = j == 0 ? 0.0 : R / lengths[j - 1];
    const double end = j < lengths.size() ? R / lengths[j] : INFINITY;
    const double cut = j == 0 ? INFINITY : lengths[j - 1];
    for (const auto& group : groups_below(tree, s.upper.size(), cut)) {
        if (group.empty()) continue;
        cluster c;
        const bool kept = group.size() == 1 ? direct_cluster(s, group[0], c)
                                            : series_cluster(s, group, lv.start, end, needed_digits, c);
        if (kept) lv.clusters.push_back(std::move(c));
    }
    return lv;
}

}  // namespace

spectral_function::spectral_function(const std::vector<ex>& outputs, const ex& t, const spectral_options& options)
    : n_outputs_(outputs.size()) {
    if (!GiNaC::is_a<GiNaC::symbol>(t)) throw type_error("spectral evaluator: the input must be a symbol");
    if (!(options.resolution > 0)) throw domain_error("spectral evaluator: the resolution must be positive");
    const double R = options.resolution;
    const std::vector<term> terms = terms_of(outputs, t);
    const std::size_t n_out = outputs.size();

    long digits = 60;
    for (int attempt = 0;; ++attempt) {
        // exponents and coefficients with `digits` digits
        const numeric tiny = GiNaC::pow(numeric(10), numeric(-(digits - 15)));
        const numeric loose = GiNaC::pow(numeric(10), numeric(-(digits / 2)));
        const spectrum s = fold_real(merge_exponents(terms, n_out, digits, tiny), n_out, tiny, loose);
        n_exponents_ = s.upper.size();
        const std::vector<edge> tree = spanning_tree(s.upper);
        const std::vector<double> lengths = cut_lengths(tree);
        levels_.clear();
        long needed_digits = 0;
        for (std::size_t j = 0; j <= lengths.size(); ++j)
            levels_.push_back(level_of(s, tree, lengths, j, R, needed_digits));
        if (needed_digits <= digits || attempt >= 4) {
            if (needed_digits > digits)
                throw domain_error("spectral evaluator: the cancellation needs more than " + std::to_string(digits) +
                                   " digits at compile time");
            break;
        }
        digits = std::min<long>(4000, needed_digits + 20);
    }
}

void spectral_function::eval(double t, double* out) const {
    for (std::size_t i = 0; i < n_outputs_; ++i) out[i] = 0;
    if (levels_.empty()) return;
    const double at = std::fabs(t);
    std::size_t j = levels_.size() - 1;
    while (j > 0 && levels_[j].start > at) --j;
    for (const cluster& c : levels_[j].clusters) {
        // e^(c t) with the phase formed exactly (c_hi t split by fma, first-order correction)
        double er = 1, ei = 0;
        if (c.re_hi != 0) {
            const double p = c.re_hi * t;
            const double d = std::fma(c.re_hi, t, -p) + c.re_lo * t;
            er = std::exp(p) * (1 + d);
        }
        if (c.im_hi != 0) {
            const double p = c.im_hi * t;
            const double d = std::fma(c.im_hi, t, -p) + c.im_lo * t;
            const double s = std::sin(p), co = std::cos(p);
            ei = er * (s + d * co);
            er = er * (co - d * s);
        }
        std::size_t n = c.length;
        if (c.series && at > 0) {
            // the terms for |t| <= bound[b] = bound[0] / 2^b, b = floor(log2(bound[0] / |t|))
            const int b = std::ilogb(c.bound[0] / at);
            n = c.terms[static_cast<std::size_t>(std::clamp(b, 0, static_cast<int>(c.terms.size()) - 1))];
        } else if (c.series) {
            n = c.terms.back();
        }
        if (ei == 0 && c.im_hi == 0) {  // a centre on the real axis: Re G only
            for (std::size_t i = 0; i < n_outputs_; ++i) {
                const std::complex<double>* k = c.coeff.data() + i * c.length;
                double gr = 0;
                for (std::size_t q = n; q-- > 0;) gr = gr * t + k[q].real();
                out[i] += er * gr;
            }
            continue;
        }
        for (std::size_t i = 0; i < n_outputs_; ++i) {
            const std::complex<double>* k = c.coeff.data() + i * c.length;
            double gr = 0, gi = 0;
            for (std::size_t q = n; q-- > 0;) {
                gr = gr * t + k[q].real();
                gi = gi * t + k[q].imag();
            }
            out[i] += er * gr - ei * gi;
        }
    }
}

void spectral_function::eval_many(const double* t, double* out, std::size_t n) const {
    for (std::size_t k = 0; k < n; ++k) eval(t[k], out + k * n_outputs_);
}

std::vector<double> spectral_function::operator()(double t) const {
    std::vector<double> out(n_outputs_);
    eval(t, out.data());
    return out;
}

}  // namespace symrep::num
