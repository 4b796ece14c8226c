// symrep/rules/rules.h -- rewrite rules over vector expressions, read from
// plain-text rule files (rules/vector.rules) at run time.
//
// engine/rules/ reads rule files and applies them; it includes core/, scalar/,
// syntax/ and vector/ (docs/architecture.md).
//
// Why a representation of its own
// --------------------------------
// GiNaC evaluates an expression when it is built: cross(a, a) is 0 at once,
// dot(b, a) becomes dot(a, b), cross(b, a) becomes -cross(a, b), scalar factors
// leave cross/dot. A rule side read into GiNaC would therefore not be the
// pattern that was written. Rule sides are parsed with the language's parser
// (syntax/parser.h) and converted into `pattern` trees that nothing evaluates; the
// matcher walks a pattern and a GiNaC expression side by side and knows that
// cross is anticommutative, dot commutative and the triple product alternating,
// so argument orders chosen by GiNaC do not matter.
//
// File format (docs/vectors.md, "Rewrite rules")
// ----------------------------------------------
//   # comment                             a whole-line comment
//   vector a, b, c, d; scalar s           typed pattern variables (from here on)
//   a x (b x c) -> b*(a . c) - c*(a . b)  # BAC-CAB   (the comment names the rule)
// One rule or declaration per statement; statements are separated by newlines
// or ';'. Every rule is checked when loaded: its sides are built with fresh
// vectors/scalars for the variables and compared with symrep::equal(); a rule
// that does not hold, an ill-typed side, a right-side variable the left side
// does not bind, or a syntax error is a syntax_error with FILE:LINE:COL.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <ginac/ginac.h>

#include "symrep/core/error.h"

namespace symrep::rules {

enum class var_type { scalar, vector };

/// A rule side as written. Subtraction is add with a factor -1 (mul), division
/// a power -1, norm(p) the power (p . p)^(1/2), as GiNaC represents them.
struct pattern {
    enum kind_t { var, number, add, mul, power, cross, dot, triple };
    kind_t kind = number;
    std::string name;         ///< var: the variable's name
    var_type type = var_type::scalar;  ///< var: its type
    GiNaC::ex num;            ///< number: the value
    std::vector<pattern> kids;
    int line = 0, column = 0;  ///< where it was written
};

/// Text of a pattern in the language's notation (fully parenthesized).
std::string to_string(const pattern& p);

/// Values of the pattern variables.
using bindings = std::map<std::string, GiNaC::ex>;

struct rule {
    std::string name;  ///< the comment on its line, or "rule N"
    std::string text;  ///< the rule as written
    source_location where;
    pattern lhs, rhs;
};

/// Matches pattern p against e itself (not its subexpressions). On success the
/// bindings and the sign f (+1 or -1) with p(bindings) = f * e: a cross product
/// matched with its arguments swapped, or a triple product with an odd
/// permutation, contributes -1. A vector variable matches any non-zero vector
/// subexpression, a scalar variable any scalar one; a repeated variable must
/// match equal subexpressions.
std::optional<std::pair<bindings, GiNaC::ex>> match(const pattern& p, const GiNaC::ex& e);

/// A match of a sum or product pattern against some of the terms (factors) of
/// e: e = (the matched part) + rest (or * rest), p(b) = sign * matched part.
/// For other patterns (or as many terms as the pattern) rest is 0 (1).
struct partial_match {
    bindings b;
    GiNaC::ex sign;
    GiNaC::ex rest;
};
std::optional<partial_match> match_partial(const pattern& p, const GiNaC::ex& e);

/// The GiNaC expression of p with the variables replaced by their bindings
/// (built with cross/dot/triple and arithmetic, so GiNaC evaluates it).
/// Throws type_error on an unbound variable or an ill-typed result.
GiNaC::ex instantiate(const pattern& p, const bindings& b);

/// Parses and checks the rules of a rule text; `file` names it in messages.
/// Throws syntax_error (where = FILE:LINE:COL) at the first problem.
std::vector<rule> parse_rules(const std::string& text, const std::string& file);

struct rewrite_result {
    GiNaC::ex result;
    std::size_t steps = 0;      ///< rewrites done
    bool bound_hit = false;     ///< a rule still applied when the bound was reached
    const rule* last = nullptr; ///< the last rule applied
};

class rule_set {
public:
    /// Reads, checks and adds the rules of a file. Returns the number added:
    /// 0 for a file already loaded into this set (same canonical path). Throws
    /// syntax_error (FILE:LINE:COL) or, for an unreadable file, domain_error;
    /// nothing is added then.
    std::size_t load_file(const std::string& path);
    /// Adds checked rules (from parse_rules).
    void add(std::vector<rule> r);
    const std::vector<rule>& rules() const { return rules_; }

    /// Applies the rules bottom-up to every subexpression of e (children first;
    /// at each node the first matching rule in load order), pass after pass,
    /// until no rule applies or max_steps rewrites have been done.
    rewrite_result rewrite(const GiNaC::ex& e, std::size_t max_steps = 1000) const;

private:
    std::vector<rule> rules_;
    std::set<std::string> files_;
};

/// The folder of the shipped rule files: $SYMREP_RULES_DIR if set, else
/// SYMREP_SOURCE_DIR/rules when that folder exists (the build tree), else the
/// installed copy (<prefix>/share/symrep/rules, docs/library.md).
std::string default_rules_dir();

/// The shipped rules (default_rules_dir()/vector.rules), read and checked once
/// per process. Throws like rule_set::load_file.
const rule_set& default_rules();

}  // namespace symrep::rules
