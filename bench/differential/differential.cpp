// bench/differential/differential.cpp -- the differential test across the solvers
// (bench/differential/harness.h) on any number of cases: the long run of issue 27.6.
//
//   build/symrep_differential [CASES [SEED [FAMILY]]]   (default 10000 cases per family, seed 1)
//
// FAMILY (constant_w, response, algebra_exp, laplace, fixed_axis) runs that family alone, on the
// seed and with the count it has in the full run (laplace n/2, fixed_axis n/4), so that its cases
// are the same as there.
// Prints the cases and disagreements per family, and each disagreement with what symrep was
// given; exits 1 if any case disagreed. docs/testing.md records the last long run.
#include <cstdlib>
#include <iostream>
#include <algorithm>
#include <map>
#include <string>

#include "harness.h"

int main(int argc, char** argv) {
    using namespace symrep::differential;
    const int n = argc > 1 ? std::atoi(argv[1]) : 10000;
    const unsigned seed = argc > 2 ? unsigned(std::atol(argv[2])) : 1;
    const std::string only = argc > 3 ? argv[3] : "";
    std::vector<outcome> cases;
    if (only.empty()) cases = all_families(seed, n);  // the seeds as all_families draws them
    else if (only == "constant_w") cases = constant_w_family(seed, n);
    else if (only == "response") cases = response_family(seed + 1, n);
    else if (only == "algebra_exp") cases = algebra_exp_family(seed + 2, n);
    else if (only == "laplace") cases = laplace_family(seed + 3, std::max(1, n / 2));
    else if (only == "fixed_axis") cases = fixed_axis_family(seed + 4, std::max(1, n / 4));
    else {
        std::cerr << "symrep_differential: unknown family " << only
                  << " (constant_w, response, algebra_exp, laplace, fixed_axis)\n";
        return 2;
    }
    std::map<std::string, std::pair<int, int>> tally;
    int failed = 0;
    for (const outcome& o : cases) {
        auto& t = tally[o.family];
        ++t.first;
        if (!o.agreed()) {
            ++t.second;
            ++failed;
            std::cout << "[" << o.family << "] difference " << o.difference << " (tolerance " << o.tolerance << ")"
                      << (o.error.empty() ? "" : ", error: " + o.error.substr(0, 400)) << "\n"
                      << o.statements << "\n\n";
        }
    }
    for (const auto& [family, t] : tally)
        std::cout << family << ": " << t.first << " cases, " << t.second << " disagreements\n";
    std::cout << cases.size() << " cases, " << failed << " disagreements\n";
    return failed ? 1 : 0;
}
