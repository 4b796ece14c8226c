// symrep/mechanics/residual_proof.cpp -- the zero proofs of check() (residual_proof.h): in the
// algebra of K, coordinate-free on quasi-polynomial coefficients, and with integral objects.
#include "symrep/mechanics/residual_proof.h"
#include "symrep/mechanics/quasi_polynomial.h"

#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <optional>
#include <set>

#include "symrep/scalar/scalar.h"
#include "symrep/core/error.h"
#include "symrep/numeric/quadrature.h"
#include "symrep/vector/vector.h"

namespace symrep::mechanics {

using GiNaC::ex;

namespace {

using vmap = std::map<ex, ex, GiNaC::ex_is_less>;
using num::has_integral;

// (linearity) sum_i c_i int_a^b f_i dtau -> int_a^b (sum_i c_i f_i) dtau for the c_i free of
// tau: the integral objects of a solution (fixed_axis.h) meet in its residual as several
// integrals over the same range, which cancel only as one.
ex merge_integrals(const ex& e) {
    const ex x = GiNaC::expand(e);
    std::vector<std::pair<ex, ex>> groups;  // (integral with integrand 1 as the key, sum of c_i f_i)
    ex rest = 0;
    for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(x) ? x.nops() : 1); ++i) {
        const ex term = GiNaC::is_a<GiNaC::add>(x) ? x.op(i) : x;
        ex I;  // the one integral factor of term
        std::size_t count = 0;
        const std::size_t n = GiNaC::is_a<GiNaC::mul>(term) ? term.nops() : 1;
        for (std::size_t j = 0; j < n; ++j) {
            const ex f = GiNaC::is_a<GiNaC::mul>(term) ? term.op(j) : term;
            if (GiNaC::is_a<GiNaC::integral>(f)) {
                I = f;
                ++count;
            } else if (has_integral(f)) {
                count = 2;
            }
        }
        if (count != 1 || I.op(0).is_equal(0)) {
            rest += term;
            continue;
        }
        const ex c = term / I;
        if (c.has(I.op(0))) {
            rest += term;
            continue;
        }
        const ex key = GiNaC::lst{I.op(0), I.op(1), I.op(2)};
        auto g = std::find_if(groups.begin(), groups.end(), [&](const auto& p) { return p.first.is_equal(key); });
        if (g == groups.end()) groups.push_back({key, c * I.op(3)});
        else g->second += c * I.op(3);
    }
    for (const auto& [key, f] : groups) {
        const ex F = GiNaC::normal(GiNaC::expand(f));
        if (!F.is_zero()) rest += GiNaC::integral(key.op(0), key.op(1), key.op(2), F);
    }
    return rest;
}

// sin(A), cos(A) as sin, cos of a fresh symbol per argument A (the angle a(t) of a rate
// a + b sin(c t), w0 t, w0 tau). Sound for a zero proof: what vanishes for every value of
// the symbols vanishes at the arguments. The residual of a Duhamel integral needs only
// sin^2 + cos^2 = 1 per argument (G(t - tau) is split by the addition theorems), and the
// zero test then works with a few independent angles instead of exponentials of each.
ex atomize_trig_arguments(const ex& e) {
    // the outermost sin and cos (those inside another one's argument go with it)
    std::vector<ex> outer;
    std::function<void(const ex&)> collect = [&](const ex& x) {
        if (is_ex_the_function(x, GiNaC::sin) || is_ex_the_function(x, GiNaC::cos)) {
            if (!GiNaC::is_a<GiNaC::numeric>(x.op(0))) outer.push_back(x);
            return;
        }
        for (std::size_t i = 0; i < x.nops(); ++i) collect(x.op(i));
    };
    collect(e);
    std::vector<std::pair<ex, ex>> args;  // expanded argument -> symbol
    GiNaC::exmap sub;
    for (const ex& f : outer) {
        const ex A = GiNaC::expand(f.op(0));
        ex alpha;
        int sign = 1;
        for (const auto& [k, sym] : args) {
            if (k.is_equal(A)) alpha = sym;
            else if (GiNaC::expand(k + A).is_zero()) alpha = sym, sign = -1;
            if (!alpha.is_zero()) break;
        }
        if (alpha.is_zero()) {
            alpha = GiNaC::realsymbol("alpha" + std::to_string(args.size()));
            args.push_back({A, alpha});
        }
        sub[f] = is_ex_the_function(f, GiNaC::sin) ? sign * GiNaC::sin(alpha) : GiNaC::cos(alpha);
    }
    return sub.empty() ? e : e.subs(sub, GiNaC::subs_options::no_pattern);
}

