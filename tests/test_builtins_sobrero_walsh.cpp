// Tests of the Sobrero and Walsh builtins, called through the registry entries'
// fn with a small mock context.
#include <gtest/gtest.h>

#include "mock_context.h"

#include <map>
#include <sstream>

#include "algebra/sobrero.h"
#include "algebra/walsh.h"
#include "algebra/walsh_complex.h"
#include "lang/builtins.h"

using namespace symrep;
using namespace symrep::lang;
using GiNaC::ex;

namespace {

using symrep::test::mock_context;

struct BuiltinsSW : ::testing::Test {
    registry r;
    mock_context ctx;
    void SetUp() override {
        register_sobrero_builtins(r);
        register_walsh_builtins(r);
    }
    value call(const std::string& name, const std::vector<value>& args) {
        const builtin* b = r.find(name);
        if (!b) throw std::logic_error("no builtin " + name);
        return b->fn(args, ctx);
    }
    std::string message(const std::string& name, const std::vector<value>& args) {
        try {
            call(name, args);
        } catch (const error& e) {
            return e.what();
        }
        return "";
    }
};

}  // namespace

TEST_F(BuiltinsSW, Documented) {
    for (const char* name : {"sobrero", "sobrero_j", "sobrero_eps", "walsh", "walsh_complex",
                             "walsh_generator", "walsh_i0"}) {
        const builtin* b = r.find(name);
        ASSERT_NE(b, nullptr) << name;
        EXPECT_FALSE(b->signature.empty()) << name;
        EXPECT_FALSE(b->summary.empty()) << name;
        EXPECT_NE(b->equation.find("III."), std::string::npos) << name;
        EXPECT_FALSE(b->example.empty()) << name;
        EXPECT_TRUE(b->section == "Sobrero algebra" || b->section == "Walsh algebra") << name;
        EXPECT_TRUE(b->fn) << name;
    }
}

TEST_F(BuiltinsSW, Sobrero) {
    const value S = call("sobrero", {value(2)});
    ASSERT_TRUE(S.is_algebra());
    EXPECT_EQ(S.as_algebra()->name(), "sobrero(2)");
    const element j = call("sobrero_j", {S}).as_element();
    const element e = call("sobrero_eps", {S}).as_element();
    EXPECT_TRUE(j * j == element::scalar(S.as_algebra(), -1));
    EXPECT_FALSE(e.pow(2) == element::scalar(S.as_algebra(), 0));
    EXPECT_TRUE(e.pow(3) == element::scalar(S.as_algebra(), 0));
    EXPECT_NE(message("sobrero", {value(5000)}).find("512"), std::string::npos);
    EXPECT_THROW(call("sobrero", {value(5000)}), size_error);
    EXPECT_THROW(call("sobrero", {value(-1)}), type_error);
    EXPECT_THROW(call("sobrero", {value("x")}), type_error);
    const std::string m = message("sobrero_j", {call("walsh", {value(2)})});
    EXPECT_NE(m.find("must be a Sobrero algebra"), std::string::npos) << m;
    EXPECT_NE(m.find("walsh(2)"), std::string::npos) << m;
}

TEST_F(BuiltinsSW, Walsh) {
    const value W = call("walsh", {value(3)});
    EXPECT_EQ(W.as_algebra()->name(), "walsh(3)");
    const element u0 = call("walsh_generator", {W, value(0)}).as_element();
    const element u2 = call("walsh_generator", {W, value(2)}).as_element();
    EXPECT_TRUE(u0 * u0 == element::one(W.as_algebra()));
    EXPECT_TRUE(u0 == element::basis(W.as_algebra(), 4));  // p_0 is the most significant bit
    EXPECT_TRUE(u2 == element::basis(W.as_algebra(), 1));
    const std::string m = message("walsh_generator", {W, value(3)});
    EXPECT_NE(m.find("there is no u_3"), std::string::npos) << m;
    EXPECT_THROW(call("walsh", {value(40)}), size_error);
    EXPECT_NE(message("walsh_i0", {W}).find("walsh_complex"), std::string::npos);

    const value C = call("walsh_complex", {value(2)});
    EXPECT_EQ(C.as_algebra()->name(), "walsh_complex(2)");
    const element i0 = call("walsh_i0", {C}).as_element();
    EXPECT_TRUE(i0 * i0 == element::scalar(C.as_algebra(), -1));
    const element v1 = call("walsh_generator", {C, value(1)}).as_element();
    EXPECT_TRUE(v1 * v1 == element::one(C.as_algebra()));
    EXPECT_THROW(call("walsh_generator", {call("sobrero", {value(1)}), value(0)}), type_error);
    EXPECT_THROW(call("walsh_complex", {value(26)}), size_error);
}
