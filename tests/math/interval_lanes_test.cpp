// IntervalLanes (math/interval_lanes.hpp) against the scalar Interval code:
// every op, in every lane, gives the same bits as the scalar op on that
// lane's intervals, over random intervals mixed with the edge cases (0 and
// −0, infinities, the largest doubles, subnormals and products that
// underflow, empty intervals of every kind). This TU is compiled for the
// build's baseline target; tests/expr/tape_pruner_test.cpp checks the AVX2
// walk of the tape pruner the same way where the CPU has AVX2.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "zeroset/math/interval_lanes.hpp"

namespace zeroset {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

/// Intervals of every kind the ops branch on.
std::vector<Interval> sample_intervals() {
    constexpr double max = std::numeric_limits<double>::max();
    const double edges[] = {0.0,    -0.0,    1.0,      -1.0,     2.5,  -3.75, 1e-310, -1e-310, 1e-160,
                            -1e-160, 1.49e-154, -1.49e-154, 1e300, -1e300, max,  -max,   inf,     -inf};
    std::vector<Interval> out;
    for (double a : edges)
        for (double b : edges)
            if (a <= b) out.push_back({a, b});
    // Empty: NaN bounds, one NaN bound, or lo above hi.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const Interval& empty : {Interval::empty(), Interval{nan, 1.0}, Interval{-1.0, nan}, Interval{2.0, 1.0}})
        out.push_back(empty);
    std::mt19937 random(3);
    std::uniform_real_distribution<double> u(-4.0, 4.0);
    for (int i = 0; i < 200; ++i) {
        const double a = u(random), b = u(random);
        out.push_back({std::min(a, b), std::max(a, b)});
    }
    return out;
}

bool same_bits(const Interval& a, const Interval& b) {
    const bool both_empty = a.is_empty() && b.is_empty();
    return both_empty || (std::bit_cast<std::uint64_t>(a.lo) == std::bit_cast<std::uint64_t>(b.lo) &&
                          std::bit_cast<std::uint64_t>(a.hi) == std::bit_cast<std::uint64_t>(b.hi));
}

/// Runs `lanes` on four lanes taken from the samples in turn and checks each
/// lane against `scalar` on that lane's operands.
template <class Lanes, class Scalar>
void expect_lanes_match(const char* name, Lanes lanes, Scalar scalar) {
    const std::vector<Interval> samples = sample_intervals();
    std::mt19937 random(11);
    std::uniform_int_distribution<std::size_t> pick(0, samples.size() - 1);
    for (int round = 0; round < 3000; ++round) {
        IntervalLanes a, b;
        for (int k = 0; k < IntervalLanes::count; ++k) {
            a.set_lane(k, samples[pick(random)]);
            b.set_lane(k, samples[pick(random)]);
        }
        const IntervalLanes r = lanes(a, b);
        for (int k = 0; k < IntervalLanes::count; ++k) {
            const Interval expected = scalar(a.lane(k), b.lane(k));
            ASSERT_TRUE(same_bits(r.lane(k), expected))
                << name << " lane " << k << " of [" << a.lo[k] << ", " << a.hi[k] << "], [" << b.lo[k] << ", "
                << b.hi[k] << "]: got [" << r.lo[k] << ", " << r.hi[k] << "], expected [" << expected.lo << ", "
                << expected.hi << "]";
        }
    }
}

TEST(IntervalLanes, EveryOpMatchesTheScalarOpBitForBitInEveryLane) {
    using L = const IntervalLanes&;
    using I = Interval;
    expect_lanes_match("+", [](L a, L b) { return a + b; }, [](I a, I b) { return a + b; });
    expect_lanes_match("-", [](L a, L b) { return a - b; }, [](I a, I b) { return a - b; });
    expect_lanes_match("neg", [](L a, L) { return -a; }, [](I a, I) { return -a; });
    expect_lanes_match("*", [](L a, L b) { return a * b; }, [](I a, I b) { return a * b; });
    expect_lanes_match("square", [](L a, L) { return square(a); }, [](I a, I) { return square(a); });
    expect_lanes_match("sqrt", [](L a, L) { return sqrt(a); }, [](I a, I) { return sqrt(a); });
    expect_lanes_match("min", [](L a, L b) { return min(a, b); }, [](I a, I b) { return min(a, b); });
    expect_lanes_match("max", [](L a, L b) { return max(a, b); }, [](I a, I b) { return max(a, b); });
    expect_lanes_match("/", [](L a, L b) { return a / b; }, [](I a, I b) { return a / b; });
    expect_lanes_match("exp", [](L a, L) { return exp(a); }, [](I a, I) { return exp(a); });
    expect_lanes_match("powi", [](L a, L) { return powi(a, -3); }, [](I a, I) { return powi(a, -3); });
    expect_lanes_match("hypot", [](L a, L b) { return hypot(a, b); }, [](I a, I b) { return hypot(a, b); });
}

TEST(IntervalLanes, APointKeepsItsSignedZero) {
    const IntervalLanes negative_zero(-0.0);
    for (int k = 0; k < IntervalLanes::count; ++k) {
        EXPECT_TRUE(std::signbit(negative_zero.lo[k]) && std::signbit(negative_zero.hi[k])) << k;
    }
    EXPECT_TRUE(std::signbit(lane_detail::splat(-0.0)[3]));
}

TEST(IntervalLanes, RoundingStepsOneUlpOutwardLikeTheScalarCode) {
    const double values[] = {1.0, -1.0, 0.0, -0.0, inf, -inf, std::numeric_limits<double>::max(),
                             std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::denorm_min(),
                             std::numeric_limits<double>::quiet_NaN()};
    for (double v : values) {
        const lane_detail::Doubles x = lane_detail::splat(v);
        const double down = lane_detail::down(x)[2], up = lane_detail::up(x)[1];
        EXPECT_EQ(std::bit_cast<std::uint64_t>(down), std::bit_cast<std::uint64_t>(rounding::down(v))) << v;
        EXPECT_EQ(std::bit_cast<std::uint64_t>(up), std::bit_cast<std::uint64_t>(rounding::up(v))) << v;
    }
}

}  // namespace
}  // namespace zeroset
