// symrep/signals/product.cpp -- see product.h.
#include "symrep/signals/product.h"

#include "symrep/core/error.h"
#include "symrep/scalar/scalar.h"

namespace symrep::signals {

using GiNaC::ex;

coeffs tensor(const coeffs& x, const coeffs& y) {
    coeffs out;
    out.reserve(x.size() * y.size());
    for (const ex& a : x)
        for (const ex& b : y) out.push_back(tidy(a * b));
    return out;
}

std::shared_ptr<const tensor_algebra> tensor_algebra::make(const representation& RA, const representation& RB) {
    const algebra& A = *RA.A;
    const algebra& B = *RB.A;
    const std::size_t m = A.dim(), n = B.dim();
    std::vector<std::vector<coeffs>> gamma(m * n, std::vector<coeffs>(m * n));
    for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = 0; j < n; ++j)
            for (std::size_t k = 0; k < m; ++k)
                for (std::size_t l = 0; l < n; ++l)
                    gamma[i * n + j][k * n + l] = tensor(A.basis_product(i, k), B.basis_product(j, l));
    std::vector<std::string> names;
    for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = 0; j < n; ++j) names.push_back(A.basis_name(i) + "(x)" + B.basis_name(j));
    const coeffs d = algebra::add(tensor(RA.d, B.unit()), tensor(A.unit(), RB.d));
    auto T = std::make_shared<const tensor_algebra>(std::move(gamma), std::move(names),
                                                    A.name() + " (x) " + B.name(), tensor(RA.lambda, RB.lambda), d);
    return T;
}

representation product_representation(const representation& RA, const representation& RB) {
    const auto T = tensor_algebra::make(RA, RB);
    representation R;
    R.A = T;
    R.d = T->operator_d();
    R.p = T->minpoly(R.d, R.X);
    R.lambda = T->functional();
    return R;
}

}  // namespace symrep::signals
