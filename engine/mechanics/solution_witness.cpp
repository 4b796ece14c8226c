// symrep/mechanics/solution_witness.cpp -- the residual of a candidate solution at one point
// (solution_witness.h; issue 27).
#include "symrep/mechanics/solution_witness.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include "symrep/core/error.h"
#include "symrep/numeric/quadrature.h"
#include "symrep/vector/vector.h"

namespace symrep::mechanics {

using GiNaC::ex;
using GiNaC::numeric;

GiNaC::numeric witness_rational(const std::string& name, int salt) {
    const std::size_t h = std::hash<std::string>{}(name) + std::size_t(salt) * 7919;
    return numeric(long(1100 + h % 1800), 1000);  // in [1.1, 2.9]
}

GiNaC::numeric witness_time() { return numeric(7, 10); }

namespace {

using vmap = std::map<ex, ex, GiNaC::ex_is_less>;

// The point does not decide (a pole, a complex value, a refused quadrature).
struct undecided {};

struct valued {
    numeric value, size;  // the value and the magnitude M (solution_witness.h)
};

numeric real_number(const ex& e) {
    const ex v = GiNaC::evalf(e);
    if (!GiNaC::is_a<numeric>(v) || !GiNaC::ex_to<numeric>(v).is_real()) throw undecided{};
    return GiNaC::ex_to<numeric>(v);
}

// The value and magnitude of e, a closed form in numbers (integral objects in their bound
// variables), at GiNaC::Digits (the caller's 40). `integrals` is set when one is met.
struct evaluator {
    bool integrals = false;
    GiNaC::exmap floats;  // the symbols standing for floating-point numbers -> the numbers
    std::map<ex, valued, GiNaC::ex_is_less> seen;

    valued operator()(const ex& e) {
        if (GiNaC::is_a<numeric>(e)) {
            const numeric x = real_number(e);
            return {x, GiNaC::abs(x)};
        }
        if (GiNaC::is_a<GiNaC::symbol>(e) && floats.count(e)) {
            const numeric x = GiNaC::ex_to<numeric>(floats.at(e));
            return {x, GiNaC::abs(x)};
        }
        if (GiNaC::is_a<GiNaC::constant>(e)) {
            const numeric x = real_number(e);
            return {x, GiNaC::abs(x)};
        }
        if (GiNaC::is_a<GiNaC::add>(e)) {
            valued out{0, 0};
            for (std::size_t i = 0; i < e.nops(); ++i) {
                const valued x = (*this)(e.op(i));
                out.value += x.value;
                out.size += x.size;
            }
            return out;
        }
        if (GiNaC::is_a<GiNaC::mul>(e)) {
            valued out{1, 1};
            for (std::size_t i = 0; i < e.nops(); ++i) {
                const valued x = (*this)(e.op(i));
                out.value *= x.value;
                out.size *= x.size;
            }
            return out;
        }
        if (const auto it = seen.find(e); it != seen.end()) return it->second;
        valued out;
        if (GiNaC::is_a<GiNaC::power>(e)) {
            const valued a = (*this)(e.op(0));
            if (GiNaC::is_a<numeric>(e.op(1)) && GiNaC::ex_to<numeric>(e.op(1)).is_pos_integer()) {
                const numeric p = GiNaC::ex_to<numeric>(e.op(1));
                out = {GiNaC::pow(a.value, p), GiNaC::pow(a.size, p)};
            } else {
                const valued p = (*this)(e.op(1));
                if (a.value.is_zero()) throw undecided{};  // a pole (or 0^p: not decided here)
                const numeric v = real_number(GiNaC::pow(a.value, p.value));
                // relative error |p| M(a)/|a| from the base, |log a| M(p) from the exponent
                out = {v, GiNaC::abs(v) * (1 + GiNaC::abs(p.value) * a.size / GiNaC::abs(a.value) +
                                           (p.size.is_zero() ? numeric(0) : GiNaC::abs(real_number(GiNaC::log(GiNaC::abs(a.value)))) * p.size))};
            }
        } else if (GiNaC::is_a<GiNaC::function>(e) && e.nops() == 1) {
            const valued a = (*this)(e.op(0));
            const GiNaC::symbol y;
            ex f = e;
            f.let_op(0) = y;
            const numeric v = real_number(f.subs(y == a.value));
            const numeric d = real_number(f.diff(y).subs(y == a.value));
            out = {v, GiNaC::abs(v) + GiNaC::abs(d) * a.size};
        } else if (GiNaC::is_a<GiNaC::integral>(e)) {
            out = integral(e);
        } else {
            throw undecided{};  // a symbol left, a function of several arguments, ...
        }
        seen.emplace(e, out);
        return out;
    }

