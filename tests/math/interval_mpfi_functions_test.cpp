// Interval enclosures of the elementary functions checked against MPFI (and
// MPFR, for ops MPFI lacks) at 256 bits, as interval_mpfi_test.cpp does for
// the arithmetic: sin, cos, tan, atan, atan2, floor, hypot, log-sum-exp,
// powi and pow. tan, atan2 and floor are tried across their poles, cut and
// integers, where they jump.
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

/// Intervals for sin and cos: general ones, and narrow or wide ones placed
/// around the peaks and troughs, where a missed extremum would show.
Interval trig_argument(Random& random) {
    switch (random.integer(0, 3)) {
        case 0:
            return random.interval(random.integer(0, 3) == 0 ? 60 : 20);
        default: {
            const double k = static_cast<double>(random.integer(-100000, 100000));
            const double centre = k * std::numbers::pi / 2 + random.number(40) * 1e-12;
            const double width = std::ldexp(random.unit(), -random.integer(0, 50)) * 8.0;
            const double offset = random.unit() * width;
            return {centre - offset, centre - offset + width};
        }
    }
}

template <class Op>
void check_trig(const char* name, std::uint64_t seed, Mpfi1 oracle, Op op) {
    Random random(seed);
    for (int i = 0; i < 2 * samples; ++i) {
        const Interval a = trig_argument(random);
        Range want;
        mpfi_range(want, oracle, a);
        // Far from 0 the peak test has a margin that grows with |a| (sound, looser).
        const bool moderate = std::abs(a.lo) < 1e6 && std::abs(a.hi) < 1e6;
        ASSERT_TRUE(encloses(std::string(name) + show(a), op(a), want, moderate ? Slack{0.0, 1e-10} : no_width_check));
    }
}

TEST(IntervalMpfi, Sin) {
    check_trig("sin", 19, mpfi_sin, [](Interval a) { return sin(a); });
}
TEST(IntervalMpfi, Cos) {
    check_trig("cos", 20, mpfi_cos, [](Interval a) { return cos(a); });
}

TEST(IntervalMpfi, TrigPeaks) {
    EXPECT_EQ(sin(Interval(1.5, 1.6)).hi, 1.0);
    EXPECT_EQ(cos(Interval(-0.1, 0.1)).hi, 1.0);
    EXPECT_EQ(cos(Interval(3.1, 3.2)).lo, -1.0);
    EXPECT_LT(sin(Interval(0.1, 0.2)).hi, 0.2);
    const Interval whole = sin(Interval(0, 7));
    EXPECT_EQ(whole.lo, -1.0);
    EXPECT_EQ(whole.hi, 1.0);
}

/// Intervals around the poles of tan (π/2 + kπ) and, as for sin, anywhere.
TEST(IntervalMpfi, Tan) {
    Random random(30);
    int poles = 0;
    for (int i = 0; i < 2 * samples; ++i) {
        Interval a = trig_argument(random);
        if (random.integer(0, 3) == 0) a = {a.lo + std::numbers::pi / 2, a.hi + std::numbers::pi / 2};
        Range want;
        mpfi_range(want, mpfi_tan, a);
        const Interval got = tan(a);
        const bool moderate = std::abs(a.lo) < 1e6 && std::abs(a.hi) < 1e6;
        if (got.lo == -inf && got.hi == inf) {
            // ℝ is right only if a pole lies in a or within the rounding margin of it.
            ++poles;
            const double margin = 1e-11 * (1.0 + std::abs(a.lo) + std::abs(a.hi));
            Range widened;
            mpfi_range(widened, mpfi_tan, {a.lo - margin, a.hi + margin});
            ASSERT_TRUE(mpfr_inf_p(widened.lo()) || !moderate) << "tan" << show(a) << " = ℝ, but no pole is near";
            continue;
        }
        ASSERT_TRUE(encloses("tan" + show(a), got, want, moderate ? Slack{1e-14, 1e-300} : no_width_check));
    }
    EXPECT_GT(poles, samples / 10);
    EXPECT_EQ(tan(Interval(1.5, 1.6)).hi, inf);  // π/2 inside
    EXPECT_LT(tan(Interval(1.5, 1.57)).hi, 1256.0);
    EXPECT_EQ(tan(Interval(0, 4)).lo, -inf);  // wider than the gap between poles
    EXPECT_TRUE(tan(Interval(1.0, 1.0)).contains(std::tan(1.0)));
}

TEST(IntervalMpfi, Atan) {
    check_unary("atan", 31, 1023, mpfi_atan, [](Interval a) { return atan(a); });
    check_unary("atan", 32, 4, mpfi_atan, [](Interval a) { return atan(a); });
    EXPECT_GE(atan(Interval(-inf, inf)).hi, std::numbers::pi / 2);
    EXPECT_LE(atan(Interval(-inf, inf)).hi, 1.5707963267948970);
}

