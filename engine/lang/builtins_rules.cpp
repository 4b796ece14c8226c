// symrep/lang/builtins_rules.cpp -- rewrite rules from rule files (rules/rules.h):
//
//   rewrite(a x (b x (c x d)))     the session's rules applied to a fixed point
//   load_rules("my.rules")         more rules, checked when loaded
//   rules()                        lists the rules
#include <filesystem>

#include "symrep/scalar/scalar.h"
#include "symrep/lang/builtins.h"
#include "symrep/lang/interpreter.h"
#include "symrep/output/printer.h"
#include "symrep/rules/rules.h"
#include "symrep/vector/vector.h"

namespace symrep::lang {

using output::print_ex;

using GiNaC::ex;
using args_t = std::vector<value>;

namespace {

const char* const section = "Rewrite rules";

session& session_of(context& c, const builtin& b) {
    auto* s = dynamic_cast<session*>(&c);
    if (!s) throw type_error(b.name + ": not available here");
    return *s;
}

// A rule file's syntax_error as one message FILE:LINE:COL: ... (the script's
// own error report then says where load_rules/rewrite was called).
[[noreturn]] void rethrow_located(const builtin& b, const syntax_error& e) {
    throw syntax_error(b.name + ": " + e.where.file + ":" + std::to_string(e.where.line) + ":" +
                           std::to_string(e.where.column) + ": " + e.what(),
                       e.where);
}

}  // namespace

symrep::rules::rule_set& session::rewrite_rules() {
    if (!rules_) rules_ = std::make_shared<symrep::rules::rule_set>(symrep::rules::default_rules());
    return *rules_;
}

namespace {

value builtin_rewrite(const builtin& b, const args_t& a, context& c) {
    session& s = session_of(c, b);
    const ex& e = arg_ex(a, 0, b);
    const long n = a.size() > 1 ? arg_int(a, 1, b, 0, 100000000L) : 1000;
    symrep::rules::rule_set* set;
    try {
        set = &s.rewrite_rules();
    } catch (const syntax_error& x) {
        rethrow_located(b, x);
    }
    const symrep::rules::rewrite_result res = set->rewrite(e, std::size_t(n));
    if (res.bound_hit) {
        std::string last, partial = print_ex(res.result);  // in the language's notation
        if (partial.size() > 160) partial = partial.substr(0, 157) + "...";
        if (res.last)
            last = "; last rule applied: " + res.last->name + " (" + res.last->where.file + ":" +
                   std::to_string(res.last->where.line) + ")";
        throw domain_error(b.name + ": no fixed point after " + std::to_string(n) +
                           " rewrites, the rules may undo each other" + last + "; partial result " +
                           partial);
    }
    return value(res.result);
}

value builtin_load_rules(const builtin& b, const args_t& a, context& c) {
    session& s = session_of(c, b);
    const std::string path = s.resolve_path(arg_string(a, 0, b));
    try {
        return value(ex(long(s.rewrite_rules().load_file(path))));
    } catch (const syntax_error& x) {
        rethrow_located(b, x);
    }
}

value builtin_rules(const builtin& b, const args_t&, context& c) {
    session& s = session_of(c, b);
    symrep::rules::rule_set* set;
    try {
        set = &s.rewrite_rules();
    } catch (const syntax_error& x) {
        rethrow_located(b, x);
    }
    for (const auto& x : set->rules())
        c.out() << x.name << ": " << x.text << "  ("
                << std::filesystem::path(x.where.file).filename().string() << ":" << x.where.line << ")\n";
    return value(ex(long(set->rules().size())));
}

}  // namespace

void register_rules_builtins(registry& r) {
    add_builtins(r, section, {
        {"rewrite", "rewrite(e [, max_steps])",
         "Applies the session's rewrite rules (rules/vector.rules and those added by load_rules) to every "
         "subexpression of e, innermost first, until none applies: BAC-CAB, Binet-Cauchy, triple products, "
         "Gram determinants, ... The value is unchanged (every rule is checked when loaded). Stops with an "
         "error after max_steps rewrites (default 1000), e.g. when two rules undo each other.",
         "", "vector a, b, c, d\nrewrite(a x (b x (c x d)))", 1, 2, builtin_rewrite},
        {"load_rules", "load_rules(\"file\")",
         "Adds the rules of a rule file to the session (format: docs/vectors.md, Rewrite rules). A relative "
         "path is relative to the running script. Every rule is checked when loaded (both sides equal for "
         "fresh vectors); an error names FILE:LINE:COL and adds nothing. Returns the number of rules added "
         "(0 for a file already loaded).",
         "", "load_rules(\"rules/vector.rules\")", 1, 1, builtin_load_rules},
        {"rules", "rules()",
         "Prints the session's rewrite rules in the order they are tried, one a line: name, the rule, "
         "FILE:LINE. Returns their number.",
         "", "rules()", 0, 0, builtin_rules},
    });
}

}  // namespace symrep::lang