    // int_a^b g(x) dx with numeric limits: by quadrature, its magnitude int |g| (the scale of
    // the quadrature's error) plus the limits' share.
    valued integral(const ex& e) {
        integrals = true;
        const ex x = e.op(0), g = e.op(3);
        const valued a = (*this)(e.op(1)), b = (*this)(e.op(2));
        num::integral_value q;
        try {
            q = num::evaluate_integral(x, a.value.to_double(), b.value.to_double(), g);
        } catch (const std::exception&) {
            throw undecided{};
        }
        // nested integrals too (one system, numeric/quadrature_chain.h); an estimate above 1e-8 of
        // the scale max(int |g|, |value|) decides nothing
        const double value = q.value, l1 = q.scale;
        if (!std::isfinite(value) || !std::isfinite(l1) || !(q.error <= 1e-8 * l1)) throw undecided{};
        const numeric v(value);
        return {v, GiNaC::abs(v) + numeric(l1) + a.size + b.size};
    }
};

// The symbols of e that get a value: not t, not a vector symbol, not a bound variable.
void point_symbols(const ex& e, const ex& t, std::set<ex, GiNaC::ex_is_less>& bound, GiNaC::exmap& point) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::integral>(*it)) bound.insert(it->op(0));
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it) && !it->is_equal(t) && !is_vector_symbol(*it) && !bound.count(*it) &&
            !point.count(*it))
            point[*it] = witness_rational(GiNaC::ex_to<GiNaC::symbol>(*it).get_name(), 0);
}

// The components of a vector (or the scalar) as a list of 1 or 3.
std::vector<ex> components(const ex& e, bool is_vector) {
    if (!is_vector) return {e};
    if (!GiNaC::is_a<GiNaC::matrix>(e)) {
        if (e.is_zero()) return {0, 0, 0};
        throw undecided{};
    }
    return {e.op(0), e.op(1), e.op(2)};
}

// Every floating-point number of e as a symbol (kept in `floats`): GiNaC adds and multiplies
// numbers as soon as they meet, so that with the point put in, a sum of floats that cancels
// would be one rounded number with nothing left to measure its terms by.
ex floats_as_symbols(const ex& e, GiNaC::exmap& floats, std::map<ex, ex, GiNaC::ex_is_less>& symbol_of) {
    struct replace : GiNaC::map_function {
        GiNaC::exmap& floats;
        std::map<ex, ex, GiNaC::ex_is_less>& symbol_of;
        replace(GiNaC::exmap& f, std::map<ex, ex, GiNaC::ex_is_less>& s) : floats(f), symbol_of(s) {}
        ex operator()(const ex& x) override {
            if (GiNaC::is_a<numeric>(x) && !GiNaC::ex_to<numeric>(x).is_crational()) {
                auto it = symbol_of.find(x);
                if (it != symbol_of.end()) return it->second;
                const ex f = GiNaC::realsymbol("float" + std::to_string(symbol_of.size()));
                symbol_of[x] = f;
                floats[f] = x;
                return f;
            }
            return x.map(*this);
        }
    } r(floats, symbol_of);
    return r(e);
}

std::string problem_text(const cauchy_problem& P) {
    std::string s = "ode(" + to_string(P.expression) + " = 0";
    for (std::size_t m = 0; m < P.initial.size(); ++m)
        s += ", " + P.unknown_name(m) + "(0) = " + to_string(P.initial[m]);
    s += ")";
    if (s.size() > 400) s = s.substr(0, 400) + " ...";
    return s;
}

}  // namespace

