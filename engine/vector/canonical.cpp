// symrep/vector/canonical.cpp -- canonical form of vector and scalar
// expressions over abstract 3-vectors.
//
// A vector expression is expanded into a linear combination of monomials
// (an atom v, i.e. a vector symbol or a literal, or v_i x v_j with v_i < v_j)
// with scalar coefficients:
//   a x (b x c)         = (a.c) b - (a.b) c                       (BAC-CAB)
//   (a x b) x (c x d)   = [a,b,d] c - [a,b,c] d
// and the scalars are rewritten in the atoms a.b (a <= b) and [a,b,c] (sorted,
// sign of the permutation, 0 on a repeat):
//   a . (b x c)         = [a,b,c]
//   (a x b).(c x d)     = (a.c)(b.d) - (a.d)(b.c)                 (Lagrange)
//   [a,b,c][d,e,f]      = det(Gram matrix of dot products)
// Atoms are ordered by name (symbols), then literals by their text, so the
// result does not depend on symbol creation order. Literal terms are summed
// into one literal. Coefficients are expanded, products of triple products
// reduced, then normalized by GiNaC (normal() when no other function such as
// sin occurs, expand() otherwise).
#include <map>
#include <string>

#include "symrep/scalar/scalar.h"
#include "symrep/core/error.h"
#include "symrep/vector/vector.h"
#include "symrep/vector/vector_internal.h"

