// symrep/lang/help.cpp -- help texts and completion candidates (lang/help.h).
#include "symrep/lang/help.h"

#include <algorithm>

namespace symrep::lang {

std::string help_text(const registry& r, const std::string& name) {
    const builtin* b = r.find(name);
    if (!b) return {};
    std::string s = b->signature + "    [" + b->section + "]\n  " + b->summary + "\n";
    if (!b->equation.empty()) s += "  Thesis: " + b->equation + "\n";
    if (!b->example.empty()) s += "  Example: " + b->example + "\n";
    return s;
}

std::string unknown_builtin_message(const registry& r, const std::string& name) {
    std::string msg = "no function named '" + name + "'";
    const auto near = similar_builtin_names(r, name);
    if (near.empty()) return msg + " (help lists all functions)";
    msg += "; did you mean ";
    for (std::size_t i = 0; i < near.size(); ++i) msg += (i ? ", " : "") + near[i];
    return msg + "?";
}

std::vector<std::string> completions(const session& s, const std::string& prefix, bool commands) {
    std::vector<std::string> out;
    auto consider = [&](const std::string& name) {
        if (name.rfind(prefix, 0) == 0) out.push_back(name);
    };
    for (const auto* b : s.builtins().all()) consider(b->name);
    for (const auto& v : s.variable_names()) consider(v);
    for (const char* k : {"vector", "positive", "true", "false", "pi", "I", "eps"}) consider(k);
    if (commands)
        for (const char* c : {"help", "quit", "exit"}) consider(c);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

}  // namespace symrep::lang