// The bound variables of the integral objects renamed by nesting depth (tau_0 for an integral
// without one inside, tau_1 around those, ...): int_0^t g(tau) dtau and int_0^t g(sigma) dsigma,
// which meet in a residual when a nested integral is differentiated, become one object.
int integral_depth(const ex& e) {
    int d = -1;
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::integral>(*it)) d = std::max(d, 1 + integral_depth(it->op(3)));
    return d;
}

ex canonical_bound_variables(const ex& e) {
    if (!has_integral(e)) return e;
    if (GiNaC::is_a<GiNaC::integral>(e) && GiNaC::is_a<GiNaC::symbol>(e.op(0))) {
        static std::vector<ex> names;
        const ex f = canonical_bound_variables(e.op(3));
        const std::size_t d = std::size_t(1 + integral_depth(f));
        while (names.size() <= d) names.push_back(GiNaC::realsymbol("tau_" + std::to_string(names.size())));
        return GiNaC::integral(names[d], e.op(1), e.op(2), f.subs(e.op(0) == names[d]));
    }
    struct recurse : GiNaC::map_function {
        ex operator()(const ex& c) override { return canonical_bound_variables(c); }
    } inner;
    return e.map(inner);
}

}  // namespace

// (issue 15.2) A vector residual proved 0 coordinate-free: each coefficient of its canonical
// form, with |v| a positive symbol (|v|^2 for v . v), a quasi-polynomial in t that is the zero
// function (quasi_polynomial's canonical form: t^k e^(lambda t) for distinct (k, lambda) are
// independent, each coefficient by the scalar zero test). Sound: an identity in independent
// symbols holds at |v|; when a coefficient is not read or not proved 0, nothing is concluded
// (the canonical form is not unique with four vectors or more) and the caller decides by
// components, which with |w| = sqrt(w1^2 + w2^2 + w3^2) cost 100 times the derivation.
bool quasi_polynomial_residual_zero(const ex& r, const ex& t) {
    try {
        for (const vector_term& term : canonical_terms(r)) {
            // |v| a positive symbol (|v|^2 for v . v), the other dot and triple products independent
            // real symbols
            GiNaC::exmap atoms;
            std::size_t count = 0;
            std::function<void(const ex&)> scan = [&](const ex& x) {
                if (atoms.count(x)) return;
                if (is_ex_the_function(x, vdot) || is_ex_the_function(x, vtriple)) {
                    if (is_ex_the_function(x, vdot) && x.op(0).is_equal(x.op(1))) {
                        const GiNaC::possymbol n("|v" + std::to_string(count++) + "|");
                        atoms[x] = GiNaC::pow(n, 2);
                        atoms[GiNaC::sqrt(x)] = n;
                    } else {
                        atoms[x] = GiNaC::realsymbol("d" + std::to_string(count++));
                    }
                    return;
                }
                for (std::size_t i = 0; i < x.nops(); ++i) scan(x.op(i));
            };
            scan(term.coefficient);
            const ex c = term.coefficient.subs(atoms, GiNaC::subs_options::no_pattern);
            if (!vector_symbols(c).empty()) return false;  // a vector left where no atom was read
            if (!quasi_polynomial::from_ex(c, t).is_zero()) return false;
        }
    } catch (const domain_error&) {
        return false;
    }
    return true;
}

