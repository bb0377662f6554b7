// rounding::down and rounding::up, the outward step of every interval
// bound: exactly std::nextafter towards −∞ and +∞ on every double — the
// edges (±0, subnormals, the largest finite, ±∞) and random bit patterns
// over the whole range — with NaN kept; and their exact-zero versions,
// the same except that 0 stays +0.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "zeroset/math/interval.hpp"

namespace zeroset {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

void expect_next_double(double x) {
    // The exact-zero versions keep 0 and step the rest alike.
    const double exact_down = x == 0.0 ? 0.0 : rounding::down(x), exact_up = x == 0.0 ? 0.0 : rounding::up(x);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(rounding::exact_zero_down(x)), std::bit_cast<std::uint64_t>(exact_down)) << x;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(rounding::exact_zero_up(x)), std::bit_cast<std::uint64_t>(exact_up)) << x;
    if (x != x) {
        EXPECT_TRUE(std::isnan(rounding::down(x)));
        EXPECT_TRUE(std::isnan(rounding::up(x)));
        return;
    }
    EXPECT_EQ(std::bit_cast<std::uint64_t>(rounding::down(x)), std::bit_cast<std::uint64_t>(std::nextafter(x, -inf)))
        << x;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(rounding::up(x)), std::bit_cast<std::uint64_t>(std::nextafter(x, inf))) << x;
}

TEST(Rounding, StepsToTheNextDoubleAtTheEdges) {
    constexpr double tiny = std::numeric_limits<double>::denorm_min(), normal = std::numeric_limits<double>::min();
    constexpr double largest = std::numeric_limits<double>::max();
    for (const double x : {0.0, -0.0, tiny, -tiny, normal, -normal, std::nextafter(normal, 0.0), largest, -largest,
                           inf, -inf, 1.0, -1.0, 0.5, std::numeric_limits<double>::quiet_NaN()})
        expect_next_double(x);
}

TEST(Rounding, StepsToTheNextDoubleOnRandomBitPatterns) {
    std::mt19937_64 random(20261207);
    for (int i = 0; i < 200000; ++i) expect_next_double(std::bit_cast<double>(random()));
}

}  // namespace
}  // namespace zeroset
