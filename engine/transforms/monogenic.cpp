// symrep/transforms/monogenic.cpp -- see monogenic.h.
#include "symrep/transforms/monogenic.h"

#include <algorithm>

#include "symrep/core/error.h"
#include "symrep/scalar/scalar.h"

namespace symrep::transforms {

using GiNaC::ex;

namespace {

// The element b as text: "i0", "2*eps - j", ...
std::string element_text(const algebra_ptr& A, const coeffs& b) {
    std::string s;
    for (std::size_t k = 0; k < b.size(); ++k) {
        if (b[k].is_zero()) continue;
        const std::string c = message_text(b[k], text_limit::fragment), name = A->basis_name(k);
        std::string term = c == "1" ? name : c == "-1" ? "-" + name : (name == "1" ? c : "(" + c + ")*" + name);
        if (k == 0) term = c;
        s += (s.empty() ? "" : " + ") + term;
    }
    return s.empty() ? "0" : s;
}

}  // namespace

monogenicity monogenic(const algebra_ptr& A, const coeffs& F, const coeffs& d) {
    A->check_size(F, "monogenic");
    A->check_size(d, "monogenic");
    const std::vector<ex> vars = symbols_by_name(d);
    if (vars.empty()) throw domain_error("monogenic: the variable d has no symbol (write d = omega0*i0 + ... with symbols)");
    std::vector<coeffs> dirs;
    for (const auto& v : vars) {
        coeffs b;
        for (const ex& x : d) {
            const ex c = tidy(x.diff(GiNaC::ex_to<GiNaC::symbol>(v)));
            for (const auto& w : vars)
                if (c.has(w))
                    throw domain_error("monogenic: d is not affine in its symbols (the coefficient of " + GiNaC::ex_to<GiNaC::symbol>(v).get_name() +
                                       " holds " + GiNaC::ex_to<GiNaC::symbol>(w).get_name() + ")");
            b.push_back(c);
        }
        dirs.push_back(b);
    }
    std::size_t r = vars.size();
    for (std::size_t i = 0; i < vars.size() && r == vars.size(); ++i)
        if (!A->is_zero_divisor(dirs[i])) r = i;
    if (r == vars.size()) throw domain_error("monogenic: no symbol of d has an invertible direction dd/dx");
    const auto partial = [&](const ex& v) {
        coeffs out;
        for (const ex& x : F) out.push_back(x.diff(GiNaC::ex_to<GiNaC::symbol>(v)));
        return out;
    };
    const coeffs Fr = partial(vars[r]);
    monogenicity out;
    out.holds = truth::yes;
    for (std::size_t i = 0; i < vars.size(); ++i) {
        if (i == r) continue;
        const coeffs lhs = A->multiply(dirs[r], partial(vars[i])), rhs = A->multiply(dirs[i], Fr);
        truth ok = truth::yes;
        std::string witness;
        for (std::size_t k = 0; k < lhs.size() && ok != truth::no; ++k) {
            const ex diff = tidy(GiNaC::normal(lhs[k] - rhs[k]));
            if (is_zero_scalar(diff)) continue;
            const zero_decision z = decide_zero(diff);
            if (z.is_zero == truth::no) {
                ok = truth::no;
                witness = " (coordinate " + A->basis_name(k) + " nonzero " + witness_text(z) + ")";
            } else if (z.is_zero == truth::unknown) {
                ok = truth::unknown;
            }
        }
        if (ok == truth::no) out.holds = truth::no;
        else if (ok == truth::unknown && out.holds == truth::yes) out.holds = truth::unknown;
        out.report += (out.report.empty() ? "" : "; ") + element_text(A, dirs[r]) + " dF/d" + GiNaC::ex_to<GiNaC::symbol>(vars[i]).get_name() +
                      " = " + element_text(A, dirs[i]) + " dF/d" + GiNaC::ex_to<GiNaC::symbol>(vars[r]).get_name() + ": " +
                      (ok == truth::yes ? "proved" : ok == truth::no ? "false" + witness : "not decided");
    }
    if (out.report.empty()) out.report = "d has one variable: F is a function of it, nothing to check";
    return out;
}

}  // namespace symrep::transforms
