// symrep/algebra/double_path.cpp -- see double_path.h.
#include "symrep/algebra/double_path.h"

#include "symrep/core/error.h"

namespace symrep::double_path {

using GiNaC::ex;

bool is_real_number(const ex& x) {
    return GiNaC::is_a<GiNaC::numeric>(x) && GiNaC::ex_to<GiNaC::numeric>(x).is_real();
}

namespace {
bool is_float(const ex& x) { return is_real_number(x) && !GiNaC::ex_to<GiNaC::numeric>(x).is_rational(); }
}  // namespace

void refuse_exact(const std::string& algebra_name, unsigned max_exact, const char* what) {
    throw size_error(std::string(what) + " in " + algebra_name + ": the exact algebra is limited to n <= " +
                     std::to_string(max_exact) + "; above it " + algebra_name +
                     " computes in double precision only, on elements with numeric coordinates (see its help)");
}

bool takes(std::initializer_list<const coeffs*> operands, bool exact, const std::string& algebra_name,
           unsigned max_exact, const char* what) {
    bool numeric = true, any_float = false;
    for (const coeffs* c : operands)
        for (const ex& x : *c) {
            numeric = numeric && is_real_number(x);
            any_float = any_float || is_float(x);
        }
    if (!exact && !numeric)
        throw size_error(std::string(what) + " in " + algebra_name +
                         ": an element with symbolic coordinates needs the exact algebra, which is limited to n <= " +
                         std::to_string(max_exact) + "; above it the coordinates must be numbers (double precision)");
    return numeric && (any_float || !exact);
}

std::vector<double> to_doubles(const coeffs& c) {
    std::vector<double> v(c.size());
    for (std::size_t k = 0; k < c.size(); ++k) v[k] = GiNaC::ex_to<GiNaC::numeric>(c[k]).to_double();
    return v;
}

coeffs from_doubles(const std::vector<double>& v) {
    coeffs c(v.size());
    for (std::size_t k = 0; k < v.size(); ++k) c[k] = v[k] == 0 ? ex(0) : ex(GiNaC::numeric(v[k]));
    return c;
}

}  // namespace symrep::double_path

namespace symrep {

bool algebra::takes_double_path(std::initializer_list<const coeffs*> operands, const char* what) const {
    return double_path::takes(operands, exact(), name(), exact_limit(), what);
}

void algebra::require_exact(const char* what) const {
    if (!exact()) double_path::refuse_exact(name(), exact_limit(), what);
}

std::optional<coeffs> algebra::exp_on_double_path(
    const coeffs& w, const GiNaC::ex& t,
    const std::function<std::vector<double>(const std::vector<double>&, double)>& double_exp) const {
    const coeffs tc{t};
    if (double_path::is_real_number(t) && takes_double_path({&w, &tc}, "exp"))
        return double_path::from_doubles(double_exp(double_path::to_doubles(w), double_path::to_doubles(tc)[0]));
    if (!exact()) takes_double_path({&w, &tc}, "exp");  // a symbolic t: refused by name
    return std::nullopt;
}

}  // namespace symrep

