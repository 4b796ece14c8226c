// symrep/vector/vector.cpp -- the vector registry, cross/dot/triple with their
// cheap eval rules, the vector/scalar check, d/dt and component substitution.
// See vector.h for the representation.
#include "symrep/vector/vector.h"

#include <algorithm>
#include <list>
#include <mutex>
#include <random>

#include "symrep/scalar/scalar.h"
#include "symrep/core/error.h"
#include "symrep/vector/vector_internal.h"

namespace symrep {

using GiNaC::ex;
using GiNaC::is_a;
using GiNaC::ex_to;

// ------------------------------------------------------------------ registry
namespace {

struct entry {
    ex sym;
    ex t;        // the time symbol for a vector function, empty (0) otherwise
    bool timed = false;
    ex deriv;    // the derivative symbol, created on demand
    bool has_deriv = false;
};

// name -> the registered symbols of that name; the first one is the symbol
// vector_symbol(name) returns. Several symbols may share a name (e.g. one per
// interpreter session); they are different vectors. std::list: entries stay put.
struct name_entries {
    std::list<entry> list;
    bool has_primary = false;  // list.front() was made by vector_symbol()
};

std::recursive_mutex& reg_mutex() {  // recursive: a message built under it prints vectors (message_text)
    static std::recursive_mutex m;
    return m;
}
std::map<std::string, name_entries>& registry() {
    static std::map<std::string, name_entries> r;
    return r;
}

void check_name(const char* who, const std::string& name) {
    if (name.empty()) throw type_error(std::string(who) + ": the name of a vector must not be empty");
    for (char c : name)
        if (c == ' ' || c == '\t' || c == '\n' || c == '(' || c == ')' || c == '[' || c == ']' || c == ',' ||
            c == '\'')
            throw type_error(std::string(who) + ": invalid character in the vector name '" + name +
                             "' (' is reserved for derivatives)");
}

// Registry lookup: the entry of the vector symbol e, or nullptr. Caller holds the lock.
entry* find_entry(const ex& e) {
    if (!is_a<GiNaC::symbol>(e)) return nullptr;
    auto& r = registry();
    auto it = r.find(ex_to<GiNaC::symbol>(e).get_name());
    if (it == r.end()) return nullptr;
    for (entry& en : it->second.list)
        if (en.sym.is_equal(e)) return &en;
    return nullptr;
}

// Adds sym (not yet registered) to the registry. Caller holds the lock.
entry& add_entry(const ex& sym, bool primary) {
    auto& ne = registry()[ex_to<GiNaC::symbol>(sym).get_name()];
    entry en;
    en.sym = sym;
    if (primary) {
        ne.list.push_front(en);
        ne.has_primary = true;
        return ne.list.front();
    }
    ne.list.push_back(en);
    return ne.list.back();
}

void make_timed(entry& en, const ex& t, const char* who) {
    const std::string name = ex_to<GiNaC::symbol>(en.sym).get_name();
    if (en.timed) {
        if (!en.t.is_equal(t))
            throw type_error(std::string(who) + ": '" + name + "' already depends on another variable");
        return;
    }
    if (name.find('\'') != std::string::npos)
        throw type_error(std::string(who) + ": '" + name + "' is a derivative symbol");
    en.timed = true;
    en.t = t;
}

}  // namespace

ex vector_symbol(const std::string& name) {
    check_name("vector_symbol", name);
    std::lock_guard<std::recursive_mutex> lock(reg_mutex());
    auto& r = registry();
    auto it = r.find(name);
    if (it != r.end() && it->second.has_primary) return it->second.list.front().sym;
    return add_entry(GiNaC::realsymbol(name), true).sym;
}

void register_vector(const ex& sym) {
    if (!is_a<GiNaC::symbol>(sym))
        throw type_error("register_vector: " + message_text(sym) + " is not a symbol");
    check_name("register_vector", ex_to<GiNaC::symbol>(sym).get_name());
    std::lock_guard<std::recursive_mutex> lock(reg_mutex());
    if (!find_entry(sym)) add_entry(sym, false);
}

ex vector_function(const std::string& name, const ex& t) {
    if (!is_a<GiNaC::symbol>(t))
        throw type_error("vector_function: the variable " + message_text(t) + " is not a symbol");
    const ex r = vector_symbol(name);
    std::lock_guard<std::recursive_mutex> lock(reg_mutex());
    make_timed(*find_entry(r), t, "vector_function");
    return r;
}

void register_vector_function(const ex& sym, const ex& t) {
    if (!is_a<GiNaC::symbol>(t))
        throw type_error("register_vector_function: the variable " + message_text(t) + " is not a symbol");
    register_vector(sym);
    std::lock_guard<std::recursive_mutex> lock(reg_mutex());
    make_timed(*find_entry(sym), t, "register_vector_function");
}

ex derivative(const ex& r) {
    std::lock_guard<std::recursive_mutex> lock(reg_mutex());
    entry* en = find_entry(r);
    if (!en || !en->timed)
        throw type_error("derivative: " + message_text(r) + " is not a vector function (declare it with vector_function)");
    if (en->has_deriv) return en->deriv;
    entry& d = add_entry(GiNaC::realsymbol(ex_to<GiNaC::symbol>(r).get_name() + "'"), false);
    d.timed = true;
    d.t = en->t;
    en->deriv = d.sym;
    en->has_deriv = true;
    return d.sym;
}

bool is_vector_symbol(const ex& e) {
    if (!is_a<GiNaC::symbol>(e)) return false;
    std::lock_guard<std::recursive_mutex> lock(reg_mutex());
    return find_entry(e) != nullptr;
}

bool is_vector_literal(const ex& e) {
    if (!is_a<GiNaC::matrix>(e)) return false;
    const auto& m = ex_to<GiNaC::matrix>(e);
    return m.rows() == 3 && m.cols() == 1;
}

ex vector_literal(const ex& x, const ex& y, const ex& z) {
    for (const ex& c : {x, y, z})
        if (is_vector(c))
            throw type_error("vector literal: the component " + message_text(c) + " is a vector, expected a scalar");
    return GiNaC::matrix(3, 1, GiNaC::lst{x, y, z});
}

// ------------------------------------------------------------ vector check
namespace detail {

std::string name_of(const ex& sym) { return ex_to<GiNaC::symbol>(sym).get_name(); }

bool is_fn(const ex& e, unsigned serial) {
    return is_a<GiNaC::function>(e) && ex_to<GiNaC::function>(e).get_serial() == serial;
}
bool is_cross(const ex& e) { return is_fn(e, vcross_SERIAL::serial); }
bool is_dot(const ex& e) { return is_fn(e, vdot_SERIAL::serial); }
bool is_triple(const ex& e) { return is_fn(e, vtriple_SERIAL::serial); }

// 1 for a vector, 0 for a scalar; throws on an ill-formed expression.
int kind(const ex& e) {
    if (is_a<GiNaC::numeric>(e)) return 0;
    if (is_a<GiNaC::symbol>(e)) return is_vector_symbol(e) ? 1 : 0;
    if (is_a<GiNaC::matrix>(e)) {
        if (!is_vector_literal(e)) {
            const auto& m = ex_to<GiNaC::matrix>(e);
            throw type_error("a " + std::to_string(m.rows()) + "x" + std::to_string(m.cols()) +
                             " matrix is not a vector (vector literals are 3x1)");
        }
        for (unsigned i = 0; i < 3; ++i)
            if (kind(comp(e, i)))
                throw type_error("a component of a vector literal must be a scalar: " + message_text(e));
        return 1;
    }
    if (is_cross(e)) return 1;
    if (is_dot(e) || is_triple(e)) return 0;
    if (is_a<GiNaC::add>(e)) {
        int v = -1;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            const int k = kind(e.op(i));
            if (v >= 0 && k != v)
                throw type_error("sum of a vector and a scalar: " + message_text(e));
            v = k;
        }
        return v < 0 ? 0 : v;
    }
    if (is_a<GiNaC::mul>(e)) {
        int n = 0;
        for (std::size_t i = 0; i < e.nops(); ++i) n += kind(e.op(i));
        if (n > 1)
            throw type_error("product of two vectors (use dot or cross): " + message_text(e));
        return n;
    }
    if (is_a<GiNaC::power>(e)) {
        if (kind(e.op(0)) || kind(e.op(1)))
            throw type_error("power of a vector (use dot or norm): " + message_text(e));
        return 0;
    }
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (kind(e.op(i)))
            throw type_error("a vector cannot be the argument of " + message_text(e));
    return 0;
}

bool is_atom(const ex& e) { return is_vector_literal(e) || is_vector_symbol(e); }

// Splits a vector term into scalar factor and vector factor (v = s * rest).
std::pair<ex, ex> split_scalar(const ex& v) {
    if (!is_a<GiNaC::mul>(v)) return {1, v};
    ex s = 1, rest = 1;
    for (std::size_t i = 0; i < v.nops(); ++i) {
        if (kind(v.op(i))) rest = v.op(i);
        else s *= v.op(i);
    }
    return {s, rest};
}

ex comp(const ex& lit, unsigned i) { return ex_to<GiNaC::matrix>(lit)(i, 0); }

ex literal_cross(const ex& a, const ex& b) {
    return GiNaC::matrix(3, 1, GiNaC::lst{comp(a, 1) * comp(b, 2) - comp(a, 2) * comp(b, 1),
                                          comp(a, 2) * comp(b, 0) - comp(a, 0) * comp(b, 2),
                                          comp(a, 0) * comp(b, 1) - comp(a, 1) * comp(b, 0)});
}
ex literal_dot(const ex& a, const ex& b) {
    return comp(a, 0) * comp(b, 0) + comp(a, 1) * comp(b, 1) + comp(a, 2) * comp(b, 2);
}

}  // namespace detail

