// IntervalLanes: four intervals side by side — one tape walk encloses f over
// four boxes (a slice tile's four sub-tiles), so the op dispatch and the
// loads of a clause are paid once for the four.
//
// Every lane gives exactly the bits math/interval.hpp gives for that lane on
// its own: the common ops (+, −, ×, min, max, neg, square, sqrt) are written
// branch-free on GCC vectors of four doubles (SIMD code: two SSE2 or one
// AVX2 instruction an operation), with the same formulas and the same
// outward rounding; a product where some lane needs the scalar code's
// careful path (a bound at 0, ∞ or an underflow), and every other op, runs
// the scalar Interval code lane by lane. Everything here is forced inline:
// code compiled for AVX2 calls it, and a 256-bit vector passed to an
// out-of-line copy built without AVX would cross an ABI boundary.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "zeroset/math/interval.hpp"

namespace zeroset {

// Aligned to 32 bytes in every build: without AVX, GCC would align the
// vectors to 16 only, and code compiled for AVX (expr/tape_pruner.cpp)
// loads them as aligned 32-byte vectors.
struct alignas(32) IntervalLanes {
    static constexpr int count = 4;
    using Doubles = double __attribute__((vector_size(32)));
    using Bits = std::uint64_t __attribute__((vector_size(32)));
    using Mask = std::int64_t __attribute__((vector_size(32)));  // a comparison's lanes: −1 true, 0 false

    Doubles lo{};
    Doubles hi{};

    IntervalLanes() = default;
    IntervalLanes(Doubles lo_, Doubles hi_) : lo(lo_), hi(hi_) {}
    /// Every lane the point interval v.
    explicit IntervalLanes(double v) : lo(Doubles{v, v, v, v}), hi(Doubles{v, v, v, v}) {}

