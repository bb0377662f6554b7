// Interval enclosures checked against an oracle nobody here wrote: MPFI (and
// MPFR, for ops MPFI lacks) at 256 bits. For thousands of random intervals per
// op — varied magnitudes and signs, points, intervals touching or straddling 0
// — zeroset's result must contain the exact range, and must not be absurdly
// wider than it. tan, atan2 and floor are tried across their poles, cut and
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

#include "zeroset/math/interval.hpp"

namespace zeroset {
namespace {

constexpr mpfr_prec_t precision = 256;
constexpr int samples = 4000;
constexpr double inf = std::numeric_limits<double>::infinity();

std::string show(double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    return buffer;
}
std::string show(Interval a) { return "[" + show(a.lo) + ", " + show(a.hi) + "]"; }

/// An MPFI interval at the oracle's precision.
class Mpfi {
public:
    Mpfi() { mpfi_init2(v_, precision); }
    explicit Mpfi(Interval a) : Mpfi() { mpfi_interv_d(v_, a.lo, a.hi); }
    ~Mpfi() { mpfi_clear(v_); }
    Mpfi(const Mpfi&) = delete;
    Mpfi& operator=(const Mpfi&) = delete;
    mpfi_ptr get() { return v_; }

private:
    mpfi_t v_;
};

/// The exact range of an op over its arguments, as a 256-bit hull; possibly empty.
class Range {
public:
    Range() { mpfr_inits2(precision, lo_, hi_, static_cast<mpfr_ptr>(nullptr)); }
    ~Range() { mpfr_clears(lo_, hi_, static_cast<mpfr_ptr>(nullptr)); }
    Range(const Range&) = delete;
    Range& operator=(const Range&) = delete;

    [[nodiscard]] bool empty() const { return empty_; }
    [[nodiscard]] mpfr_srcptr lo() const { return lo_; }
    [[nodiscard]] mpfr_srcptr hi() const { return hi_; }

    void set(mpfi_ptr v) {
        mpfi_get_left(lo_, v);
        mpfi_get_right(hi_, v);
        empty_ = false;
    }
    /// Adds the value f(result, rounding) — computed once rounded down, once up.
    void add(const std::function<void(mpfr_ptr, mpfr_rnd_t)>& f) {
        mpfr_t down, up;
        mpfr_inits2(precision, down, up, static_cast<mpfr_ptr>(nullptr));
        f(down, MPFR_RNDD);
        f(up, MPFR_RNDU);
        if (empty_ || mpfr_less_p(down, lo_)) mpfr_set(lo_, down, MPFR_RNDD);
        if (empty_ || mpfr_greater_p(up, hi_)) mpfr_set(hi_, up, MPFR_RNDU);
        empty_ = false;
        mpfr_clears(down, up, static_cast<mpfr_ptr>(nullptr));
    }
    void add(double v) {
        add([v](mpfr_ptr r, mpfr_rnd_t rnd) { mpfr_set_d(r, v, rnd); });
    }

    [[nodiscard]] std::string str() const {
        if (empty_) return "empty";
        return "[" + show(mpfr_get_d(lo_, MPFR_RNDD)) + ", " + show(mpfr_get_d(hi_, MPFR_RNDU)) + "]";
    }

private:
    mpfr_t lo_, hi_;
    bool empty_ = true;
};

/// Slack for the width check: how much wider than the exact range a result may be.
struct Slack {
    double relative;  // of the bound's magnitude; < 0 skips the width check
    double absolute = 0.0;
};
constexpr Slack tight{1e-14, 1e-300};
constexpr Slack no_width_check{-1.0};

/// `got` contains `want` (soundness) and is at most `slack` wider on each side.
testing::AssertionResult encloses(const std::string& what, Interval got, const Range& want, Slack slack) {
    if (want.empty()) {  // every interval contains the empty set: only tightness can fail
        if (got.is_empty() || slack.relative < 0.0) return testing::AssertionSuccess();
        return testing::AssertionFailure() << what << " = " << show(got) << ", expected empty";
    }
    if (got.is_empty()) return testing::AssertionFailure() << what << " = empty, but the exact range is " << want.str();
    if (mpfr_cmp_d(want.lo(), got.lo) < 0 || mpfr_cmp_d(want.hi(), got.hi) > 0)
        return testing::AssertionFailure()
               << what << " = " << show(got) << " does not contain the exact range " << want.str();
    if (slack.relative >= 0.0) {
        const double lo = mpfr_get_d(want.lo(), MPFR_RNDD), hi = mpfr_get_d(want.hi(), MPFR_RNDU);
        const double lo_limit = lo - (slack.relative * std::abs(lo) + slack.absolute);
        const double hi_limit = hi + (slack.relative * std::abs(hi) + slack.absolute);
        if (got.lo < lo_limit || got.hi > hi_limit)
            return testing::AssertionFailure()
                   << what << " = " << show(got) << " is much wider than the exact range " << want.str();
    }
    return testing::AssertionSuccess();
}

/// Deterministic random numbers from raw generator bits (portable across libraries).
class Random {
public:
    explicit Random(std::uint64_t seed) : rng_(seed) {}