using namespace detail;

// -------------------------------------------------------------- eval rules
namespace {

// 0 or the literal [0, 0, 0] (the derivative of a constant literal, say).
bool zero_vector(const ex& a) {
    return a.is_zero() || (is_vector_literal(a) && a.op(0).is_zero() && a.op(1).is_zero() && a.op(2).is_zero());
}

void check_arg(const char* op, int pos, const ex& a) {
    if (a.is_zero()) return;
    if (!kind(a))
        throw type_error(std::string(op) + ": argument " + std::to_string(pos) + " (" + message_text(a) +
                         ") is a scalar, expected a vector");
}

ex vcross_eval(const ex& a, const ex& b) {
    check_arg("cross", 1, a);
    check_arg("cross", 2, b);
    if (zero_vector(a) || zero_vector(b)) return 0;
    if (is_a<GiNaC::add>(a)) {
        ex s = 0;
        for (std::size_t i = 0; i < a.nops(); ++i) s += vcross(a.op(i), b);
        return s;
    }
    if (is_a<GiNaC::add>(b)) {
        ex s = 0;
        for (std::size_t i = 0; i < b.nops(); ++i) s += vcross(a, b.op(i));
        return s;
    }
    const auto [sa, va] = split_scalar(a);
    const auto [sb, vb] = split_scalar(b);
    if (!(sa.is_equal(1) && sb.is_equal(1))) return sa * sb * vcross(va, vb);
    if (a.is_equal(b)) return 0;
    if (is_vector_literal(a) && is_vector_literal(b)) return literal_cross(a, b);
    if (is_vector_symbol(a) && is_vector_symbol(b) && name_of(b) < name_of(a)) return -vcross(b, a);
    return vcross(a, b).hold();
}

// As vcross_eval in shape (bilinear: sums and scalars taken out), but symmetric where the
// cross product is antisymmetric (a x a = 0, b x a = -a x b).
ex vdot_eval(const ex& a, const ex& b) {
    check_arg("dot", 1, a);
    check_arg("dot", 2, b);
    if (zero_vector(a) || zero_vector(b)) return 0;
    if (is_a<GiNaC::add>(a)) {
        ex s = 0;
        for (std::size_t i = 0; i < a.nops(); ++i) s += vdot(a.op(i), b);
        return s;
    }
    if (is_a<GiNaC::add>(b)) {
        ex s = 0;
        for (std::size_t i = 0; i < b.nops(); ++i) s += vdot(a, b.op(i));
        return s;
    }
    const auto [sa, va] = split_scalar(a);
    const auto [sb, vb] = split_scalar(b);
    if (!(sa.is_equal(1) && sb.is_equal(1))) return sa * sb * vdot(va, vb);
    if (is_vector_literal(a) && is_vector_literal(b)) return literal_dot(a, b);
    // a . (a x c) = a . (c x a) = 0
    if (is_cross(b) && (a.is_equal(b.op(0)) || a.is_equal(b.op(1)))) return 0;
    if (is_cross(a) && (b.is_equal(a.op(0)) || b.is_equal(a.op(1)))) return 0;
    const bool atom_a = is_atom(a), atom_b = is_atom(b);
    if (!atom_a && atom_b) return vdot(b, a);
    if (is_vector_symbol(a) && is_vector_symbol(b) && name_of(b) < name_of(a)) return vdot(b, a);
    return vdot(a, b).hold();
}

ex vtriple_eval(const ex& a, const ex& b, const ex& c) {
    check_arg("triple", 1, a);
    check_arg("triple", 2, b);
    check_arg("triple", 3, c);
    if (zero_vector(a) || zero_vector(b) || zero_vector(c)) return 0;
    const ex args[3] = {a, b, c};
    for (int k = 0; k < 3; ++k)
        if (is_a<GiNaC::add>(args[k])) {
            ex s = 0;
            for (std::size_t i = 0; i < args[k].nops(); ++i) {
                ex x[3] = {a, b, c};
                x[k] = args[k].op(i);
                s += vtriple(x[0], x[1], x[2]);
            }
            return s;
        }
    ex s = 1, v[3];
    for (int k = 0; k < 3; ++k) {
        const auto [sk, vk] = split_scalar(args[k]);
        s *= sk;
        v[k] = vk;
    }
    if (!s.is_equal(1)) return s * vtriple(v[0], v[1], v[2]);
    if (a.is_equal(b) || b.is_equal(c) || a.is_equal(c)) return 0;
    if (is_vector_literal(a) && is_vector_literal(b) && is_vector_literal(c))
        return literal_dot(a, literal_cross(b, c));
    if (is_vector_symbol(a) && is_vector_symbol(b) && is_vector_symbol(c)) {
        std::string n[3] = {name_of(a), name_of(b), name_of(c)};
        ex x[3] = {a, b, c};
        int sign = 1;
        for (int i = 0; i < 3; ++i)  // bubble sort, counting swaps
            for (int j = 0; j + 1 < 3 - i; ++j)
                if (n[j + 1] < n[j]) {
                    std::swap(n[j], n[j + 1]);
                    std::swap(x[j], x[j + 1]);
                    sign = -sign;
                }
        if (sign < 0) return -vtriple(x[0], x[1], x[2]);
        return vtriple(x[0], x[1], x[2]).hold();
    }
    return vtriple(a, b, c).hold();
}

ex vcross_deriv(const ex& a, const ex& b, const GiNaC::symbol& s) {
    return vcross(a.diff(s), b) + vcross(a, b.diff(s));
}
ex vdot_deriv(const ex& a, const ex& b, const GiNaC::symbol& s) {
    return vdot(a.diff(s), b) + vdot(a, b.diff(s));
}
ex vtriple_deriv(const ex& a, const ex& b, const ex& c, const GiNaC::symbol& s) {
    return vtriple(a.diff(s), b, c) + vtriple(a, b.diff(s), c) + vtriple(a, b, c.diff(s));
}

}  // namespace