/// Boxes for atan2(y, x): random, and near the cut (x < 0, y ≈ 0) and the origin.
TEST(IntervalMpfi, Atan2) {
    Random random(33);
    int on_cut = 0;
    for (int i = 0; i < 2 * samples; ++i) {
        Interval y = random.interval(random.coin() ? 4 : 60), x = random.interval(random.coin() ? 4 : 60);
        if (random.integer(0, 3) == 0) {  // a thin box straddling or just missing the cut
            const double w = std::ldexp(random.unit(), -random.integer(0, 40));
            const double c = (random.unit() - 0.5) * 4.0 * w;
            y = {c - w, c + w};
            x = {-x.magnitude() - 1.0, -std::min(std::abs(x.lo), std::abs(x.hi))};
        }
        const Interval got = atan2(y, x);
        Range want;
        if (y.contains(0.0) && x.lo <= 0.0) {
            // The box meets the cut or holds the origin: a signed zero y reaches
            // both π and −π, so the exact range (of the doubles' atan2) is [−π, π].
            ++on_cut;
            want.add([](mpfr_ptr r, mpfr_rnd_t rnd) { mpfr_const_pi(r, rnd); });
            want.add([](mpfr_ptr r, mpfr_rnd_t rnd) {  // −π: π rounded the other way, negated
                mpfr_const_pi(r, rnd == MPFR_RNDD ? MPFR_RNDU : MPFR_RNDD);
                mpfr_neg(r, r, rnd);
            });
        } else {
            mpfi_range(want, mpfi_atan2, y, x);
        }
        ASSERT_TRUE(encloses("atan2(" + show(y) + ", " + show(x) + ")", got, want, Slack{1e-14, 1e-300}));
    }
    EXPECT_GT(on_cut, samples / 4);
    const Interval quadrant = atan2(Interval(1, 2), Interval(1, 2));  // corners atan2(1, 2) … atan2(2, 1)
    EXPECT_LE(quadrant.lo, std::atan2(1.0, 2.0));
    EXPECT_GE(quadrant.hi, std::atan2(2.0, 1.0));
    EXPECT_LT(quadrant.width(), std::atan2(2.0, 1.0) - std::atan2(1.0, 2.0) + 1e-14);
    EXPECT_LE(atan2(Interval(-1, 1), Interval(1, 2)).lo, -std::numbers::pi / 4);  // across y = 0, x > 0: no jump
    EXPECT_GT(atan2(Interval(-1, 1), Interval(1, 2)).lo, -1.0);
}

TEST(IntervalMpfi, FloorIsExact) {
    Random random(34);
    for (int i = 0; i < samples; ++i) {
        const Interval a = random.interval(random.coin() ? 3 : 1023);
        Range want;  // floor is non-decreasing and exact in floating point: the ends floored
        want.add([&a](mpfr_ptr r, mpfr_rnd_t) { mpfr_set_d(r, a.lo, MPFR_RNDN), mpfr_floor(r, r); });
        want.add([&a](mpfr_ptr r, mpfr_rnd_t) { mpfr_set_d(r, a.hi, MPFR_RNDN), mpfr_floor(r, r); });
        ASSERT_TRUE(encloses("floor" + show(a), floor(a), want, Slack{0.0}));
        ASSERT_EQ(floor_may_jump(a), std::floor(a.lo) != std::floor(a.hi)) << show(a);
    }
    EXPECT_EQ(floor(Interval(-0.5, 2.5)).lo, -1.0);
    EXPECT_EQ(floor(Interval(-0.5, 2.5)).hi, 2.0);
    EXPECT_FALSE(floor_may_jump(Interval(2.0, 2.9)));
    EXPECT_TRUE(floor_may_jump(Interval(1.9, 2.0)));
}

TEST(IntervalMpfi, Hypot) {
    check_binary("hypot", 35, 60, mpfi_hypot, [](Interval a, Interval b) { return hypot(a, b); });
    check_binary("hypot", 36, 1023, mpfi_hypot, [](Interval a, Interval b) { return hypot(a, b); });  // overflow
    EXPECT_EQ(hypot(Interval(-1, 2), Interval(-3, 1)).lo, 0.0);
}

