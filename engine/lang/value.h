// symrep/lang/value.h -- the values of the symrep language.
//
// A value is one of: nothing (a statement with no result), a boolean, a GiNaC
// expression (numbers, symbols, formulas, relations `a = b`, vector expressions),
// a string, a list, an algebra, an element of an algebra, or a Cauchy problem
// (`ode(...)`), or a solution by reduction (solve(P) of a turning frame). Values are immutable and cheap to copy.
#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include <ginac/ginac.h>

#include "symrep/algebra/element.h"
#include "symrep/core/error.h"
#include "symrep/mechanics/cauchy_problem.h"
#include "symrep/mechanics/reduced_solution.h"

namespace symrep::lang {

struct value;
using list = std::vector<value>;
using problem_ptr = std::shared_ptr<const mechanics::cauchy_problem>;
/// A solution by reduction r = F_(-w)(psi) (mechanics/reduced_solution.h), or its
/// derivative r' when `derivative` is set.
struct reduction {
    std::shared_ptr<const mechanics::reduced_solution> solution;
    int derivative = 0;
};

/// Lists may nest at most this deep ([[...]] counts 2): printing, comparing and
/// destroying a value recurse through the nesting.
inline constexpr std::size_t max_list_depth = 1000;

struct value {
    using variant_t = std::variant<std::monostate, bool, GiNaC::ex, std::string,
                                   std::shared_ptr<const list>, algebra_ptr, element, problem_ptr, reduction>;
private:
    std::size_t depth_ = 0;  ///< list nesting depth (0: not a list), cached at construction

    static std::size_t list_depth_of(const list& l);

public:
    variant_t v;

    value() = default;
    value(bool b) : v(b) {}
    value(GiNaC::ex e) : v(std::move(e)) {}
    value(const GiNaC::symbol& s) : v(GiNaC::ex(s)) {}
    value(int k) : v(GiNaC::ex(k)) {}
    value(std::string s) : v(std::move(s)) {}
    value(const char* s) : v(std::string(s)) {}
    /// Throws size_error when the list would nest deeper than max_list_depth.
    value(list l) : depth_(list_depth_of(l)), v(std::make_shared<const list>(std::move(l))) {}
    value(algebra_ptr A) : v(std::move(A)) {}
    value(element w) : v(std::move(w)) {}
    value(problem_ptr p) : v(std::move(p)) {}
    value(reduction r) : v(std::move(r)) {}

    bool is_none() const { return std::holds_alternative<std::monostate>(v); }
    bool is_bool() const { return std::holds_alternative<bool>(v); }
    bool is_ex() const { return std::holds_alternative<GiNaC::ex>(v); }
    bool is_string() const { return std::holds_alternative<std::string>(v); }
    bool is_list() const { return std::holds_alternative<std::shared_ptr<const list>>(v); }
    bool is_algebra() const { return std::holds_alternative<algebra_ptr>(v); }
    bool is_element() const { return std::holds_alternative<element>(v); }
    bool is_problem() const { return std::holds_alternative<problem_ptr>(v); }
    bool is_reduction() const { return std::holds_alternative<reduction>(v); }

    bool as_bool() const { return std::get<bool>(v); }
    const GiNaC::ex& as_ex() const { return std::get<GiNaC::ex>(v); }
    const std::string& as_string() const { return std::get<std::string>(v); }
    const list& as_list() const { return *std::get<std::shared_ptr<const list>>(v); }
    const algebra_ptr& as_algebra() const { return std::get<algebra_ptr>(v); }
    const element& as_element() const { return std::get<element>(v); }
    const mechanics::cauchy_problem& as_problem() const { return *std::get<problem_ptr>(v); }
    const problem_ptr& problem_pointer() const { return std::get<problem_ptr>(v); }
    const reduction& as_reduction() const { return std::get<reduction>(v); }

    /// "nothing", "boolean", "expression", "string", "list", "algebra", "element", "problem", "solution".
    std::string kind() const;
    /// kind() with its article: "an expression", "a list", ...
    std::string a_kind() const;
    /// Nesting depth of a list value ([] is 1, [[1]] is 2); 0 for other values.
    std::size_t list_depth() const { return is_list() ? depth_ : 0; }
};

inline std::size_t value::list_depth_of(const list& l) {
    std::size_t d = 0;
    for (const value& x : l) d = std::max(d, x.list_depth());
    if (d + 1 > max_list_depth)
        throw size_error("lists nest more than " + std::to_string(max_list_depth) + " deep");
    return d + 1;
}

}  // namespace symrep::lang