// Commutative results: without it a GiNaC function takes the return type of its first
// argument, so dot([0, 0, 1], v0) was non-commutative like a matrix, and its product with
// a literal became an ncmul that kind() rejects -- depending on the argument order,
// which follows GiNaC's hashes (a failure in some runs only).
REGISTER_FUNCTION(vcross, eval_func(vcross_eval).expl_derivative_func(vcross_deriv).set_name("cross").set_return_type(
                              GiNaC::return_types::commutative))
REGISTER_FUNCTION(vdot, eval_func(vdot_eval).expl_derivative_func(vdot_deriv).set_name("dot").set_return_type(
                            GiNaC::return_types::commutative))
REGISTER_FUNCTION(vtriple, eval_func(vtriple_eval).expl_derivative_func(vtriple_deriv).set_name("triple").set_return_type(
                               GiNaC::return_types::commutative))

// ---------------------------------------------------------------- wrappers
ex cross(const ex& a, const ex& b) { return vcross(a, b); }
ex dot(const ex& a, const ex& b) { return vdot(a, b); }
ex triple(const ex& a, const ex& b, const ex& c) { return vtriple(a, b, c); }
ex norm(const ex& a) {
    if (!a.is_zero() && !kind(a))
        throw type_error("norm: the argument (" + message_text(a) + ") is a scalar, expected a vector");
    const ex d = vdot(a, a);
    // a literal's length with trigonometric components: |W [cos p, 0, sin p]| = W for positive W
    if (vector_symbols(d).empty() && (d.has(GiNaC::sin(GiNaC::wild())) || d.has(GiNaC::cos(GiNaC::wild()))))
        return GiNaC::sqrt(simplify_scalar(d));
    return GiNaC::sqrt(d);
}

