// symrep/lang/values.cpp -- numeric values for symbols (see values.h); moved from
// builtins_mechanics.cpp, shared by eval, verify, plot, trajectory and hodograph.
#include "lang/values.h"

#include <set>

#include "numeric/reference.h"

#include "scalar/scalar.h"
#include "output/printer.h"
#include "vector/vector.h"
#include "lang/print_value.h"

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

// Where the values make e singular (w = 0 in sin(|w| t)/|w|), its limit: each
// zero value x becomes lambda x' (a vector: x' a fixed generic direction; a scalar:
// lambda^2, so that sqrt(k) is lambda) and the
// lambda^0 term of the series in lambda is taken (the exact limit lambda -> 0).
ex put_values_limit(const ex& e, const data_values& d) {
    try {
        return put_values(e, d);
    } catch (const std::exception&) {
    }
    const GiNaC::possymbol lambda("lambda");
    data_values dl = d;
    bool any = false;
    for (auto& [k, x] : dl.vectors)
        if (GiNaC::normal(x.op(0)).is_zero() && GiNaC::normal(x.op(1)).is_zero() && GiNaC::normal(x.op(2)).is_zero()) {
            x = vector_literal(lambda * 3, lambda * 5, lambda * 7) / 7;
            any = true;
        }
    // a scalar as lambda^2: the forms of a spring constant k = 0 have sqrt(k) (sqrt(k/m) t),
    // a series in lambda then, not in sqrt(lambda) (which GiNaC's series does not expand)
    for (auto& [k, x] : dl.scalars)
        if (GiNaC::normal(x).is_zero()) { x = GiNaC::pow(lambda, 2); any = true; }
    if (!any) return put_values(e, d);  // rethrows the original error
    const ex c = put_values(e, dl);
    auto lim = [&](const ex& x) {
        const ex s = GiNaC::series_to_poly(GiNaC::normal(x).series(lambda == 0, 1));
        return subs_checked(s, lambda == 0);
    };
    if (GiNaC::is_a<GiNaC::matrix>(c)) {
        GiNaC::matrix m = GiNaC::ex_to<GiNaC::matrix>(c);
        for (unsigned i = 0; i < m.rows(); ++i) m(i, 0) = lim(m(i, 0));
        return m;
    }
    return lim(c);
}

std::vector<ex> components(const ex& c) {
    if (!GiNaC::is_a<GiNaC::matrix>(c)) return {c};
    std::vector<ex> out;
    for (unsigned i = 0; i < c.nops(); ++i) out.push_back(c.op(i));
    return out;
}

data_values exact_values(data_values d) {
    for (auto& [k, x] : d.vectors) x = num::exact_floats_of(x);
    for (auto& [k, x] : d.scalars) x = num::exact_floats_of(x);
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
