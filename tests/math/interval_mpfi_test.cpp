// Interval enclosures checked against an oracle nobody here wrote: MPFI (and
// MPFR, for ops MPFI lacks) at 256 bits. For thousands of random intervals per
// op — varied magnitudes and signs, points, intervals touching or straddling 0
// — zeroset's result must contain the exact range, and must not be absurdly
// wider than it. Here the arithmetic, square, sqrt, exp, log, min, max and
// the edges (infinite ends, empty intervals); the other functions in
// interval_mpfi_functions_test.cpp.
#include <gtest/gtest.h>
#include <mpfi.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <string>

#include "mpfi_interval_oracle.hpp"
#include "zeroset/math/interval.hpp"

namespace zeroset {
namespace {

using namespace mpfi_oracle;

TEST(IntervalMpfi, Add) {
    check_binary("+", 1, 60, mpfi_add, [](Interval a, Interval b) { return a + b; });
    check_binary("+", 2, 1023, mpfi_add, [](Interval a, Interval b) { return a + b; });  // overflow, cancellation
}

TEST(IntervalMpfi, Sub) {
    check_binary("-", 3, 60, mpfi_sub, [](Interval a, Interval b) { return a - b; });
    check_binary("-", 4, 1023, mpfi_sub, [](Interval a, Interval b) { return a - b; });
}

TEST(IntervalMpfi, Mul) {
    check_binary("*", 5, 60, mpfi_mul, [](Interval a, Interval b) { return a * b; });
    check_binary("*", 6, 700, mpfi_mul, [](Interval a, Interval b) { return a * b; });  // overflow, underflow
}

TEST(IntervalMpfi, ExactZerosStayZero) {
    // A sum that rounds to 0 is exact, and so is a product with a zero factor:
    // their bounds stay 0 instead of stepping to subnormals (slow on x86).
    const auto is_zero = [](Interval v) { return v.lo == 0.0 && v.hi == 0.0; };
    EXPECT_TRUE(is_zero(Interval(0.0) + Interval(0.0)));
    EXPECT_TRUE(is_zero(Interval(0.3) - Interval(0.3)));
    EXPECT_TRUE(is_zero(Interval(0.0) * Interval(-3.0, 5.0)));
    EXPECT_TRUE(is_zero(Interval(-3.0, 5.0) * Interval(0.0)));
    EXPECT_TRUE(is_zero(Interval(0.0) * Interval::entire()));  // 0 × ∞ = 0
    const Interval spread = Interval(-0.25, 0.5) - Interval(0.5);
    EXPECT_EQ(spread.hi, 0.0);
    EXPECT_LT(spread.lo, -0.75);
    // A product that underflows is not exact: its tiny value stays enclosed,
    // by the smallest normal double rather than a subnormal.
    const Interval positive = Interval(1e-200) * Interval(1e-200);
    EXPECT_EQ(positive.lo, 0.0);
    EXPECT_EQ(positive.hi, std::numeric_limits<double>::min());
    const Interval negative = Interval(-1e-200) * Interval(1e-200);
    EXPECT_EQ(negative.lo, -std::numeric_limits<double>::min());
    EXPECT_EQ(negative.hi, 0.0);
    const Interval partly = Interval(1e-160, 1e-100) * Interval(1e-160, 1e-150);
    EXPECT_EQ(partly.lo, 0.0);
    EXPECT_GE(partly.hi, 1e-250);
}

TEST(IntervalMpfi, NoBoundIsSubnormal) {
    // Products and exponentials near the smallest normal double: enclosed
    // (long double holds these values exactly enough), and never a
    // subnormal bound, whose arithmetic costs a microcode assist.
    const auto normal_or_zero = [](double v) { return std::fpclassify(v) != FP_SUBNORMAL; };
    for (double x = -709.5; x <= -707.5; x += 1.0 / 64.0) {
        const Interval e = exp(Interval(x));
        const long double want = std::exp(static_cast<long double>(x));
        ASSERT_TRUE(e.lo <= want && want <= e.hi) << "exp(" << x << ")";
        ASSERT_TRUE(normal_or_zero(e.lo) && normal_or_zero(e.hi)) << "exp(" << x << ")";
        for (const double factor : {1.0, 0.5, 1e-3, 1e-300}) {
            const Interval p = e * Interval(factor);
            const long double exact = want * static_cast<long double>(factor);
            ASSERT_TRUE(p.lo <= exact && exact <= p.hi) << "exp(" << x << ") * " << factor;
            ASSERT_TRUE(normal_or_zero(p.lo) && normal_or_zero(p.hi)) << "exp(" << x << ") * " << factor;
        }
    }
}

/// The exact range of a / b over b's nonzero part (MPFI answers ℝ for a divisor
/// [0, 0], where the quotient is nowhere defined, and for 0 / b, which is 0).
void division_range(Range& want, Interval a, Interval b) {
    if (b.lo == 0.0 && b.hi == 0.0) return;  // empty
    if (a.lo == 0.0 && a.hi == 0.0) return want.add(0.0);
    mpfi_range(want, mpfi_div, a, b);
}

TEST(IntervalMpfi, Div) {
    for (const int max_exp : {30, 600}) {
        Random random(static_cast<std::uint64_t>(7 + max_exp));
        int divisor_with_zero = 0;
        for (int i = 0; i < samples; ++i) {
            const Interval a = random.interval(max_exp), b = random.interval(max_exp);
            divisor_with_zero += b.contains(0.0);
            Range want;
            division_range(want, a, b);
            // 0 / b with 0 ∈ b is deliberately loose (answers [0, ∞] or ℝ).
            const bool loose = a.lo == 0.0 && a.hi == 0.0 && b.contains(0.0);
            ASSERT_TRUE(encloses(show(a) + " / " + show(b), a / b, want, loose ? no_width_check : tight));
        }
        EXPECT_GT(divisor_with_zero, samples / 4);  // the zero cases really are exercised
    }
}

TEST(IntervalMpfi, DivisorContainingZero) {
    const struct {
        Interval a, b, expected;
    } cases[] = {
        {{1, 2}, {0, 4}, {0.25, inf}},    {{1, 2}, {-4, 0}, {-inf, -0.25}}, {{-2, -1}, {0, 4}, {-inf, -0.25}},
        {{-2, -1}, {-4, 0}, {0.25, inf}}, {{-1, 2}, {0, 4}, {-inf, inf}},   {{1, 2}, {-1, 4}, {-inf, inf}},
        {{0, 2}, {0, 4}, {0, inf}},       {{-2, 0}, {-4, 0}, {0, inf}},     {{0, 2}, {-4, 0}, {-inf, 0}},
    };
    // Infinite and zero ends are exact; finite quotients are rounded outward by an ulp or so.
    const auto near_below = [](double got, double want) {
        return got == want || (got < want && got >= want - 1e-15 * std::abs(want));
    };
    for (const auto& c : cases) {
        const Interval q = c.a / c.b;
        EXPECT_TRUE(near_below(q.lo, c.expected.lo)) << show(c.a) << " / " << show(c.b) << " = " << show(q);
        EXPECT_TRUE(near_below(-q.hi, -c.expected.hi)) << show(c.a) << " / " << show(c.b) << " = " << show(q);
    }
    EXPECT_TRUE((Interval(1, 2) / Interval(0.0)).is_empty());
    EXPECT_TRUE((Interval(-1, 2) / Interval(0.0)).is_empty());
    EXPECT_TRUE((Interval(0.0) / Interval(0.0)).is_empty());
}

TEST(IntervalMpfi, Neg) {
    check_unary("-", 11, 1023, mpfi_neg, [](Interval a) { return -a; });
}

TEST(IntervalMpfi, Abs) {
    check_unary("abs", 12, 1023, mpfi_abs, [](Interval a) { return abs(a); });
}

TEST(IntervalMpfi, SquareIsTight) {
    check_unary("square", 13, 600, mpfi_sqr, [](Interval a) { return square(a); });
    Random random(14);
    for (int i = 0; i < samples; ++i) {
        const Interval a = random.interval(60);
        const Interval s = square(a);
        if (a.contains(0.0)) {
            ASSERT_EQ(s.lo, 0.0) << "square" << show(a);  // not a·a = [lo·hi, …] < 0
        } else {
            ASSERT_GT(s.lo, 0.0) << "square" << show(a);
        }
    }
    EXPECT_EQ(square(Interval(-3, 2)).lo, 0.0);
    EXPECT_GE(square(Interval(-3, 2)).hi, 9.0);
    EXPECT_LE(square(Interval(-3, 2)).hi, 9.0 + 1e-14);
}

TEST(IntervalMpfi, SqrtClipsItsDomain) {
    Random random(15);
    for (int i = 0; i < samples; ++i) {
        const Interval a = random.interval(1000);
        Range want;
        if (a.hi >= 0.0) mpfi_range(want, mpfi_sqrt, {std::max(a.lo, 0.0), a.hi});
        ASSERT_TRUE(encloses("sqrt" + show(a), sqrt(a), want, tight));
        if (a.lo <= 0.0 && a.hi >= 0.0) {
            ASSERT_EQ(sqrt(a).lo, 0.0) << "sqrt" << show(a);
        }
    }
    const Interval s = sqrt(Interval(-1, 4));
    EXPECT_EQ(s.lo, 0.0);
    EXPECT_GE(s.hi, 2.0);
    EXPECT_LE(s.hi, 2.0 + 1e-15);
    EXPECT_TRUE(sqrt(Interval(-4, -1)).is_empty());
    EXPECT_TRUE((sqrt(Interval(-4, -1)) + Interval(1, 2)).is_empty());  // empty propagates
}

TEST(IntervalMpfi, Exp) {
    check_unary("exp", 16, 10, mpfi_exp, [](Interval a) { return exp(a); });  // up to |a| ≈ 2048: overflow, underflow
    check_unary("exp", 17, 3, mpfi_exp, [](Interval a) { return exp(a); });
}

TEST(IntervalMpfi, LogClipsItsDomain) {
    Random random(18);
    for (int i = 0; i < samples; ++i) {
        const Interval a = random.interval(1000);
        Range want;
        if (a.hi >= 0.0) mpfi_range(want, mpfi_log, {std::max(a.lo, 0.0), a.hi});
        ASSERT_TRUE(encloses("log" + show(a), log(a), want, tight));
    }
    EXPECT_EQ(log(Interval(-1, 1)).lo, -inf);
    EXPECT_TRUE(log(Interval(-2, -1)).is_empty());
}


TEST(IntervalMpfi, MinMaxAreExact) {
    Random random(24);
    for (int i = 0; i < samples; ++i) {
        const Interval a = random.interval(1023), b = random.interval(1023);
        Range want_min, want_max;
        // min and max are monotone in both arguments: the range is spanned by the corners.
        want_min.add(std::min(a.lo, b.lo));
        want_min.add(std::min(a.hi, b.hi));
        want_max.add(std::max(a.lo, b.lo));
        want_max.add(std::max(a.hi, b.hi));
        ASSERT_TRUE(encloses("min(" + show(a) + ", " + show(b) + ")", min(a, b), want_min, Slack{0.0}));
        ASSERT_TRUE(encloses("max(" + show(a) + ", " + show(b) + ")", max(a, b), want_max, Slack{0.0}));
    }
}

TEST(IntervalMpfi, InfiniteEndpoints) {
    const Interval pos{1, inf}, all = Interval::entire();
    EXPECT_EQ((pos + Interval(-1, 2)).hi, inf);
    EXPECT_GE((pos + Interval(-1, 2)).lo, -1e-15);
    EXPECT_LE((pos + Interval(-1, 2)).lo, 0.0);
    const Interval p = Interval(0, 1) * pos;  // 0 · ∞ = 0: the range is [0, ∞)
    EXPECT_LE(p.lo, 0.0);
    EXPECT_GE(p.lo, -1e-300);
    EXPECT_EQ(p.hi, inf);
    EXPECT_EQ(exp(Interval(-inf, 0)).lo, 0.0);
    EXPECT_GE(exp(Interval(-inf, 0)).hi, 1.0);
    EXPECT_EQ(log(Interval(0, inf)).lo, -inf);
    EXPECT_EQ(log(Interval(0, inf)).hi, inf);
    EXPECT_EQ(sin(all).lo, -1.0);
    EXPECT_EQ(sin(all).hi, 1.0);
    EXPECT_TRUE(all.contains(square(all)));
    EXPECT_EQ(square(all).lo, 0.0);
}

TEST(IntervalMpfi, EmptyPropagates) {
    const Interval e = Interval::empty(), a(1, 2);
    for (const Interval r : {e + a, a - e, e * a, a / e, -e, square(e), sqrt(e), abs(e), exp(e), log(e), sin(e), cos(e),
                             tan(e), atan(e), atan2(e, a), atan2(a, e), floor(e), hypot(e, a), powi(e, 3), pow(e, a),
                             pow(a, e), min(e, a), max(a, e)})
        EXPECT_TRUE(r.is_empty()) << show(r);
    EXPECT_FALSE(e.contains(0.0));
}

}  // namespace
}  // namespace zeroset