bool is_vector(const ex& e) { return kind(e) == 1; }

std::vector<ex> vector_symbols(const ex& e) {
    std::map<std::string, ex> found;
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (is_vector_symbol(*it)) found.emplace(name_of(*it), *it);
    std::vector<ex> out;
    for (auto& [n, s] : found) out.push_back(s);
    return out;
}

// --------------------------------------------------------------------- d/dt
ex diff_t(const ex& e, const ex& t) {
    if (!is_a<GiNaC::symbol>(t))
        throw type_error("diff_t: the variable " + message_text(t) + " is not a symbol");
    kind(e);  // reject ill-formed input early
    const GiNaC::symbol& ts = ex_to<GiNaC::symbol>(t);
    ex result = e.diff(ts);  // partial derivative, vectors constant
    // plus the directional derivative along r' for every vector function r(t)
    const GiNaC::symbol eps("eps");
    for (const ex& r : vector_symbols(e)) {
        bool timed;
        {
            std::lock_guard<std::recursive_mutex> lock(reg_mutex());
            entry* en = find_entry(r);
            timed = en && en->timed && en->t.is_equal(t);
        }
        if (!timed) continue;
        const ex moved = e.subs(r == r + eps * derivative(r));
        result += moved.diff(eps).subs(eps == 0);
    }
    return result;
}

