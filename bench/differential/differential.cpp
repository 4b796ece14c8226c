// bench/differential/differential.cpp -- the differential test across the solvers
// (bench/differential/harness.h) on any number of cases: the long run of issue 27.6.
//
//   build/symrep_differential [CASES [SEED]]     (default 10000 cases per family, seed 1)
//
// Prints the cases and disagreements per family, and each disagreement with what symrep was
// given; exits 1 if any case disagreed. docs/testing.md records the last long run.
#include <cstdlib>
#include <iostream>
#include <map>

#include "harness.h"

int main(int argc, char** argv) {
    using namespace symrep::differential;
    const int n = argc > 1 ? std::atoi(argv[1]) : 10000;
    const unsigned seed = argc > 2 ? unsigned(std::atol(argv[2])) : 1;
    const std::vector<outcome> cases = all_families(seed, n);
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
