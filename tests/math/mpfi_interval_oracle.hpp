// The MPFI oracle the interval tests share (interval_mpfi_test.cpp for the
// arithmetic, interval_mpfi_functions_test.cpp for the elementary
// functions): 256-bit MPFI intervals, the exact range of an op as their
// hull, the containment-and-width check, and portable random intervals.
#pragma once

#include <gtest/gtest.h>
#include <mpfi.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>

#include "zeroset/math/interval.hpp"

namespace zeroset::mpfi_oracle {

constexpr mpfr_prec_t precision = 256;
constexpr int samples = 4000;
constexpr double inf = std::numeric_limits<double>::infinity();

inline std::string show(double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    return buffer;
}
inline std::string show(Interval a) { return "[" + show(a.lo) + ", " + show(a.hi) + "]"; }

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
inline testing::AssertionResult encloses(const std::string& what, Interval got, const Range& want, Slack slack) {
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

inline void mpfi_range(Range& r, Mpfi1 f, Interval a) {
    Mpfi x(a), y;
    f(y.get(), x.get());
    r.set(y.get());
}
inline void mpfi_range(Range& r, Mpfi2 f, Interval a, Interval b) {
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


}  // namespace zeroset::mpfi_oracle
