// The plain-number functions of math/scalar.hpp where they are subtle:
// powi over the whole int range, and min/max carrying NaN from either side.
#include <gtest/gtest.h>

#include <climits>
#include <cmath>
#include <limits>

#include "zeroset/math/scalar.hpp"

namespace zeroset {
namespace {

TEST(Scalar, PowiCoversTheWholeIntRange) {
    EXPECT_EQ(powi(2.0, 10), 1024.0);
    EXPECT_EQ(powi(-2.0, 3), -8.0);
    EXPECT_EQ(powi(2.0, -2), 0.25);
    EXPECT_EQ(powi(1.0, INT_MIN), 1.0);   // |INT_MIN| does not fit an int
    EXPECT_EQ(powi(-1.0, INT_MIN), 1.0);  // an even power
    EXPECT_EQ(powi(-1.0, INT_MAX), -1.0);
    EXPECT_EQ(powi(2.0, INT_MIN), 0.0);
    EXPECT_EQ(powi(0.5f, INT_MIN), std::numeric_limits<float>::infinity());
}

TEST(Scalar, MinAndMaxCarryNaNFromEitherSide) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(std::isnan(min(nan, 1.0)));
    EXPECT_TRUE(std::isnan(min(1.0, nan)));
    EXPECT_TRUE(std::isnan(max(nan, 1.0)));
    EXPECT_TRUE(std::isnan(max(1.0, nan)));
    EXPECT_EQ(min(1.0, 2.0), 1.0);
    EXPECT_EQ(max(1.0f, 2.0f), 2.0f);
}

}  // namespace
}  // namespace zeroset
