// tests/test_support.h -- helpers shared by the language tests: two tiny
// test-only algebras (the complex numbers C and the dual numbers D, j^2 = 0)
// registered as builtins cplx() and dual(), a value-to-ex shortcut, and the
// names a script calls.
#pragma once

#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "algebra/algebra.h"
#include "algebra/element.h"
#include "lang/interpreter.h"
#include "syntax/parser.h"
#include "test_util.h"  // same(): exact equality of expressions

namespace symrep::test {

/// C as a real algebra: basis 1, j with j^2 = -1.
class complex_test_algebra : public algebra {
public:
    std::string name() const override { return "cplx_test"; }
    std::size_t dim() const override { return 2; }
    std::string basis_name(std::size_t k) const override { return k == 0 ? "1" : "j"; }
    coeffs multiply(const coeffs& a, const coeffs& b) const override {
        return {GiNaC::expand(a[0] * b[0] - a[1] * b[1]), GiNaC::expand(a[0] * b[1] + a[1] * b[0])};
    }
};

/// The dual numbers: basis 1, j with j^2 = 0 (j is a zero divisor).
class dual_test_algebra : public algebra {
public:
    std::string name() const override { return "dual_test"; }
    std::size_t dim() const override { return 2; }
    std::string basis_name(std::size_t k) const override { return k == 0 ? "1" : "j"; }
    coeffs multiply(const coeffs& a, const coeffs& b) const override {
        return {GiNaC::expand(a[0] * b[0]), GiNaC::expand(a[0] * b[1] + a[1] * b[0])};
    }
};

inline void register_test_algebras(lang::registry& r) {
    auto add = [&](const char* name, algebra_ptr A) {
        lang::builtin b;
        b.name = name;
        b.signature = std::string(name) + "()";
        b.summary = "test-only algebra";
        b.section = "Test";
        b.fn = [A](const std::vector<lang::value>&, lang::context&) { return lang::value(A); };
        r.add(std::move(b));
    };
    add("cplx", std::make_shared<complex_test_algebra>());
    add("dual_test", std::make_shared<dual_test_algebra>());  // not "dual": the builtin dual(a, b)
}

/// A session writing into string streams, with the test algebras registered.
struct test_session {
    std::ostringstream out, err;
    lang::session s{out, err};
    test_session() { register_test_algebras(s.builtins()); }
    GiNaC::ex ex(const std::string& text) {
        lang::value v = s.evaluate(text);
        EXPECT_TRUE(v.is_ex()) << text << " gave a " << v.kind();
        return v.is_ex() ? v.as_ex() : GiNaC::ex(0);
    }
    lang::value val(const std::string& text) { return s.evaluate(text); }
    /// Runs `text` as a script; returns the number of failed statements.
    int run(const std::string& text) { return s.run_string(text, "t.sr"); }
};

/// Adds the names of the functions called anywhere in the syntax tree n to out.
inline void called_names(const lang::node& n, std::set<std::string>& out) {
    if (n.kind == lang::node::call) out.insert(n.text);
    for (const auto& k : n.kids) called_names(*k, out);
}

}  // namespace symrep::test