witness_report witness(const cauchy_problem& P, const ex& s) {
    witness_report out;
    const long saved = GiNaC::Digits;
    struct restore {
        long d;
        ~restore() { GiNaC::Digits = d; }
    } keep{saved};
    const numeric float_tolerance(rounding_tolerance());  // at the caller's Digits, not at 40
    const bool floats = has_float(P.expression) || has_float(s) ||
                        std::any_of(P.initial.begin(), P.initial.end(), [](const ex& x) { return has_float(x); });
    try {
        const std::size_t M = P.order();
        const ex& t = P.t;
        GiNaC::exmap float_values;
        std::map<ex, ex, GiNaC::ex_is_less> symbol_of;
        const ex S = floats ? floats_as_symbols(s, float_values, symbol_of) : s;
        const ex E = floats ? floats_as_symbols(P.expression, float_values, symbol_of) : P.expression;
        std::vector<ex> X0;
        for (const ex& x : P.initial) X0.push_back(floats ? floats_as_symbols(x, float_values, symbol_of) : x);
        const GiNaC::symbol& ts = GiNaC::ex_to<GiNaC::symbol>(t);
        // the point: vector symbols (not the unknowns) by components, then the scalars
        vmap comps;
        GiNaC::exmap point;
        std::set<ex, GiNaC::ex_is_less> bound;
        if (P.is_vector) {
            std::set<ex, GiNaC::ex_is_less> unknowns(P.unknowns.begin(), P.unknowns.end());
            std::vector<ex> parts{S, E};
            parts.insert(parts.end(), X0.begin(), X0.end());
            for (const ex& part : parts)
                for (const ex& v : vector_symbols(part)) {
                    if (unknowns.count(v) || comps.count(v)) continue;
                    if (!diff_t(v, t).is_zero()) return out;  // a vector function w(t): no values for it here
                    const std::string n = to_string(v);
                    comps[v] = vector_literal(witness_rational(n, 1), -witness_rational(n, 2), witness_rational(n, 3));
                }
        }
        for (const ex& part : {S, E}) point_symbols(part, t, bound, point);
        for (const ex& x : X0) point_symbols(x, t, bound, point);
        for (const auto& [f, x] : float_values) point.erase(f);
        for (const ex& u : P.unknowns) point.erase(u);
        auto at = [&](const ex& e) {
            return (P.is_vector ? subs_components(e, comps) : e).subs(point, GiNaC::subs_options::no_pattern);
        };
        // s, s', ..., s^(M) by components (numbers but t)
        std::vector<std::vector<ex>> d{components(at(S), P.is_vector)};
        for (std::size_t m = 1; m <= M; ++m) {
            std::vector<ex> next;
            for (const ex& c : d.back()) next.push_back(c.diff(ts));
            d.push_back(std::move(next));
        }
        // the residual
        ex R;
        if (P.is_vector) {
            vmap all = comps;
            for (std::size_t m = 0; m <= M; ++m) all[P.unknowns[m]] = vector_literal(d[m][0], d[m][1], d[m][2]);
            R = subs_components(E, all).subs(point, GiNaC::subs_options::no_pattern);
        } else {
            GiNaC::exmap all = point;
            for (std::size_t m = 0; m <= M; ++m) all[P.unknowns[m]] = d[m][0];
            R = E.subs(all, GiNaC::subs_options::no_pattern);
        }
        // what is tested: the residual's components at t = 7/10, the initial differences at 0
        std::vector<std::pair<std::string, ex>> tests;
        const std::vector<ex> rc = components(R, P.is_vector);
        for (std::size_t i = 0; i < rc.size(); ++i)
            tests.push_back({"the residual" + (P.is_vector ? " (component " + std::to_string(i + 1) + ")" : std::string()),
                             rc[i].subs(t == witness_time())});
        for (std::size_t m = 0; m < M; ++m) {
            const std::vector<ex> X = components(at(X0[m]), P.is_vector);
            for (std::size_t i = 0; i < X.size(); ++i)
                tests.push_back({"the initial value " + P.unknown_name(m) + "(0)" +
                                     (P.is_vector ? " (component " + std::to_string(i + 1) + ")" : std::string()),
                                 d[m][i].subs(t == 0) - X[i]});
        }
        GiNaC::Digits = 40;
        evaluator eval;
        eval.floats = float_values;
        const numeric exact_tolerance = GiNaC::pow(numeric(10), numeric(-20));
        std::vector<std::pair<std::size_t, valued>> values;  // (test, value) of those decided
        bool integrals = false;
        numeric largest = 0;
        for (std::size_t i = 0; i < tests.size(); ++i) {
            try {
                values.push_back({i, eval(tests[i].second)});
            } catch (const undecided&) {
                continue;  // this one is not decided at the point; the others still are
            } catch (const std::exception&) {
                continue;  // a pole (division by 0), a function without a derivative
            }
            integrals = integrals || num::has_integral(tests[i].second);
            largest = std::max(largest, values.back().second.size);
        }
        // With floats (rounded once at the end of the derivation) or integral objects (doubles), a
        // component that cancels to 0 keeps the rounding of terms that the rounding itself has
        // made small: the scale is then the largest magnitude of all (check()'s rounding ratio
        // takes the largest coefficient of all components the same way).
        for (const auto& [i, v] : values) {
            const numeric scale = floats || integrals ? largest : v.size;
            const numeric tolerance = integrals ? numeric(1, 1000000)
                                      : floats  ? float_tolerance
                                                : exact_tolerance;
            if (GiNaC::abs(v.value) > tolerance * scale) {
                out.seen_nonzero = true;
                out.what = tests[i].first;
                out.value = v.value.to_double();
                out.size = v.size.to_double();
                return out;
            }
        }
    } catch (const undecided&) {
        return out;
    } catch (const std::exception&) {
        // a pole at t = 0 or at the point, a substitution that fails: no witness
        return out;
    }
    return out;
}

void require_witness(const cauchy_problem& P, const ex& s) {
    const witness_report w = witness(P, s);
    if (!w.seen_nonzero) return;
    std::ostringstream os;
    os.precision(6);
    os << "internal error: the solution that solve derived for " << problem_text(P)
       << " does not solve it: " << w.what << " is " << w.value << " at t = " << (w.what.find("(0)") != std::string::npos ? "0" : "7/10")
       << " (every other symbol a number fixed by its name), not 0 (the size of its terms is " << w.size
       << "); the result is withheld. This is a defect of symrep: please report the problem";
    throw internal_error(os.str());
}

}  // namespace symrep::mechanics