// (issue 15.2) The check in the algebra of K = w x (VI.1.21-22, 26-38): s read exactly as
//     s = sum_v [ c0_v(t) v + c1_v(t) K v + c2_v(t) K^2 v ]
// over the vector symbols v of the problem's data (K^2 v = w (w . v) - |w|^2 v), each c_k a
// quasi-polynomial in t, and the residual  sum_m A_m(K) s^(m) - sum_j q_j K^(k_j) F_j  computed
// on those coefficients (derivatives and products by K^3 = -|w|^2 K in quasi_polynomial
// arithmetic), each coefficient decided by the scalar zero test. All coefficients 0 proves the
// residual 0 (it is their combination); otherwise, or when s is not of that form (another
// vector, a literal, a coefficient not a quasi-polynomial), nothing is concluded and the caller
// tests the vector residual. Costs a few derivations where expanding the vector residual cost
// 15 (t e^-t cos 2t forcing).
namespace operator_check {

namespace {

using triple = std::array<quasi_polynomial, 3>;

// a_v v + b_v (w x v) per vector symbol v
struct reading {
    vmap a, b;
};

void add_into(reading& x, const reading& y, const ex& scale) {
    for (const auto& [v, c] : y.a) x.a[v] += scale * c;
    for (const auto& [v, c] : y.b) x.b[v] += scale * c;
}

// K applied to a reading: v -> w x v, w x v -> w (w . v) - v (w . w)
reading apply_K(const reading& y, const ex& w) {
    reading x;
    for (const auto& [v, c] : y.a)
        if (!v.is_equal(w)) x.b[v] += c;
    for (const auto& [v, c] : y.b) {
        if (v.is_equal(w)) continue;
        x.a[w] += c * dot(w, v);
        x.a[v] -= c * dot(w, w);
    }
    return x;
}

// c when y is c w exactly (structurally), nullopt otherwise
std::optional<ex> multiple_of(const reading& y, const ex& w) {
    if (!y.b.empty() || y.a.size() != 1 || !y.a.begin()->first.is_equal(w)) return std::nullopt;
    return y.a.begin()->second;
}

std::optional<reading> read(const ex& e, const ex& w) {
    reading x;
    if (is_vector_symbol(e)) {
        x.a[e] = 1;
        return x;
    }
    if (GiNaC::is_a<GiNaC::add>(e)) {
        for (std::size_t i = 0; i < e.nops(); ++i) {
            const auto y = read(e.op(i), w);
            if (!y) return std::nullopt;
            add_into(x, *y, 1);
        }
        return x;
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
        ex scale = 1;
        std::optional<ex> vec;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            if (!is_vector(e.op(i))) {
                scale *= e.op(i);
            } else if (!vec) {
                vec = e.op(i);
            } else {
                return std::nullopt;  // a vector in two factors (a dot product times a vector, say)
            }
        }
        if (!vec) return std::nullopt;
        const auto y = read(*vec, w);
        if (!y) return std::nullopt;
        add_into(x, *y, scale);
        return x;
    }
    if (is_ex_the_function(e, vcross) && !w.is_zero()) {
        const auto l = read(e.op(0), w), r = read(e.op(1), w);
        if (!l || !r) return std::nullopt;
        if (const auto c = multiple_of(*l, w)) {  // (c w) x y = c K y
            add_into(x, apply_K(*r, w), *c);
            return x;
        }
        if (const auto c = multiple_of(*r, w)) {  // y x (c w) = -c K y
            add_into(x, apply_K(*l, w), -*c);
            return x;
        }
    }
    return std::nullopt;
}

// The coefficients (c0, c1, c2) of s on each data vector symbol, |w| as Omega, into out; false
// when s is not read so.
bool coefficients(const cauchy_problem& P, const operator_form& F, const ex& s,
                                 std::map<ex, triple, GiNaC::ex_is_less>& out) {
    const ex& w = F.axis;
    if (!w.is_zero() && (!is_vector_symbol(w) || !GiNaC::is_a<GiNaC::symbol>(F.Omega))) return false;
    std::set<ex, GiNaC::ex_is_less> data;
    for (const auto& [name, v] : F.data) {
        if (v.is_zero()) continue;  // x(0) = 0
        if (!is_vector_symbol(v) || v.is_equal(w)) return false;
        data.insert(v);
    }
    const auto x = read(s, w);
    if (!x) return false;
    // |w| -> Omega, w . v -> d_v (fresh), then every coefficient free of vectors
    GiNaC::exmap to_omega;
    vmap d;
    if (!w.is_zero()) {
        to_omega[dot(w, w)] = GiNaC::pow(F.Omega, 2);
        for (const ex& v : data) d[v] = GiNaC::realsymbol("d_" + to_string(v));
    }
    GiNaC::exmap to_d = to_omega;
    for (const auto& [v, s_v] : d) to_d[dot(w, v)] = s_v;
    auto scalar = [&](const ex& c) -> std::optional<ex> {
        const ex y = c.subs(to_omega, GiNaC::subs_options::no_pattern);
        if (!vector_symbols(y).empty()) return std::nullopt;
        return y;
    };
    std::map<ex, std::array<ex, 3>, GiNaC::ex_is_less> c;
    for (const ex& v : data) c[v] = {0, 0, 0};
    for (const auto& [v, a] : x->a) {
        if (v.is_equal(w)) continue;
        if (!data.count(v)) return false;
        const auto y = scalar(a);
        if (!y) return false;
        c[v][0] += *y;
    }
    for (const auto& [v, b] : x->b) {
        if (!data.count(v)) return false;
        const auto y = scalar(b);
        if (!y) return false;
        c[v][1] += *y;
    }
    if (const auto it = x->a.find(w); it != x->a.end()) {
        // a_w = sum_v c2_v (w . v), linear in the d_v with nothing else
        const ex aw = it->second.subs(to_d, GiNaC::subs_options::no_pattern);
        if (!vector_symbols(aw).empty()) return false;
        GiNaC::exmap none;
        for (const auto& [v, s_v] : d) none[s_v] = 0;
        if (!aw.subs(none, GiNaC::subs_options::no_pattern).is_zero()) return false;
        for (const auto& [v, s_v] : d) {
            const ex c2 = aw.diff(GiNaC::ex_to<GiNaC::symbol>(s_v));
            for (const auto& [u, s_u] : d)
                if (c2.has(s_u)) return false;
            c[v][2] += c2;
            c[v][0] += GiNaC::pow(F.Omega, 2) * c2;
        }
    }
    try {
        for (const auto& [v, k] : c)
            out[v] = {quasi_polynomial::from_ex(k[0], P.t), quasi_polynomial::from_ex(k[1], P.t),
                      quasi_polynomial::from_ex(k[2], P.t)};
    } catch (const domain_error&) {
        return false;
    }
    return true;
}

}  // namespace