/// ln(eᵖ + e^q) at one corner, as max + ln(1 + e^(min − max)): the sum
/// eᵖ + e^q itself would round a tiny e^(min − max) away at 256 bits.
void log_sum_exp_at(mpfi_ptr r, double p, double q) {
    Mpfi tail;
    mpfi_set_d(tail.get(), std::min(p, q));
    mpfi_sub_d(tail.get(), tail.get(), std::max(p, q));
    mpfi_exp(tail.get(), tail.get());
    mpfi_log1p(tail.get(), tail.get());
    mpfi_add_d(r, tail.get(), std::max(p, q));
}
/// The exact range of ln(eˣ + eʸ), increasing in both: from corner to corner.
int mpfi_log_sum_exp(mpfi_ptr r, mpfi_srcptr x, mpfi_srcptr y) {
    Mpfi lower, upper;
    log_sum_exp_at(lower.get(), mpfr_get_d(&x->left, MPFR_RNDN), mpfr_get_d(&y->left, MPFR_RNDN));
    log_sum_exp_at(upper.get(), mpfr_get_d(&x->right, MPFR_RNDN), mpfr_get_d(&y->right, MPFR_RNDN));
    return mpfi_union(r, lower.get(), upper.get());
}

/// Tight where ln(eᵃ + eᵇ) is not near 0; near 0 (a ≈ b ≈ −ln 2) the error
/// of ln(1 + e^−|a−b|) is absolute, a few ulps of ln 2.
TEST(IntervalMpfi, LogSumExp) {
    constexpr Slack near_zero{1e-14, 1e-15};
    check_binary("log-sum-exp", 37, 6, mpfi_log_sum_exp, [](Interval a, Interval b) { return log_sum_exp(a, b); },
                 near_zero);
    check_binary("log-sum-exp", 38, 20, mpfi_log_sum_exp, [](Interval a, Interval b) { return log_sum_exp(a, b); },
                 near_zero);
    // Finite where the written-out ln(exp(a) + exp(b)) overflows.
    const Interval big = log_sum_exp(Interval(800.0, 900.0), Interval(-1.0, 850.0));
    EXPECT_LE(big.lo, 800.0);
    EXPECT_GE(big.hi, 900.0);
    EXPECT_LT(big.hi, 900.0 + 1e-9);
    EXPECT_EQ(log_sum_exp(Interval(-inf, 1.0), Interval(-inf, 2.0)).lo, -inf);
    EXPECT_EQ(log_sum_exp(Interval(0.0, inf), Interval(-1.0, 2.0)).hi, inf);
    EXPECT_TRUE(log_sum_exp(Interval::empty(), Interval(1.0)).is_empty());
}

/// The weight 1/(1 + e^(b−a)) of ∂/∂a encloses its exact range (it is
/// decreasing in b − a) and stays within [0, 1].
TEST(IntervalMpfi, LogSumExpWeight) {
    Random random(39);
    for (int i = 0; i < samples; ++i) {
        const Interval a = random.interval(6), b = random.interval(6);
        const Interval w = log_sum_exp_weight(a, b);
        ASSERT_GE(w.lo, 0.0);
        ASSERT_LE(w.hi, 1.0);
        for (const auto& [x, y] : {std::pair{a.lo, b.hi}, std::pair{a.hi, b.lo}}) {
            Mpfi difference, weight;
            mpfi_set_d(difference.get(), y);
            mpfi_sub_d(difference.get(), difference.get(), x);
            mpfi_exp(weight.get(), difference.get());
            mpfi_add_ui(weight.get(), weight.get(), 1);
            mpfi_ui_div(weight.get(), 1, weight.get());
            Range want;
            want.set(weight.get());
            ASSERT_TRUE(w.lo <= mpfr_get_d(want.lo(), MPFR_RNDD) && mpfr_get_d(want.hi(), MPFR_RNDU) <= w.hi)
                << show(a) << " " << show(b) << " -> " << show(w);
        }
    }
}

/// The exact range of a^n (n an integer) over a's part where it is defined.
void powi_range(Range& want, Interval a, int n) {
    const auto at = [n](double x) {
        return [n, x](mpfr_ptr r, mpfr_rnd_t rnd) {
            mpfr_set_d(r, x, MPFR_RNDN);  // exact: the precision exceeds a double's
            mpfr_pow_si(r, r, n, rnd);
        };
    };
    if (n < 0 && a.contains(0.0)) {
        if (a.lo == 0.0 && a.hi == 0.0) return;  // nowhere defined
        if (n % 2 == 0) {
            want.add(at(std::max(-a.lo, a.hi)));
            return want.add(inf);
        }
        if (a.lo < 0.0)
            want.add(-inf);
        else
            want.add(at(a.hi));
        if (a.hi > 0.0)
            want.add(inf);
        else
            want.add(at(a.lo));
        return;
    }
    // Continuous on a: monotone pieces either side of 0.
    want.add(at(a.lo));
    want.add(at(a.hi));
    if (a.contains(0.0)) want.add(at(0.0));
}

