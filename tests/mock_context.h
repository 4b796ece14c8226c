// tests/mock_context.h -- a minimal lang::context for calling builtins directly
// (registry entry -> fn(args, ctx)) without a session: real symbols by name and
// an output buffer.
#pragma once

#include <map>
#include <sstream>
#include <string>

#include "lang/builtins.h"

namespace symrep::test {

class mock_context : public lang::context {
public:
    GiNaC::ex symbol(const std::string& name) override {
        auto it = syms_.find(name);
        if (it == syms_.end()) it = syms_.emplace(name, GiNaC::realsymbol(name)).first;
        return it->second;
    }
    std::ostream& out() override { return out_; }
    std::string output() const { return out_.str(); }

private:
    std::map<std::string, GiNaC::ex> syms_;
    std::ostringstream out_;
};

}  // namespace symrep::test