proof prove(const cauchy_problem& P, const ex& s) {
    if (!P.is_vector || P.fixed_axis || P.turning || P.velocity) return {};
    try {
        const operator_form F = P.reduced ? *P.reduced : reduce(P);
        if (!F.general.empty()) return {};  // Duhamel integral objects: integral_residual_zero
        std::map<ex, triple, GiNaC::ex_is_less> G;
        if (!coefficients(P, F, s, G)) return {};
        const ex W2 = GiNaC::pow(F.Omega, 2);
        auto K = [&](const triple& c) { return triple{quasi_polynomial(), c[0] - W2 * c[2], c[1]}; };
        const std::map<std::string, ex> data(F.data.begin(), F.data.end());
        const std::size_t M = F.ode.A.size() - 1;
        proof out{true, true};
        for (const auto& [v, g] : G) {
            triple lhs{}, Gm = g;
            for (std::size_t m = 0; m <= M; ++m) {
                if (m < M) {  // s^(m)(0) = x^(m)(0) on v
                    const bool here = data.at(F.ode.initial[m]).is_equal(v);
                    for (int k = 0; k < 3; ++k) {  // the zero proof of normalize(); else the caller tests
                        const cex at0 = Gm[k].at_zero_untidied();
                        out.initial = out.initial && proved_zero_by_denominators(at0.re - (here && k == 0 ? 1 : 0)) &&
                                      proved_zero_by_denominators(at0.im);
                    }
                }
                triple KjG = Gm;  // A_m(K) s^(m)
                for (std::size_t j = 0; j < F.ode.A[m].size(); ++j) {
                    if (j) KjG = K(KjG);
                    for (int k = 0; k < 3; ++k) lhs[k] = lhs[k] + F.ode.A[m][j] * KjG[k];
                }
                for (int k = 0; k < 3; ++k) Gm[k] = Gm[k].derivative();
            }
            for (const forcing_term& f : F.ode.forcing) {
                if (!data.at(f.vector).is_equal(v)) continue;
                triple q{f.q, quasi_polynomial(), quasi_polynomial()};
                for (unsigned j = 0; j < f.power; ++j) q = K(q);
                for (int k = 0; k < 3; ++k) lhs[k] = lhs[k] - q[k];
            }
            for (const auto& r : lhs) out.residual = out.residual && r.is_zero();
            if (!out.residual) return {};
        }
        // an initial value or a forcing vector met in no coefficient of s
        for (std::size_t m = 0; m < M; ++m) {
            const ex& u = data.at(F.ode.initial[m]);
            out.initial = out.initial && (u.is_zero() || G.count(u));
        }
        for (const forcing_term& f : F.ode.forcing)
            if (!G.count(data.at(f.vector))) return {};
        return out;
    } catch (const type_error&) {  // a form the reading does not take: the caller decides
        return {};
    } catch (const domain_error&) {
        return {};
    }
}

}  // namespace operator_check

// A vector residual with integral objects: 0 when each component, with fresh symbols for the
// vectors and the integrals merged, is 0.
bool integral_residual_zero(const ex& r0) {
    const ex r = canonical_bound_variables(r0);
    // coordinate-free first (fewer symbols: dot products and norms as atoms); the canonical
    // form is not unique with four vectors or more, so a coefficient left is not a proof of
    // anything: then by components
    bool all_zero = true;
    for (const vector_term& term : canonical_terms(r))
        if (!is_zero_scalar(atomize_trig_arguments(merge_integrals(term.coefficient)))) {
            all_zero = false;
            break;
        }
    if (all_zero) return true;
    vmap comps;
    for (const ex& v : vector_symbols(r)) {
        const std::string n = to_string(v);
        comps[v] = vector_literal(GiNaC::realsymbol(n + "_1"), GiNaC::realsymbol(n + "_2"), GiNaC::realsymbol(n + "_3"));
    }
    const ex c = subs_components(r, comps);
    for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::matrix>(c) ? c.nops() : 1); ++i)
        if (!is_zero_scalar(atomize_trig_arguments(merge_integrals(GiNaC::is_a<GiNaC::matrix>(c) ? c.op(i) : c))))
            return false;
    return true;
}

}  // namespace symrep::mechanics
