// binary_exponent and times_power_of_two (math/power_of_two.hpp) give
// std::ilogb's and std::ldexp's results bit for bit: on normal numbers, at
// the edges of the exponent range, into and out of subnormals, and on zeros,
// infinities and NaN.
#include "zeroset/math/power_of_two.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace zeroset {
namespace {

using limits = std::numeric_limits<double>;

bool same_bits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b) || (std::isnan(a) && std::isnan(b));
}

std::vector<double> samples() {
    std::vector<double> v{0.0,          -0.0,         1.0,          -1.0,         0.75,          3.0,
                          limits::min(), limits::denorm_min(), 0x1.8p-1030, limits::max(), -limits::max(),
                          limits::infinity(), -limits::infinity(), limits::quiet_NaN(), 1e300, 1e-300};
    std::mt19937_64 random(7);
    for (int i = 0; i < 2000; ++i) {
        const double u = std::bit_cast<double>(random());  // every exponent, sign and payload
        v.push_back(u);
    }
    return v;
}

TEST(PowerOfTwo, BinaryExponentIsIlogb) {
    for (const double v : samples()) EXPECT_EQ(binary_exponent(v), std::ilogb(v)) << std::hexfloat << v;
}

TEST(PowerOfTwo, TimesPowerOfTwoIsLdexp) {
    for (const double v : samples()) {
        for (const int e : {-2200, -1100, -1075, -1074, -1023, -1022, -1021, -60, -1, 0, 1, 60, 1022, 1023, 1024, 2200}) {
            EXPECT_TRUE(same_bits(times_power_of_two(v, e), std::ldexp(v, e))) << std::hexfloat << v << " e " << e;
        }
    }
}

}  // namespace
}  // namespace zeroset
