// bench/differential/families.h -- every family of the differential test (issue 27.6) by
// name, for bench/differential/differential.cpp and tests/test_differential.cpp.
#pragma once

#include <set>
#include <sstream>

#include "compiled.h"
#include "frames.h"
#include "harness.h"

namespace symrep::differential {

/// The families by name, each with its share of `n` (the slower ones run fewer cases):
///   constant_w (with solve(P, values) on every fourth case), constant_w_general (without),
///   response (orders 2 and 3), response2 (order 2), laplace (n/2), algebra_exp,
///   fixed_axis (n/4), turning_w (n/2), charge (n/4), kepler (n/2), relative_motion,
///   compiled (n/4, three outcomes each).
/// `only`: a comma-separated list of names (empty: every family except the two variants
/// constant_w_general and response2).
inline std::vector<outcome> all_families(unsigned seed, int n, const std::string& only = "") {
    std::set<std::string> chosen;
    std::stringstream ss(only);
    for (std::string name; std::getline(ss, name, ',');)
        if (!name.empty()) chosen.insert(name);
    const std::vector<std::pair<std::string, std::function<std::vector<outcome>(unsigned)>>> families{
        {"constant_w", [n](unsigned s) { return constant_w_family(s, n); }},
        {"constant_w_general", [n](unsigned s) { return constant_w_family(s, n, false); }},
        {"response", [n](unsigned s) { return response_family(s, n); }},
        {"response2", [n](unsigned s) { return response_family(s, n, 2); }},
        {"algebra_exp", [n](unsigned s) { return algebra_exp_family(s, n); }},
        {"laplace", [n](unsigned s) { return laplace_family(s, std::max(1, n / 2)); }},
        {"fixed_axis", [n](unsigned s) { return fixed_axis_family(s, std::max(1, n / 4)); }},
        {"turning_w", [n](unsigned s) { return turning_w_family(s, std::max(1, n / 2)); }},
        {"charge", [n](unsigned s) { return charge_family(s, std::max(1, n / 4)); }},
        {"kepler", [n](unsigned s) { return kepler_family(s, std::max(1, n / 2)); }},
        {"relative_motion", [n](unsigned s) { return relative_motion_family(s, n); }},
        {"compiled", [n](unsigned s) { return compiled_family(s, std::max(1, n / 4)); }},
    };
    for (const std::string& name : chosen)
        if (std::none_of(families.begin(), families.end(), [&](const auto& f) { return f.first == name; }))
            throw std::invalid_argument("no differential family '" + name + "'");
    std::vector<outcome> out;
    // seeds as before the filter: constant_w seed, response seed + 1, algebra_exp + 2, laplace + 3,
    // fixed_axis + 4; the families added later + 5 ...
    const std::map<std::string, unsigned> offset{{"constant_w", 0}, {"constant_w_general", 0}, {"response", 1},
                                                 {"response2", 1},  {"algebra_exp", 2},        {"laplace", 3},
                                                 {"fixed_axis", 4}, {"turning_w", 5},          {"charge", 6},
                                                 {"kepler", 7},     {"relative_motion", 8},    {"compiled", 9}};
    for (const auto& [name, run] : families) {
        const bool variant = name == "constant_w_general" || name == "response2";
        if (chosen.empty() ? variant : !chosen.count(name)) continue;
        try {
            auto r = run(seed + offset.at(name));
            out.insert(out.end(), r.begin(), r.end());
        } catch (const std::exception& e) {  // a reference that failed outside a case's guard
            outcome o;
            o.family = name;
            o.difference = -1;
            o.error = std::string("the family ended (its cases are lost): ") + e.what();
            out.push_back(o);
        }
    }
    return out;
}

}  // namespace symrep::differential