// ------------------------------------------------------------- substitution
namespace {

using exmap_less = std::map<ex, ex, GiNaC::ex_is_less>;

void check_map(const char* who, const exmap_less& m) {
    for (const auto& [k, v] : m) {
        if (!is_vector_symbol(k))
            throw type_error(std::string(who) + ": the key " + message_text(k) + " is not a vector symbol");
        if (!v.is_zero() && !kind(v))
            throw type_error(std::string(who) + ": the value for " + message_text(k) + " (" + message_text(v) +
                             ") is a scalar, expected a vector");
    }
}

// Component evaluation with the vectors of m replaced by their components:
// vec() for a vector expression (3 components), scal() for a scalar one.
// Nothing is expanded here.
struct components {
    const exmap_less& m;

    std::vector<ex> vec(const ex& e) {
        if (e.is_zero()) return {0, 0, 0};
        if (is_vector_literal(e)) return {scal(comp(e, 0)), scal(comp(e, 1)), scal(comp(e, 2))};
        if (is_vector_symbol(e)) {
            auto it = m.find(e);
            if (it == m.end())
                throw type_error("no value given for the vector " + name_of(e) + " (give it as " + name_of(e) + " = [x, y, z])");
            const ex& v = it->second;
            if (!vector_symbols(v).empty())
                throw type_error("subs_components: the value for " + name_of(e) +
                                 " must not contain abstract vectors");
            return vec(v);
        }
        if (is_a<GiNaC::add>(e)) {
            std::vector<ex> s{0, 0, 0};
            for (std::size_t i = 0; i < e.nops(); ++i) {
                auto c = vec(e.op(i));
                for (int k = 0; k < 3; ++k) s[k] += c[k];
            }
            return s;
        }
        if (is_a<GiNaC::mul>(e)) {
            const auto [s, v] = split_scalar(e);
            const ex sc = scal(s);
            auto c = vec(v);
            for (auto& x : c) x = sc * x;
            return c;
        }
        if (is_cross(e)) {
            auto a = vec(e.op(0)), b = vec(e.op(1));
            return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
        }
        throw type_error("subs_components: not a vector expression: " + message_text(e));
    }

