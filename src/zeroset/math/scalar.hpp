// The tape's operations on plain floating-point numbers. Every number type of
// the evaluator (Interval, Dual, Jet, …) offers the same named functions, so a
// single evaluator template serves them all (DESIGN.md, "one tape, many number
// types"). The predicates at the end let generic code (Dual, Jet) pick a branch
// of min/max/abs: a plain number always knows which side wins.
#pragma once

#include <cmath>
#include <concepts>
#include <optional>

namespace zeroset {

template <std::floating_point F> inline F square(F a) { return a * a; }
template <std::floating_point F> inline F sqrt(F a) { return std::sqrt(a); }
template <std::floating_point F> inline F abs(F a) { return std::fabs(a); }
template <std::floating_point F> inline F exp(F a) { return std::exp(a); }
template <std::floating_point F> inline F log(F a) { return std::log(a); }
template <std::floating_point F> inline F sin(F a) { return std::sin(a); }
template <std::floating_point F> inline F cos(F a) { return std::cos(a); }
template <std::floating_point F> inline F pow(F a, F b) { return std::pow(a, b); }
/// a^n for an integer n, by repeated squaring (exact sign for negative a).
template <std::floating_point F> inline F powi(F a, int n) {
    if (n < 0) return F(1) / powi(a, -n);
    F result = F(1);
    F base = a;
    while (n != 0) {
        if (n & 1) result *= base;
        base *= base;
        n >>= 1;
    }
    return result;
}
/// The value as an int when it is exactly a moderately sized integer: then
/// pow(a, b) = powi(a, n), whose domain includes negative bases.
template <std::floating_point F> inline std::optional<int> integer_value(F a) {
    if (a == std::round(a) && std::abs(a) < F(1 << 30)) return static_cast<int>(a);
    return std::nullopt;
}
// NaN-propagating min/max: a NaN operand must not be silently dropped.
template <std::floating_point F> inline F min(F a, F b) { return (a != a || b != b) ? a + b : (a < b ? a : b); }
template <std::floating_point F> inline F max(F a, F b) { return (a != a || b != b) ? a + b : (a > b ? a : b); }

/// True when a ≤ b holds for every value the numbers stand for.
template <std::floating_point F> inline bool certainly_le(F a, F b) { return a <= b; }
/// The smallest number that stands for both (only reached by NaN for scalars).
template <std::floating_point F> inline F hull(F a, F /*b*/) { return a; }
template <std::floating_point F> inline bool is_exact_zero(F a) { return a == F(0); }

}  // namespace zeroset