namespace symrep {

using GiNaC::ex;
using GiNaC::is_a;
using GiNaC::ex_to;
using namespace detail;

namespace {

std::string atom_key(const ex& a) {
    if (is_vector_symbol(a)) return "0" + name_of(a);
    return "1" + to_string(a, notation::ascii);  // a sort key: the same in both notations
}

// A vector monomial: an atom (b empty) or a x b with key(a) < key(b).
struct mon {
    ex a, b;
    bool is_cross = false;
    std::string key() const {
        return is_cross ? "2" + atom_key(a) + "|" + atom_key(b) : atom_key(a);
    }
    ex value() const { return is_cross ? vcross(a, b) : a; }
};

// key -> (monomial, coefficient)
using vlin = std::map<std::string, std::pair<mon, ex>>;

void add_to(vlin& v, const mon& m, const ex& c) {
    if (c.is_zero()) return;
    auto [it, fresh] = v.emplace(m.key(), std::make_pair(m, c));
    if (!fresh) it->second.second += c;
}

void add_to(vlin& v, const vlin& w, const ex& c) {
    for (const auto& [k, mc] : w) add_to(v, mc.first, c * mc.second);
}

vlin atom_lin(const ex& a) {
    vlin v;
    mon m;
    m.a = a;
    add_to(v, m, 1);
    return v;
}

ex mk_dot(const ex& x, const ex& y) {
    if (is_vector_literal(x) && is_vector_literal(y)) return vdot(x, y);
    return atom_key(x) <= atom_key(y) ? vdot(x, y) : vdot(y, x);
}

ex mk_triple(const ex& a, const ex& b, const ex& c) {
    if (a.is_equal(b) || b.is_equal(c) || a.is_equal(c)) return 0;
    ex x[3] = {a, b, c};
    std::string k[3] = {atom_key(a), atom_key(b), atom_key(c)};
    int sign = 1;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j + 1 < 3 - i; ++j)
            if (k[j + 1] < k[j]) {
                std::swap(k[j], k[j + 1]);
                std::swap(x[j], x[j + 1]);
                sign = -sign;
            }
    return sign * vtriple(x[0], x[1], x[2]);
}

// m1 x m2
vlin cross_mon(const mon& m1, const mon& m2) {
    vlin r;
    if (!m1.is_cross && !m2.is_cross) {
        if (m1.a.is_equal(m2.a)) return r;
        if (is_vector_literal(m1.a) && is_vector_literal(m2.a)) return atom_lin(vcross(m1.a, m2.a));
        mon m;
        m.is_cross = true;
        const bool ordered = atom_key(m1.a) < atom_key(m2.a);
        m.a = ordered ? m1.a : m2.a;
        m.b = ordered ? m2.a : m1.a;
        add_to(r, m, ordered ? 1 : -1);
        return r;
    }
    mon b, c;
    if (!m1.is_cross) {  // a x (b x c) = (a.c) b - (a.b) c
        const ex& a = m1.a;
        b.a = m2.a;
        c.a = m2.b;
        add_to(r, b, mk_dot(a, m2.b));
        add_to(r, c, -mk_dot(a, m2.a));
        return r;
    }
    if (!m2.is_cross) {  // (b x c) x a = (a.b) c - (a.c) b
        const ex& a = m2.a;
        b.a = m1.a;
        c.a = m1.b;
        add_to(r, c, mk_dot(a, m1.a));
        add_to(r, b, -mk_dot(a, m1.b));
        return r;
    }
    // (a x b) x (c x d) = [a,b,d] c - [a,b,c] d
    c.a = m2.a;
    mon d;
    d.a = m2.b;
    add_to(r, c, mk_triple(m1.a, m1.b, m2.b));
    add_to(r, d, -mk_triple(m1.a, m1.b, m2.a));
    return r;
}

// m1 . m2
ex dot_mon(const mon& m1, const mon& m2) {
    if (!m1.is_cross && !m2.is_cross) return mk_dot(m1.a, m2.a);
    if (!m1.is_cross) return mk_triple(m1.a, m2.a, m2.b);
    if (!m2.is_cross) return mk_triple(m2.a, m1.a, m1.b);
    return mk_dot(m1.a, m2.a) * mk_dot(m1.b, m2.b) - mk_dot(m1.a, m2.b) * mk_dot(m1.b, m2.a);
}

vlin cross_lin(const vlin& x, const vlin& y) {
    vlin r;
    for (const auto& [k1, mc1] : x)
        for (const auto& [k2, mc2] : y) add_to(r, cross_mon(mc1.first, mc2.first), mc1.second * mc2.second);
    return r;
}

ex dot_lin(const vlin& x, const vlin& y) {
    ex s = 0;
    for (const auto& [k1, mc1] : x)
        for (const auto& [k2, mc2] : y) s += mc1.second * mc2.second * dot_mon(mc1.first, mc2.first);
    return s;
}

bool has_vector_data(const ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (is_a<GiNaC::matrix>(*it) || is_vector_symbol(*it)) return true;
    return false;
}

ex rscal(const ex& e);

vlin rvec(const ex& e) {
    if (e.is_zero()) return {};
    if (is_vector_symbol(e)) return atom_lin(e);
    if (is_vector_literal(e)) {
        // literal components are scalars; reduce them too
        const ex l = GiNaC::matrix(3, 1, GiNaC::lst{rscal(comp(e, 0)), rscal(comp(e, 1)), rscal(comp(e, 2))});
        return atom_lin(l);
    }
    if (is_a<GiNaC::add>(e)) {
        vlin r;
        for (std::size_t i = 0; i < e.nops(); ++i) add_to(r, rvec(e.op(i)), 1);
        return r;
    }
    if (is_a<GiNaC::mul>(e)) {
        const auto [s, v] = split_scalar(e);
        vlin r;
        add_to(r, rvec(v), rscal(s));
        return r;
    }
    if (is_cross(e)) return cross_lin(rvec(e.op(0)), rvec(e.op(1)));
    throw type_error("canonical: not a vector expression: " + message_text(e));
}

ex rscal(const ex& e) {
    if (!has_vector_data(e)) return e;
    if (is_dot(e)) return dot_lin(rvec(e.op(0)), rvec(e.op(1)));
    if (is_triple(e)) return dot_lin(rvec(e.op(0)), cross_lin(rvec(e.op(1)), rvec(e.op(2))));
    struct mapper : GiNaC::map_function {
        ex operator()(const ex& x) override { return rscal(x); }
    } f;
    return e.map(f);
}

// [a,b,c][d,e,f] = det(Gram)
ex gram(const ex& t1, const ex& t2) {
    ex g[3][3];
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j) g[i][j] = mk_dot(t1.op(i), t2.op(j));
    return g[0][0] * (g[1][1] * g[2][2] - g[1][2] * g[2][1]) - g[0][1] * (g[1][0] * g[2][2] - g[1][2] * g[2][0]) +
           g[0][2] * (g[1][0] * g[2][1] - g[1][1] * g[2][0]);
}

