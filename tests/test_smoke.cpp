#include <gtest/gtest.h>
#include "algebra/walsh_hadamard.h"
TEST(WalshHadamard, InvolutionUpToScale) {
    std::vector<double> a{1, 2, 3, 4, 5, 6, 7, 8}, b = a;
    symrep::fwht(b); symrep::fwht(b);
    for (std::size_t k = 0; k < a.size(); ++k) EXPECT_DOUBLE_EQ(b[k], 8 * a[k]);
}
