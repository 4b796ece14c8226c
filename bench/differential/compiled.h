// bench/differential/compiled.h -- the differential family of the compiled paths (issue 27.6,
// 27.1.3): the closed forms of the constant-w family (harness.h) evaluated as the library
// offers them to C++ (docs/numeric.md): the values put in exactly (lang::exact_values,
// put_values_limit, as the Python `compile` does), then num::compile's double program
// (eval_many) and num::stable_function (eval, eval_many with its check tolerance), at several
// times, against the same Odeint reference as the constant-w family.
#pragma once

#include "harness.h"
#include "lang/values.h"
#include "numeric/evaluator.h"
#include "numeric/stable_evaluator.h"

namespace symrep::differential {

/// Each case gives three outcomes at four times in (0, T]:
/// - "compiled: stable eval": stable_function::eval, tolerance 1e-9 relative to the norm of
///   r (its documented accuracy is 1e-14; the reference's ~1e-11 of the data's scale);
/// - "compiled: stable eval_many": eval_many(check_tol = 1e-6), each output proved to 1e-6
///   of itself: tolerance 2e-6 relative to the norm;
/// - "compiled: plain eval_many": the bare double program may be wrong where the closed form
///   cancels (documented), but then its running error bound (stable_function::eval_binary64)
///   must flag the point (bound above 1e-6 of the value); a wrong value that the bound does
///   not flag is a disagreement (its difference is reported), a flagged one counts as agreed.
/// Magnitudes as the constant-w family: data 10^[-250, 250], |w| 10^[-300, 0.5] or 0.
inline std::vector<outcome> compiled_family(unsigned seed, int n) {
    std::mt19937 gen(seed);
    std::vector<outcome> out;
    runner R;
    R.run("vector w, g, r0, v0\npositive w0");
    std::string solved_for;
    const GiNaC::ex t = R.s.symbol("t");
    lang::builtin b;
    b.name = "compile";
    for (int i = 0; i < n; ++i) {
        const constant_w_case c = draw_constant_w(gen);
        const constant_w_data data = draw_constant_w_data(gen);
        const double S = data.S, w0 = data.w0, T = data.T;
        const vec3 &w = data.w, &g0 = data.g0, &r00 = data.r00, &v00 = data.v00;
        const std::string values = data.values(c.foucault);
        const std::vector<double> at{T / 1000, T / 7, T / 2, T};
        std::vector<std::vector<double>> refs;
        outcome st, many, plain;
        const bool referenced = reference(st, [&] {
            for (double tk : at) {
                std::vector<double> ref = constant_w_reference(c, w, w0, g0, r00, v00, tk);
                for (double& x : ref) x *= S;
                refs.push_back(ref);
            }
        });
        const double floor = 1e-3 * S;
        const std::string statements = "P := " + c.problem + "\ns := solve(P)\n(C++) the components of s with " +
                                       values + " put in exactly, compiled in t, at t = " + decimal(at[0]) + ", " +
                                       decimal(at[1]) + ", " + decimal(at[2]) + ", " + decimal(at[3]);
        trace(statements);
        st.family = "compiled: stable eval", st.tolerance = 1e-9;
        many.family = "compiled: stable eval_many", many.tolerance = 2e-6;
        plain.family = "compiled: plain eval_many", plain.tolerance = 1e-6;
        st.statements = many.statements = plain.statements = statements;
        try {
            if (!referenced) throw std::runtime_error(st.error);
            if (solved_for != c.problem) {
                R.run("P := " + c.problem + "\ns := solve(P)");
                solved_for = c.problem;
            }
            const GiNaC::ex s = R.value("s").as_ex();
            const lang::data_values d = lang::exact_values(lang::read_values(R.value(values), b, 1));
            const std::vector<GiNaC::ex> outs = lang::components(lang::put_values_limit(s, d));
            const num::compiled_function f = num::compile(outs, {t});
            const num::stable_function sf(outs, {t});
            const std::size_t m = outs.size(), np = at.size();
            std::vector<double> y_plain(m * np), y_many(m * np), y_one(m), value(m), bound(m);
            f.eval_many(at.data(), y_plain.data(), np);
            sf.eval_many(at.data(), y_many.data(), np, 1e-6);
            for (std::size_t k = 0; k < np; ++k) {
                auto row = [&](const std::vector<double>& y) { return std::vector<double>(y.begin() + k * m, y.begin() + (k + 1) * m); };
                sf.eval(&at[k], y_one.data());
                st.difference = std::max(st.difference, relative(y_one, refs[k], floor));
                many.difference = std::max(many.difference, relative(row(y_many), refs[k], floor));
                const double dp = relative(row(y_plain), refs[k], floor);
                if (dp > plain.tolerance) {
                    sf.eval_binary64(&at[k], value.data(), bound.data());
                    bool flagged = false;
                    for (std::size_t j = 0; j < m; ++j)
                        if (!(bound[j] <= 1e-6 * std::abs(value[j]))) flagged = true;
                    if (!flagged) plain.difference = std::max(plain.difference, dp);
                }
            }
        } catch (const std::exception& e) {
            for (outcome* o : {&st, &many, &plain}) o->difference = -1, o->error = e.what();
        }
        out.push_back(std::move(st));
        out.push_back(std::move(many));
        out.push_back(std::move(plain));
    }
    return out;
}

}  // namespace symrep::differential
