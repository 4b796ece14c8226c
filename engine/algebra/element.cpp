// symrep/algebra/element.cpp
#include "symrep/algebra/element.h"

#include "symrep/scalar/equality.h"
#include "symrep/scalar/scalar.h"
#include "symrep/core/error.h"

namespace symrep {

using GiNaC::ex;

element::element(algebra_ptr A, coeffs c) : A_(std::move(A)), c_(std::move(c)) {
    if (!A_) throw algebra_error("element of no algebra");
    A_->check_size(c_, "element");
}

element element::one(algebra_ptr A) { auto u = A->unit(); return {std::move(A), std::move(u)}; }
element element::basis(algebra_ptr A, std::size_t k) {
    auto b = A->basis_vector(k);
    return {std::move(A), std::move(b)};
}
element element::scalar(algebra_ptr A, const ex& s) {
    auto u = algebra::scale(s, A->unit());
    return {std::move(A), std::move(u)};
}

void require_same_algebra(const element& a, const element& b, const char* op) {
    if (a.parent_ptr() == b.parent_ptr()) return;
    if (a.parent().name() != b.parent().name())
        throw algebra_error(std::string("cannot ") + op + " elements of different algebras: " +
                            a.parent().name() + " and " + b.parent().name());
}

element element::operator-() const { return {A_, algebra::scale(-1, c_)}; }

element operator+(const element& a, const element& b) {
    require_same_algebra(a, b, "add");
    coeffs c = algebra::add(a.c_, b.c_);
    for (auto& x : c) x = tidy(x);
    return {a.A_, std::move(c)};
}

element operator-(const element& a, const element& b) {
    require_same_algebra(a, b, "subtract");
    coeffs c = algebra::sub(a.c_, b.c_);
    for (auto& x : c) x = tidy(x);
    return {a.A_, std::move(c)};
}

element operator*(const element& a, const element& b) {
    require_same_algebra(a, b, "multiply");
    return {a.A_, a.A_->multiply(a.c_, b.c_)};
}

element operator*(const ex& s, const element& a) { return {a.A_, algebra::scale(s, a.c_)}; }

element operator/(const element& a, const element& b) { return a * b.inverse(); }

element operator/(const element& a, const ex& s) {
    if (!is_nonzero_generic(s, "division of an algebra element")) throw domain_error("division of an algebra element by zero");
    return {a.A_, algebra::scale(1 / s, a.c_)};
}

element element::pow(long k) const {
    if (k >= 0) return {A_, A_->power(c_, static_cast<unsigned long>(k))};
    return {A_, A_->power(A_->inverse(c_), static_cast<unsigned long>(-k))};
}

bool operator==(const element& a, const element& b) {
    return a.A_->name() == b.A_->name() && algebra::equal(a.c_, b.c_);
}

element element::evaluate(const ex& p, const GiNaC::symbol& X) const {
    return {A_, A_->evaluate_polynomial(p, X, c_)};
}

}  // namespace symrep