    ex scal(const ex& e) {
        if (!has_vector_data(e)) return e;
        if (is_dot(e)) {
            auto a = vec(e.op(0)), b = vec(e.op(1));
            return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        }
        if (is_triple(e)) {
            auto a = vec(e.op(0)), b = vec(e.op(1)), c = vec(e.op(2));
            return a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
                   a[2] * (b[0] * c[1] - b[1] * c[0]);
        }
        struct mapper : GiNaC::map_function {
            components* self;
            explicit mapper(components* s) : self(s) {}
            ex operator()(const ex& x) override { return self->scal(x); }
        } f(this);
        return e.map(f);
    }

    static bool has_vector_data(const ex& e) {
        for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
            if (is_a<GiNaC::matrix>(*it) || is_vector_symbol(*it)) return true;
        return false;
    }
};

}  // namespace

ex subs_vectors(const ex& e, const exmap_less& m) {
    check_map("subs_vectors", m);
    kind(e);
    GiNaC::exmap gm(m.begin(), m.end());
    return e.subs(gm, GiNaC::subs_options::no_pattern);
}

ex subs_components(const ex& e, const exmap_less& m) {
    check_map("subs_components", m);
    components c{m};
    if (kind(e)) {
        auto v = c.vec(e);
        return GiNaC::matrix(3, 1, GiNaC::lst{GiNaC::expand(v[0]), GiNaC::expand(v[1]), GiNaC::expand(v[2])});
    }
    return GiNaC::expand(c.scal(e));
}

// ------------------------------------------------------------------ equality
namespace {

// True when e has a literal or a non-integer power (|w| = sqrt(w.w)).
bool has_literal_or_root(const ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
        if (is_a<GiNaC::matrix>(*it)) return true;
        if (is_a<GiNaC::power>(*it) &&
            !(is_a<GiNaC::numeric>(it->op(1)) && ex_to<GiNaC::numeric>(it->op(1)).is_integer()))
            return true;
    }
    return false;
}

// The components of d (vector or scalar) with fresh symbols for the vectors.
// Without literals, d is built from rotation-equivariant operations (sums,
// scalar factors, cross, dot, triple), so d = 0 for all vectors iff d = 0 when
// the first vector lies along e1 and the second in the e1-e2 plane (rotate any
// configuration there): three fewer variables. Roots are excluded because
// sqrt(x^2) is |x|, not x, which normal() would not cancel.
std::vector<ex> symbolic_components(const ex& d) {
    exmap_less m;
    const bool normal_position = !has_literal_or_root(d);
    int k = 0;
    for (const ex& v : vector_symbols(d)) {
        const std::string n = name_of(v);
        const ex x = GiNaC::realsymbol(n + "_1"), y = GiNaC::realsymbol(n + "_2"), z = GiNaC::realsymbol(n + "_3");
        if (normal_position && k == 0) m[v] = GiNaC::matrix(3, 1, GiNaC::lst{x, 0, 0});
        else if (normal_position && k == 1) m[v] = GiNaC::matrix(3, 1, GiNaC::lst{x, y, 0});
        else m[v] = GiNaC::matrix(3, 1, GiNaC::lst{x, y, z});
        ++k;
    }
    const ex c = subs_components(d, m);
    if (is_a<GiNaC::matrix>(c)) return {comp(c, 0), comp(c, 1), comp(c, 2)};
    return {c};
}