TEST(IntervalMpfi, Powi) {
    Random random(21);
    for (const int n : {0, 1, 2, 3, 4, 5, 6, 7, 10, 15, 31, 64, -1, -2, -3, -4, -7, -10}) {
        for (int i = 0; i < samples / 4; ++i) {
            const Interval a = random.interval(n == 0 ? 100 : std::max(2, 600 / std::abs(n)));
            Range want;
            powi_range(want, a, n);
            // 0^n, n < 0, is nowhere defined; 1/square([0, 0]) = 1/[0, ε] answers [max, ∞]. Loose but sound.
            const bool at_pole = n < 0 && a.lo == 0.0 && a.hi == 0.0;
            ASSERT_TRUE(encloses("powi(" + show(a) + ", " + std::to_string(n) + ")", powi(a, n), want,
                                 at_pole ? no_width_check : tight));
        }
    }
    EXPECT_EQ(powi(Interval(-2, 1), 4).lo, 0.0);
    EXPECT_LE(powi(Interval(-2, 1), 3).lo, -8.0);
    EXPECT_GE(powi(Interval(-2, 1), 3).lo, -8.0 - 1e-14);
    EXPECT_EQ(powi(Interval(0, 2), -1).hi, inf);
    const Interval pole = powi(Interval(0.0), -2);  // nothing finite
    EXPECT_TRUE(pole.is_empty() || pole.lo >= std::numeric_limits<double>::max()) << show(pole);
    EXPECT_TRUE(powi(Interval(0.0), -3).is_empty());
}

/// pow(a, p) for a constant p: powi when p is an integer, otherwise over a ≥ 0.
void pow_range(Range& want, Interval a, Interval b) {
    if (b.lo == b.hi && b.lo == std::round(b.lo) && std::abs(b.lo) < 1e6)
        return powi_range(want, a, static_cast<int>(b.lo));
    if (a.hi < 0.0) return;                          // empty
    const double base_lo = a.lo > 0.0 ? a.lo : 0.0;  // +0: MPFR's (−0)^−3 is −∞
    // x^y is monotone in x for fixed y and in y for fixed x (taking 0^y as its
    // limit, which MPFR does), so the extremes are at the four corners.
    for (const double x : {base_lo, a.hi})
        for (const double y : {b.lo, b.hi})
            want.add([x, y](mpfr_ptr r, mpfr_rnd_t rnd) {
                mpfr_t xm, ym;
                mpfr_inits2(precision, xm, ym, static_cast<mpfr_ptr>(nullptr));
                mpfr_set_d(xm, x, MPFR_RNDN);
                mpfr_set_d(ym, y, MPFR_RNDN);
                mpfr_pow(r, xm, ym, rnd);
                mpfr_clears(xm, ym, static_cast<mpfr_ptr>(nullptr));
            });
}

TEST(IntervalMpfi, PowConstantExponent) {
    Random random(22);
    for (int i = 0; i < samples; ++i) {
        const Interval a = random.interval(20);
        double p = random.number(3);
        if (random.integer(0, 3) == 0) p = std::round(p);  // integral exponents go through powi
        Range want;
        pow_range(want, a, Interval(p));
        const bool at_pole = p < 0.0 && a.lo == 0.0 && a.hi == 0.0;  // as for powi
        ASSERT_TRUE(encloses("pow(" + show(a) + ", " + show(p) + ")", pow(a, Interval(p)), want,
                             at_pole ? no_width_check : Slack{1e-13, 1e-300}));
    }
    EXPECT_TRUE(pow(Interval(-4, -1), Interval(0.5)).is_empty());
    EXPECT_EQ(pow(Interval(-4, 4), Interval(0.5)).lo, 0.0);
    EXPECT_EQ(pow(Interval(-4, 4), Interval(-0.5)).hi, inf);
    EXPECT_EQ(pow(Interval(-2, -1), Interval(3.0)).lo, powi(Interval(-2, -1), 3).lo);
}

TEST(IntervalMpfi, PowIntervalExponent) {
    Random random(23);
    for (int i = 0; i < samples; ++i) {
        const Interval a = random.interval(random.coin() ? 3 : 20);
        const Interval b = random.interval(3);
        Range want;
        pow_range(want, a, b);
        // exp(b·log a) loses about |b·log a| ulps; at a = 0 the hull is deliberately coarse.
        const bool coarse = a.lo <= 0.0;
        ASSERT_TRUE(encloses("pow(" + show(a) + ", " + show(b) + ")", pow(a, b), want,
                             coarse ? no_width_check : Slack{1e-11, 1e-300}));
    }
}


}  // namespace
}  // namespace zeroset