    double unit() { return static_cast<double>(rng_() >> 11) * 0x1p-53; }
    int integer(int lo, int hi) { return lo + static_cast<int>(rng_() % static_cast<std::uint64_t>(hi - lo + 1)); }
    bool coin() { return (rng_() & 1) != 0; }

    /// A double of magnitude 2^[-max_exp, max_exp], either sign; sometimes a small integer.
    double number(int max_exp) {
        if (integer(0, 9) == 0) return static_cast<double>(integer(-4, 4));
        const double m = std::ldexp(1.0 + unit(), integer(-max_exp, max_exp));
        return coin() ? m : -m;
    }

    /// An interval with endpoints of magnitude up to 2^max_exp, of varied shape.
    Interval interval(int max_exp) {
        const double a = number(max_exp), b = number(max_exp);
        switch (integer(0, 9)) {
            case 0:
                return Interval(a);  // a point
            case 1:
                return {0.0, std::abs(a)};  // touches 0 from above
            case 2:
                return {-std::abs(a), 0.0};  // touches 0 from below
            case 3:
                return {-std::abs(a), std::abs(b)};  // straddles 0
            case 4: {                                // narrow
                const double w = std::abs(a) * std::ldexp(1.0, -integer(1, 52));
                return {a, a + w};
            }
            case 5:
                return integer(0, 3) == 0 ? Interval(0.0) : Interval(std::min(a, b), std::max(a, b));
            default:
                return {std::min(a, b), std::max(a, b)};
        }
    }

private:
    std::mt19937_64 rng_;
};

using Mpfi1 = int (*)(mpfi_ptr, mpfi_srcptr);
using Mpfi2 = int (*)(mpfi_ptr, mpfi_srcptr, mpfi_srcptr);

void mpfi_range(Range& r, Mpfi1 f, Interval a) {
    Mpfi x(a), y;
    f(y.get(), x.get());
    r.set(y.get());
}
void mpfi_range(Range& r, Mpfi2 f, Interval a, Interval b) {
    Mpfi x(a), y(b), z;
    f(z.get(), x.get(), y.get());
    r.set(z.get());
}

template <class Op>
void check_binary(const char* name, std::uint64_t seed, int max_exp, Mpfi2 oracle, Op op, Slack slack = tight) {
    Random random(seed);
    for (int i = 0; i < samples; ++i) {
        const Interval a = random.interval(max_exp), b = random.interval(max_exp);
        Range want;
        mpfi_range(want, oracle, a, b);
        ASSERT_TRUE(encloses(show(a) + " " + name + " " + show(b), op(a, b), want, slack));
    }
}

template <class Op>
void check_unary(const char* name, std::uint64_t seed, int max_exp, Mpfi1 oracle, Op op, Slack slack = tight) {
    Random random(seed);
    for (int i = 0; i < samples; ++i) {
        const Interval a = random.interval(max_exp);
        Range want;
        mpfi_range(want, oracle, a);
        ASSERT_TRUE(encloses(std::string(name) + show(a), op(a), want, slack));
    }
}

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