// A polynomial in symbols with rational (or complex rational) coefficients, whose
// expanded form is canonical: nonzero when it is not 0. Radicals, constants
// such as pi and functions are excluded: sqrt(12) - 2 sqrt(3) expands to itself.
bool is_polynomial_in_symbols(const ex& e) {
    GiNaC::lst syms;
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
        if (is_a<GiNaC::symbol>(*it)) syms.append(*it);
        else if (is_a<GiNaC::constant>(*it) || is_a<GiNaC::function>(*it)) return false;
        else if (is_a<GiNaC::numeric>(*it) && !ex_to<GiNaC::numeric>(*it).is_cinteger() &&
                 !ex_to<GiNaC::numeric>(*it).is_crational())
            return false;
        else if (is_a<GiNaC::power>(*it) && !(is_a<GiNaC::numeric>(it->op(1)) &&
                                               ex_to<GiNaC::numeric>(it->op(1)).is_integer()))
            return false;
    }
    return e.is_polynomial(syms);
}

// Fast rejection: random integer components for the vectors and random
// integers for the scalar symbols. Returns true only when some component is
// then a non-zero rational number, which proves d != 0; anything else (a pole,
// a transcendental value, zero) is inconclusive.
bool provably_nonzero_at_random_point(const ex& d) {
    std::mt19937 gen(20240611);
    std::uniform_int_distribution<int> dist(-997, 997);
    exmap_less m;
    for (const ex& v : vector_symbols(d)) m[v] = GiNaC::matrix(3, 1, GiNaC::lst{dist(gen), dist(gen), dist(gen)});
    try {
        components cm{m};
        std::vector<ex> comps = kind(d) ? cm.vec(d) : std::vector<ex>{cm.scal(d)};
        GiNaC::exmap vals;
        for (const ex& c : comps)
            for (auto it = c.preorder_begin(); it != c.preorder_end(); ++it)
                if (is_a<GiNaC::symbol>(*it) && !vals.count(*it)) vals[*it] = dist(gen);
        for (const ex& c : comps) {
            const ex v = c.subs(vals, GiNaC::subs_options::no_pattern);
            if (is_a<GiNaC::numeric>(v) && ex_to<GiNaC::numeric>(v).is_rational() && !v.is_zero()) return true;
        }
    } catch (const std::exception&) {
        // division by zero at this point: inconclusive
    }
    return false;
}

}  // namespace

bool equal(const ex& a, const ex& b) {
    const int ka = kind(a), kb = kind(b);
    if (ka != kb && !(a.is_zero() || b.is_zero()))
        throw type_error("equal: comparing a vector with a scalar: " + message_text(a) + " and " + message_text(b));
    const ex d = a - b;
    if (d.is_zero()) return true;
    if (provably_nonzero_at_random_point(d)) return false;
    if (canonical(d).is_zero()) return true;  // canonical() only applies identities
    const std::vector<ex> comps = symbolic_components(d);
    // ground truth: every component must vanish identically
    for (const ex& c : comps) {
        if (c.is_zero()) continue;  // subs_components has expanded c
        if (is_polynomial_in_symbols(c)) return false;  // an expanded non-zero polynomial
        if (!is_zero_scalar(c)) return false;
    }
    return true;
}

zero_decision decide_zero_vector(const ex& d) {
    if (equal(d, 0)) {
        zero_decision z;
        z.is_zero = truth::yes;
        return z;
    }
    // by components, each vector symbol v as [v_1, v_2, v_3]: a witness is a point of the components
    exmap_less m;
    for (const ex& v : vector_symbols(d))
        m[v] = vector_literal(GiNaC::realsymbol(name_of(v) + "_1"), GiNaC::realsymbol(name_of(v) + "_2"),
                              GiNaC::realsymbol(name_of(v) + "_3"));
    const ex c = subs_components(d, m);
    if (!is_a<GiNaC::matrix>(c)) return decide_zero(c);
    zero_decision out;
    out.is_zero = truth::yes;
    for (std::size_t i = 0; i < c.nops(); ++i) {
        const zero_decision z = decide_zero(c.op(i));
        if (z.is_zero == truth::no) return z;
        if (z.is_zero == truth::unknown) out = z;
    }
    return out;
}

}  // namespace symrep