    [[nodiscard]] Interval lane(int k) const { return {lo[k], hi[k]}; }
    void set_lane(int k, Interval v) {
        lo[k] = v.lo;
        hi[k] = v.hi;
    }
};

namespace lane_detail {

using Doubles = IntervalLanes::Doubles;
using Mask = IntervalLanes::Mask;

[[gnu::always_inline]] inline Doubles splat(double v) { return Doubles{v, v, v, v}; }  // not 0 + v, which loses −0
[[gnu::always_inline]] inline bool all(Mask m) { return (m[0] & m[1] & m[2] & m[3]) != 0; }

/// rounding::down in every lane: the next double towards −∞, with NaN and
/// −∞ kept and ±0 going to the negative smallest subnormal.
[[gnu::always_inline]] inline Doubles down(Doubles x) {
    const auto bits = std::bit_cast<IntervalLanes::Bits>(x);
    const auto stepped = std::bit_cast<Doubles>(bits - 1 + ((bits >> 63) << 1));  // −1 ulp above 0, +1 below
    const Doubles kept = ((x != x) | (x == -std::numeric_limits<double>::infinity())) ? x : stepped;
    return x == 0.0 ? splat(-std::numeric_limits<double>::denorm_min()) : kept;
}
[[gnu::always_inline]] inline Doubles up(Doubles x) { return -down(-x); }
[[gnu::always_inline]] inline Doubles exact_zero_down(Doubles x) { return x == 0.0 ? splat(0.0) : down(x); }
[[gnu::always_inline]] inline Doubles exact_zero_up(Doubles x) { return x == 0.0 ? splat(0.0) : up(x); }
/// std::min and std::max as the scalar code calls them (the first argument
/// when neither is below the other: the same signed zero, the same NaN).
[[gnu::always_inline]] inline Doubles min(Doubles a, Doubles b) { return b < a ? b : a; }
[[gnu::always_inline]] inline Doubles max(Doubles a, Doubles b) { return a < b ? b : a; }
/// The lanes where an interval is empty (NaN bounds).
[[gnu::always_inline]] inline Mask empty(const IntervalLanes& a) { return !(a.lo <= a.hi); }

/// The scalar function applied lane by lane.
template <class F>
[[gnu::always_inline]] inline IntervalLanes each_lane(const IntervalLanes& a, F f) {
    IntervalLanes r;
    for (int k = 0; k < IntervalLanes::count; ++k) r.set_lane(k, f(a.lane(k)));
    return r;
}
template <class F>
[[gnu::always_inline]] inline IntervalLanes each_lane(const IntervalLanes& a, const IntervalLanes& b, F f) {
    IntervalLanes r;
    for (int k = 0; k < IntervalLanes::count; ++k) r.set_lane(k, f(a.lane(k), b.lane(k)));
    return r;
}

}  // namespace lane_detail

[[gnu::always_inline]] inline IntervalLanes operator+(const IntervalLanes& a, const IntervalLanes& b) {
    return {lane_detail::exact_zero_down(a.lo + b.lo), lane_detail::exact_zero_up(a.hi + b.hi)};
}

[[gnu::always_inline]] inline IntervalLanes operator-(const IntervalLanes& a, const IntervalLanes& b) {
    return {lane_detail::exact_zero_down(a.lo - b.hi), lane_detail::exact_zero_up(a.hi - b.lo)};
}

[[gnu::always_inline]] inline IntervalLanes operator-(const IntervalLanes& a) { return {-a.hi, -a.lo}; }

/// The scalar operator*'s fast path when it applies in every lane (both
/// operands non-empty, every product normal or infinite, no 0 × ∞); else
/// the scalar code lane by lane.
[[gnu::always_inline]] inline IntervalLanes operator*(const IntervalLanes& a, const IntervalLanes& b) {
    using lane_detail::max;
    using lane_detail::min;
    constexpr double tiny = std::numeric_limits<double>::min();
    const lane_detail::Doubles p0 = a.lo * b.lo, p1 = a.lo * b.hi, p2 = a.hi * b.lo, p3 = a.hi * b.hi;
    // std::min({p0, p1, p2, p3}) keeps the first of equals, as these do.
    const lane_detail::Doubles lo = min(min(min(p0, p1), p2), p3), hi = max(max(max(p0, p1), p2), p3);
    const lane_detail::Doubles sum = p0 + p1 + p2 + p3;
    const lane_detail::Mask fast = ((lo > tiny) | (lo < -tiny)) & ((hi > tiny) | (hi < -tiny)) & (sum == sum) &
                                   ~lane_detail::empty(a) & ~lane_detail::empty(b);
    if (lane_detail::all(fast)) return {lane_detail::down(lo), lane_detail::up(hi)};
    return lane_detail::each_lane(a, b, [](Interval x, Interval y) { return x * y; });
}

[[gnu::always_inline]] inline IntervalLanes square(const IntervalLanes& a) {
    using lane_detail::splat;
    const lane_detail::Doubles lo = a.lo, hi = a.hi;
    const lane_detail::Doubles low_square = lo * lo, high_square = hi * hi;
    // lo ≥ 0: [lo², hi²]; hi ≤ 0: [hi², lo²]; across 0: [0, max(−lo, hi)²].
    const lane_detail::Doubles m = lane_detail::max(-lo, hi);
    const lane_detail::Doubles from = lo >= 0.0 ? low_square : high_square;
    const lane_detail::Doubles to = lo >= 0.0 ? high_square : hi <= 0.0 ? low_square : m * m;
    const lane_detail::Doubles rounded_from = lane_detail::max(splat(0.0), lane_detail::down(from));
    const lane_detail::Mask empty = lane_detail::empty(a);
    return {empty ? lo : ((lo >= 0.0) | (hi <= 0.0)) ? rounded_from : splat(0.0), empty ? hi : lane_detail::up(to)};
}

[[gnu::always_inline]] inline IntervalLanes sqrt(const IntervalLanes& a) {
    using lane_detail::splat;
    lane_detail::Doubles root_lo, root_hi;
    for (int k = 0; k < IntervalLanes::count; ++k) {
        root_lo[k] = std::sqrt(a.lo[k]);
        root_hi[k] = std::sqrt(a.hi[k]);
    }
    // Empty, or below 0: empty; from 0 where lo ≤ 0.
    const lane_detail::Mask none = lane_detail::empty(a) | (a.hi < 0.0);
    const lane_detail::Doubles lo = a.lo <= 0.0 ? splat(0.0) : lane_detail::max(splat(0.0), lane_detail::down(root_lo));
    const lane_detail::Doubles nan = splat(std::numeric_limits<double>::quiet_NaN());
    return {none ? nan : lo, none ? nan : lane_detail::up(root_hi)};
}

[[gnu::always_inline]] inline IntervalLanes min(const IntervalLanes& a, const IntervalLanes& b) {
    const lane_detail::Mask empty = lane_detail::empty(a) | lane_detail::empty(b);
    const lane_detail::Doubles nan = lane_detail::splat(std::numeric_limits<double>::quiet_NaN());
    return {empty ? nan : lane_detail::min(a.lo, b.lo), empty ? nan : lane_detail::min(a.hi, b.hi)};
}

[[gnu::always_inline]] inline IntervalLanes max(const IntervalLanes& a, const IntervalLanes& b) {
    const lane_detail::Mask empty = lane_detail::empty(a) | lane_detail::empty(b);
    const lane_detail::Doubles nan = lane_detail::splat(std::numeric_limits<double>::quiet_NaN());
    return {empty ? nan : lane_detail::max(a.lo, b.lo), empty ? nan : lane_detail::max(a.hi, b.hi)};
}

// The other ops, lane by lane with the scalar code.
[[gnu::always_inline]] inline IntervalLanes operator/(const IntervalLanes& a, const IntervalLanes& b) {
    return lane_detail::each_lane(a, b, [](Interval x, Interval y) { return x / y; });
}
[[gnu::always_inline]] inline IntervalLanes abs(const IntervalLanes& a) {
    return lane_detail::each_lane(a, [](Interval x) { return abs(x); });
}
[[gnu::always_inline]] inline IntervalLanes exp(const IntervalLanes& a) {
    return lane_detail::each_lane(a, [](Interval x) { return exp(x); });
}
[[gnu::always_inline]] inline IntervalLanes log(const IntervalLanes& a) {
    return lane_detail::each_lane(a, [](Interval x) { return log(x); });
}
[[gnu::always_inline]] inline IntervalLanes sin(const IntervalLanes& a) {
    return lane_detail::each_lane(a, [](Interval x) { return sin(x); });
}
[[gnu::always_inline]] inline IntervalLanes cos(const IntervalLanes& a) {
    return lane_detail::each_lane(a, [](Interval x) { return cos(x); });
}
[[gnu::always_inline]] inline IntervalLanes tan(const IntervalLanes& a) {
    return lane_detail::each_lane(a, [](Interval x) { return tan(x); });
}
[[gnu::always_inline]] inline IntervalLanes atan(const IntervalLanes& a) {
    return lane_detail::each_lane(a, [](Interval x) { return atan(x); });
}
[[gnu::always_inline]] inline IntervalLanes floor(const IntervalLanes& a) {
    return lane_detail::each_lane(a, [](Interval x) { return floor(x); });
}
[[gnu::always_inline]] inline IntervalLanes powi(const IntervalLanes& a, int n) {
    return lane_detail::each_lane(a, [n](Interval x) { return powi(x, n); });
}
[[gnu::always_inline]] inline IntervalLanes atan2(const IntervalLanes& a, const IntervalLanes& b) {
    return lane_detail::each_lane(a, b, [](Interval y, Interval x) { return atan2(y, x); });
}
[[gnu::always_inline]] inline IntervalLanes hypot(const IntervalLanes& a, const IntervalLanes& b) {
    return lane_detail::each_lane(a, b, [](Interval x, Interval y) { return hypot(x, y); });
}
[[gnu::always_inline]] inline IntervalLanes log_sum_exp(const IntervalLanes& a, const IntervalLanes& b) {
    return lane_detail::each_lane(a, b, [](Interval x, Interval y) { return log_sum_exp(x, y); });
}
[[gnu::always_inline]] inline IntervalLanes pow(const IntervalLanes& a, const IntervalLanes& b) {
    return lane_detail::each_lane(a, b, [](Interval x, Interval y) { return pow(x, y); });
}

}  // namespace zeroset