// One product term: replaces one pair of triple-product factors, if any.
bool gram_term(const ex& t, ex& out) {
    std::vector<ex> factors = is_a<GiNaC::mul>(t) ? std::vector<ex>(t.begin(), t.end()) : std::vector<ex>{t};
    for (std::size_t i = 0; i < factors.size(); ++i) {
        const ex& f = factors[i];
        const bool pw = is_a<GiNaC::power>(f) && is_triple(f.op(0)) && is_a<GiNaC::numeric>(f.op(1)) &&
                        ex_to<GiNaC::numeric>(f.op(1)).is_pos_integer();
        if (pw) {  // T^n, n >= 2
            const ex T = f.op(0);
            factors[i] = GiNaC::pow(T, f.op(1) - 2) * gram(T, T);
        } else if (is_triple(f)) {
            std::size_t j = i + 1;
            while (j < factors.size() && !is_triple(factors[j])) ++j;
            if (j == factors.size()) continue;
            factors[i] = gram(f, factors[j]);
            factors[j] = 1;
        } else {
            continue;
        }
        ex p = 1;
        for (const ex& x : factors) p *= x;
        out = p;
        return true;
    }
    return false;
}

ex gram_reduce(ex c) {
    for (int guard = 0; guard < 1000; ++guard) {
        c = GiNaC::expand(c);
        bool changed = false;
        if (is_a<GiNaC::add>(c)) {
            ex s = 0;
            for (std::size_t i = 0; i < c.nops(); ++i) {
                ex o;
                if (gram_term(c.op(i), o)) {
                    changed = true;
                    s += o;
                } else {
                    s += c.op(i);
                }
            }
            c = s;
        } else {
            ex o;
            if (gram_term(c, o)) {
                changed = true;
                c = o;
            }
        }
        if (!changed) return c;
    }
    return c;
}

bool has_other_function(const ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (is_a<GiNaC::function>(*it) && !is_dot(*it) && !is_triple(*it)) return true;
    return false;
}

ex normalize_coef(const ex& c) {
    const ex e = gram_reduce(c);
    if (e.is_zero()) return e;
    if (has_other_function(e)) return GiNaC::expand(normalize_trig_signs(e));
    // (the sign of a sum in a denominator follows GiNaC's internal order;
    // to_string() normalizes it in the text)
    return GiNaC::normal(e);
}

}  // namespace

std::vector<vector_term> canonical_terms(const ex& e) {
    if (!kind(e)) {
        const ex c = normalize_coef(rscal(e));
        if (c.is_zero()) return {};
        return {vector_term{1, c}};
    }
    const vlin v = rvec(e);
    std::vector<vector_term> out;
    ex lit[3] = {0, 0, 0};
    bool has_lit = false;
    for (const auto& [k, mc] : v) {  // in key order: symbols by name, literals, cross products
        const mon& m = mc.first;
        if (!m.is_cross && is_vector_literal(m.a)) {
            for (unsigned i = 0; i < 3; ++i) lit[i] += mc.second * comp(m.a, i);
            has_lit = true;
            continue;
        }
        const ex c = normalize_coef(mc.second);
        if (!c.is_zero()) out.push_back(vector_term{m.value(), c});
    }
    if (has_lit) {
        for (auto& x : lit) x = normalize_coef(x);
        if (!(lit[0].is_zero() && lit[1].is_zero() && lit[2].is_zero()))
            out.push_back(vector_term{GiNaC::matrix(3, 1, GiNaC::lst{lit[0], lit[1], lit[2]}), 1});
    }
    return out;
}

ex canonical(const ex& e) {
    ex result = 0;
    for (const auto& t : canonical_terms(e)) result += t.coefficient * t.monomial;
    return result;
}

}  // namespace symrep
