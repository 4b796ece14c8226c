// symrep/numeric/reference.cpp -- see reference.h.
#include "numeric/reference.h"

#include <cln/float.h>
#include <cln/real.h>
#include <cmath>
#include <sstream>

#include "io/error.h"

namespace symrep::num {

GiNaC::numeric exact_rational(double x) {
    if (!std::isfinite(x)) throw domain_error("reference: input is not a finite number");
    return GiNaC::numeric(cln::cl_N(cln::rational(cln::cl_DF(x))));
}

namespace {

/// Sets GiNaC::Digits for one scope.
struct digits_scope {
    long saved;
    explicit digits_scope(long d) : saved(GiNaC::Digits) { GiNaC::Digits = d; }
    ~digits_scope() { GiNaC::Digits = saved; }
    digits_scope(const digits_scope&) = delete;
    digits_scope& operator=(const digits_scope&) = delete;
};

}  // namespace

std::vector<long double> reference_eval(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::ex>& inputs,
                                        const std::vector<double>& point, int digits) {
    if (point.size() != inputs.size())
        throw type_error("reference: " + std::to_string(point.size()) + " values for " +
                         std::to_string(inputs.size()) + " inputs");
    if (digits < 20 || digits > 10000) throw domain_error("reference: digits must be in 20 .. 10000");
    GiNaC::exmap at;
    for (std::size_t i = 0; i < inputs.size(); ++i) at[inputs[i]] = exact_rational(point[i]);
    const digits_scope scope(digits);
    std::vector<long double> out;
    out.reserve(outputs.size());
    for (const GiNaC::ex& e : outputs) {
        const GiNaC::ex v = e.subs(at, GiNaC::subs_options::no_pattern).evalf();
        if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) {
            std::ostringstream os;
            os << v;
            std::string s = os.str();
            if (s.size() > 120) s = s.substr(0, 117) + "...";
            throw domain_error("reference: not a real number: " + s);
        }
        const cln::cl_R r = cln::the<cln::cl_R>(GiNaC::ex_to<GiNaC::numeric>(v).to_cl_N());
        out.push_back(cln::double_approx(r) + static_cast<long double>(
            cln::double_approx(r - cln::rational(cln::cl_DF(cln::double_approx(r))))));
    }
    return out;
}

}  // namespace symrep::num
