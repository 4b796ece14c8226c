// symrep/lang/values.cpp -- numeric values for symbols (see values.h); moved from
// builtins_mechanics.cpp, shared by eval, verify, plot, trajectory and hodograph.
#include "symrep/lang/values.h"

#include <set>

#include "symrep/numeric/reference.h"
#include "symrep/scalar/floats.h"
#include "symrep/scalar/limit.h"

#include "symrep/scalar/scalar.h"
#include "symrep/output/printer.h"
#include "symrep/vector/vector.h"
#include "symrep/lang/print_value.h"

namespace symrep::lang {

using output::print_ex;

using GiNaC::ex;

// ---------------------------------------------------------------- values
// [w = [..], phi = 0.85, w0 = sqrt(9.81/67), ...]: vector and scalar values; a
// value may use the others (w = W [cos(phi), 0, sin(phi)] with phi given).
data_values read_values(const value& v, const builtin& b, std::size_t argno) {
    std::vector<ex> rels;
    auto take = [&](const value& x) {
        if (!x.is_ex() || !GiNaC::is_a<GiNaC::relational>(x.as_ex()))
            throw type_error(b.name + ": argument " + std::to_string(argno + 1) +
                             " must list values as name = value, found " + print_value(x));
        rels.push_back(x.as_ex());
    };
    if (v.is_list()) for (const value& x : v.as_list()) take(x);
    else take(v);
    data_values d;
    std::set<std::string> seen;
    for (const ex& r : rels) {
        const ex lhs = r.lhs();
        // a name given twice is a mistake (the last one would win silently)
        if ((is_vector_symbol(lhs) || GiNaC::is_a<GiNaC::symbol>(lhs)) && !seen.insert(print_ex(lhs)).second)
            throw type_error(b.name + ": " + print_ex(lhs) + " is given a value twice in argument " +
                             std::to_string(argno + 1));
        if (is_vector_symbol(lhs)) {
            if (!is_vector_literal(r.rhs()) && !r.rhs().is_zero())
                throw type_error(b.name + ": the value of the vector " + print_ex(lhs) +
                                 " must be a vector [x, y, z], not " + print_ex(r.rhs()));
            d.vectors[lhs] = r.rhs().is_zero() ? vector_literal(0, 0, 0) : r.rhs();
        } else if (GiNaC::is_a<GiNaC::symbol>(lhs)) {
            if (is_vector_literal(r.rhs()))
                throw type_error(b.name + ": " + print_ex(lhs) + " is a scalar (declare it with 'vector " +
                                 print_ex(lhs) + "' to give it a vector value)");
            d.scalars[lhs] = r.rhs();
        } else {
            throw type_error(b.name + ": the left side of " + print_ex(r) + " must be a name");
        }
    }
    // values that use other values: substitute until nothing changes
    for (int pass = 0; pass < 16; ++pass) {
        bool changed = false;
        for (auto& [k, x] : d.scalars) {
            const ex y = subs_checked(x, d.scalars);
            if (!y.is_equal(x)) { x = y; changed = true; }
        }
        for (auto& [k, x] : d.vectors) {
            const ex y = subs_checked(x, d.scalars);
            if (!y.is_equal(x)) { x = y; changed = true; }
        }
        if (!changed) break;
    }
    // a value that still uses a name with a value refers to itself through the others
    // (a = 2*b, b = a): refused by name, not answered with whatever the passes left
    for (const auto& [k, x] : d.scalars)
        for (const auto& [k2, x2] : d.scalars)
            if (x.has(k2))
                throw type_error(b.name + ": the values are cyclic: the value of " + print_ex(k) + " still uses " +
                                 print_ex(k2) + " (a value cannot refer to itself, directly or through other values)");
    for (const auto& [k, x] : d.vectors)
        for (const auto& [k2, x2] : d.scalars)
            if (x.has(k2))
                throw type_error(b.name + ": the values are cyclic: the value of " + print_ex(k) + " still uses " +
                                 print_ex(k2) + " (a value cannot refer to itself, directly or through other values)");
    return d;
}

// e with every value put in: vectors by components, then scalars. The result is
// a 3x1 matrix for a vector e.
ex put_values(const ex& e, const data_values& d) {
    ex c = vector_symbols(e).empty() ? e : subs_components(e, d.vectors);
    return subs_checked(c, d.scalars);
}

std::string vanishing_denominator(const ex& e, const data_values& d) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
        if (!GiNaC::is_a<GiNaC::power>(*it)) continue;
        const ex& k = it->op(1);
        if (!GiNaC::is_a<GiNaC::numeric>(k) || !GiNaC::ex_to<GiNaC::numeric>(k).is_negative()) continue;
        try {
            if (GiNaC::normal(put_values(it->op(0), d)).is_zero()) return print_ex(it->op(0));
        } catch (const std::exception&) {
        }
    }
    return "";
}

