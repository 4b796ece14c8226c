// symrep/transforms/parseval.cpp -- see parseval.h.
#include "symrep/transforms/parseval.h"

#include <bit>

#include "symrep/algebra/multicomplex.h"
#include "symrep/core/error.h"
#include "symrep/scalar/scalar.h"
#include "symrep/signals/representation.h"
#include "symrep/transforms/inversion.h"
#include "symrep/transforms/laplace.h"

namespace symrep::transforms {

using GiNaC::ex;

coeffs hypercomplex_conjugate(const algebra_ptr& A, const coeffs& x) {
    if (dynamic_cast<const multicomplex*>(A.get()) == nullptr)
        throw algebra_error("hypercomplex_conjugate: defined on multicomplex(n) (V.2.40-41), not on " + A->name());
    A->check_size(x, "hypercomplex_conjugate");
    coeffs out(x.size());
    for (std::size_t k = 0; k < x.size(); ++k) out[k] = std::popcount(k) % 2 ? ex(-x[k]) : x[k];
    return out;
}

namespace {

// Every exponent of f shown to have a negative real part (f in L2), else domain_error naming it.
void require_decaying(const ex& f, const GiNaC::symbol& t, const char* which) {
    for (const auto& e : signals::exponents_of(f, t)) {
        const ex re = tidy(GiNaC::real_part(e.lambda.expand()));
        GiNaC::numeric v;
        if (re.info(GiNaC::info_flags::negative) || (evaluate_numeric(re, 30, v) && v.is_real() && v.is_negative()))
            continue;
        const bool known = evaluate_numeric(re, 30, v) && v.is_real();
        throw domain_error(std::string("parseval: ") +
                           (known ? "the signal " : "cannot decide whether the signal ") + which + " = " +
                           message_text(f, text_limit::report) +
                           (known ? " is not in L2" : " is in L2") + ": its exponent " +
                           message_text(e.lambda, text_limit::report) +
                           (known ? " has a real part >= 0" : " is not shown to have a negative real part"));
    }
}

/// x proved 0 after tidying it (scalar/equality.h).
bool proved_zero_tidy(const ex& x) { return proved_zero(tidy(x)); }

}  // namespace

ex parseval_frequency_side(const ex& f, const ex& g, const GiNaC::symbol& t) {
    require_decaying(f, t, "f");
    require_decaying(g, t, "g");
    if (f.is_zero() || g.is_zero()) return 0;
    const GiNaC::symbol s("s");
    const ex F = laplace(f, t, s), G = laplace(g, t, s);
    const ex nd = GiNaC::normal(F).numer_denom();
    const ex den = nd.op(1).expand(), lc = den.lcoeff(s);
    const auto exps = signals::exponents_of(f, t);
    ex product = 1;
    for (const auto& e : exps) product *= GiNaC::pow(s - e.lambda, e.multiplicity);
    if (!proved_zero_tidy(product - den / lc))
        throw internal_error("parseval: the denominator of L f is not the product over the exponents of f");
    const ex Gm = G.subs(s == -s);
    ex sum = 0;
    for (const auto& e : exps) {
        ex rest = nd.op(0) / lc * Gm;
        for (const auto& o : exps)
            if (!o.lambda.is_equal(e.lambda)) rest = rest / GiNaC::pow(s - o.lambda, o.multiplicity);
        for (unsigned j = 1; j < e.multiplicity; ++j) rest = rest.diff(s);
        sum += rest.subs(s == e.lambda) / GiNaC::factorial(e.multiplicity - 1);
    }
    return tidy(GiNaC::normal(tidy(sum)));
}

parseval_result parseval(const algebra_ptr& A, const ex& f, const ex& g, const GiNaC::symbol& t) {
    const auto* M = dynamic_cast<const multicomplex*>(A.get());
    if (M == nullptr) throw algebra_error("parseval: the relation V.2.44 is stated over multicomplex(n), not " + A->name());
    parseval_result out;
    out.frequency_side = parseval_frequency_side(f, g, t);  // first: refuses a signal not in L2 by name
    out.time_side = inner_product(f, g, t);
    bool all = true;
    const auto note = [&](bool ok, const std::string& what) {
        all = all && ok;
        out.report += (out.report.empty() ? "" : "; ") + what + (ok ? ": proved" : ": not proved");
    };
    note(proved_zero_tidy(out.time_side - out.frequency_side),
         "int_0^oo f g dt = (1/2 pi) int F(i w) conj G(i w) dw (residues)");
    // the algebra side with d = sum_k omega_k i_k symbolic
    const unsigned n = M->order();
    coeffs d = A->zero();
    std::vector<GiNaC::symbol> omega;
    for (unsigned k = 0; k <= n; ++k) {
        omega.emplace_back("omega" + std::to_string(k));
        d = algebra::add(d, algebra::scale(omega.back(), M->imag_unit(k)));
    }
    const coeffs Tf = transform(A, d, f, t).value, Tg = transform(A, d, g, t).value;
    const coeffs Tg_star = hypercomplex_conjugate(A, Tg), Tg_minus = transform(A, algebra::scale(-1, d), g, t).value;
    bool conj_ok = true;
    for (std::size_t k = 0; k < Tg.size(); ++k) conj_ok = conj_ok && proved_zero_tidy(Tg_star[k] - Tg_minus[k]);
    note(conj_ok, "(T g)^* = T g(-d)");
    const GiNaC::symbol s("s");
    const ex F = laplace(f, t, s), G = laplace(g, t, s);
    // the product is componentwise in the idempotent basis (III.1.39): component p of T f (T g)^*
    const auto Pf = A->idempotent_components(Tf), Pg = A->idempotent_components(Tg_star);
    const auto D = A->idempotent_components(d);
    bool comp_ok = true;
    for (std::size_t p = 0; p < Pf.size(); ++p)  // D[p] = i Omega_p
        comp_ok = comp_ok && proved_zero_tidy(GiNaC::normal(Pf[p] * Pg[p] - F.subs(s == D[p]) * G.subs(s == -D[p])));
    note(comp_ok, "the components of T f (T g)^* are F(i Omega_p) conj G(i Omega_p)");
    out.element = algebra::scale(out.frequency_side, A->unit());
    out.proved = all ? truth::yes : truth::unknown;
    // the frequency integral by quadrature, for numeric data
    try {
        const inversion_value q = parseval_integral(F, G, s);
        out.quadrature = q.value;
        out.quadrature_error = q.error_estimate;
        out.has_quadrature = true;
    } catch (const domain_error&) {
        // symbolic coefficients: no quadrature
    }
    return out;
}

}  // namespace symrep::transforms