// Where the values make e divide by zero (w = 0 in sin(|w| t)/|w|, c = 2, k = 1 in
// sin(sqrt(4 k - c^2) t/2)/sqrt(4 k - c^2), a resonance), its limit as every value
// (each scalar, each component of a vector) approaches the one given
// (scalar/limit.h: along lines through the point from both sides, accepted where
// they agree; `held`, the time of eval, stays as given); where that limit is not
// established, domain_error naming the denominator and why.
ex put_values_limit(const ex& e, const data_values& d, const ex& held) {
    try {
        return put_values(e, d);
    } catch (const std::exception& x) {
        if (!is_division_by_zero(x)) throw;
    }
    std::vector<ex> scalar_keys, vector_keys;
    for (const auto& [k, x] : d.scalars)
        if (!k.is_equal(held)) scalar_keys.push_back(k);
    for (const auto& [k, x] : d.vectors) vector_keys.push_back(k);
    const near_point near = [&](const std::vector<ex>& off) {
        data_values m = d;
        std::size_t i = 0;
        for (const ex& k : scalar_keys) m.scalars[k] = d.scalars.at(k) + off[i++];
        for (const ex& k : vector_keys) {
            const ex& x = d.vectors.at(k);
            m.vectors[k] = vector_literal(x.op(0) + off[i], x.op(1) + off[i + 1], x.op(2) + off[i + 2]);
            i += 3;
        }
        return put_values(e, m);
    };
    try {
        return limit_at_point(scalar_keys.size() + 3 * vector_keys.size(), near);
    } catch (const domain_error& x) {
        const std::string den = vanishing_denominator(e, d);
        throw domain_error(std::string(singular_values_message) +
                           (den.empty() ? std::string(" (a division by zero)") : " (its denominator " + den + " is 0 there)") +
                           " and " + x.what());
    }
}

std::vector<ex> components(const ex& c) {
    if (!GiNaC::is_a<GiNaC::matrix>(c)) return {c};
    std::vector<ex> out;
    for (unsigned i = 0; i < c.nops(); ++i) out.push_back(c.op(i));
    return out;
}

data_values exact_values(data_values d) {
    // a float is worth the decimal it prints as (scalar/floats.h, as == takes it): 0.7 -> 7/10.
    // Its binary value instead (0.7 at 40 digits has a 2^133 denominator) made verify's system
    // carry integers of 300 digits (through sqrt and |x|^-3) that overflow in doubles
    for (auto& [k, x] : d.vectors) x = floats_as_decimals(x);
    for (auto& [k, x] : d.scalars) x = floats_as_decimals(x);
    return d;
}

double to_double(const ex& x, const builtin& b, const std::string& what) {
    if (GiNaC::is_a<GiNaC::numeric>(x) && GiNaC::ex_to<GiNaC::numeric>(x).is_real())
        return GiNaC::ex_to<GiNaC::numeric>(x).to_double();
    // Precision-controlled (numeric/reference.h): a fixed-precision evalf loses
    // digits where x cancels or has a long phase.
    try {
        return num::accurate_double(x);
    } catch (const domain_error& e) {
        const std::string m = e.what();
        if (m.rfind("integral:", 0) == 0 || m.rfind("cannot evaluate to double precision", 0) == 0)
            throw domain_error(b.name + ": " + m);
        throw type_error(b.name + ": " + what + " does not evaluate to a real number: " +
                         message_text(GiNaC::evalf(x)) + " (give every symbol a value)");
    }
}

first_order_system first_order(const mechanics::cauchy_problem& P, const data_values& d, const builtin& b) {
    const std::size_t M = P.order(), dim = P.is_vector ? 3 : 1;
    first_order_system sys;
    std::vector<ex> accel;
    for (std::size_t i = 0; i < M * dim; ++i) sys.state.push_back(GiNaC::symbol("y" + std::to_string(i)));
    for (std::size_t i = 0; i < dim; ++i) accel.push_back(GiNaC::symbol("a" + std::to_string(i)));
    data_values dv = d;
    if (P.is_vector) {
        for (std::size_t m = 0; m < M; ++m)
            dv.vectors[P.unknowns[m]] = vector_literal(sys.state[3 * m], sys.state[3 * m + 1], sys.state[3 * m + 2]);
        dv.vectors[P.unknowns[M]] = vector_literal(accel[0], accel[1], accel[2]);
    } else {
        for (std::size_t m = 0; m < M; ++m) dv.scalars[P.unknowns[m]] = sys.state[m];
        dv.scalars[P.unknowns[M]] = accel[0];
    }
    const ex E = put_values(P.expression, dv);
    GiNaC::lst eqs, unk;
    for (const ex& x : components(E)) eqs.append(GiNaC::expand(x) == 0);
    for (const ex& x : accel) unk.append(x);
    const ex sol = GiNaC::lsolve(eqs, unk);
    if (sol.nops() != dim)
        throw domain_error(b.name + ": the equation cannot be solved for " + P.unknown_name(M) +
                           " at these values (its leading coefficient is singular)");
    for (std::size_t i = dim; i < M * dim; ++i) sys.rhs.push_back(sys.state[i]);
    // expanded: lsolve's form of a solution depends on GiNaC's term order, which varies from run
    // to run (hash seeds); the expanded sum does not (compile() orders its terms), so the
    // rounding of the integration, and what verify prints, is the same in every run
    for (std::size_t i = 0; i < dim; ++i) sys.rhs.push_back(GiNaC::expand(sol.op(i).rhs()));
    for (std::size_t m = 0; m < M; ++m) {
        const ex x0 = P.is_vector && P.initial[m].is_zero() ? vector_literal(0, 0, 0) : P.initial[m];
        for (const ex& x : components(put_values_limit(x0, d)))
            sys.initial.push_back(to_double(x, b, "the initial value of " + P.unknown_name(m)));
    }
    return sys;
}

}  // namespace symrep::lang
