// The surface seen along one ray, H(t) = f(o + t·d), and its derivative H′(t),
// enclosed over an interval of t with MPFI at high precision — the arithmetic
// of the first-hit oracle (mpfi_ray_oracle.hpp). It walks the Expr DAG itself
// (not zeroset's tape or Interval), so it is a check that nobody here shares
// code with: every op of the op table is written again over mpfi functions.
//
// H′ comes from forward-mode differentiation: each node carries an enclosure
// of its value and of its t-derivative. At the kinks of abs, min and max the
// derivative encloses both one-sided slopes (Clarke's generalised gradient),
// which keeps the mean-value theorem H(s) − H(r) ∈ H′(T)·(s − r) true.
//
// Domains are clipped as zeroset's Interval does: sqrt, log and pow enclose
// the function over the part of their argument where it is defined. An op
// whose argument lies wholly outside its domain makes the node — and every
// node above it — undefined over the interval (NaN is never a root). An
// enclosure is `regular` when every op met its argument inside the open set
// where it is continuous and differentiable (no clipping, no divisor or
// negative power near 0, no pole of tan, no integer inside floor's argument,
// no point of atan2's cut x ≤ 0, y = 0, no apex of hypot): only then are H
// continuous and H′ meaningful. Across a jump H′ is ℝ, and atan2 over its
// cut is [−π, π], as zeroset's Interval makes it.
#pragma once

#include <mpfi.h>

#include <cstdint>
#include <vector>

#include "zeroset/expr/expr.hpp"
#include "zeroset/math/ray.hpp"

namespace zeroset::test {

/// A fixed number of MPFI intervals at one precision, initialised once.
class MpfiArray {
public:
    MpfiArray(std::size_t count, mpfr_prec_t precision);
    ~MpfiArray();
    MpfiArray(const MpfiArray&) = delete;
    MpfiArray& operator=(const MpfiArray&) = delete;

    mpfi_ptr operator[](std::size_t i) { return &items_[i]; }
    mpfi_srcptr operator[](std::size_t i) const { return &items_[i]; }

private:
    std::vector<__mpfi_struct> items_;
};

struct Enclosure {
    bool defined;  // false: f is undefined (NaN) everywhere on the interval
    bool regular;  // H is continuous there and H′ (if asked for) encloses its slopes
};

class MpfiRayFunction {
public:
    MpfiRayFunction(const Expr& f, mpfr_prec_t precision);

    /// The ray whose H is evaluated; origin and direction are taken as exact.
    void set_ray(const Ray& ray);

    /// Encloses H over t (a point or an interval), and H′ too when `with_derivative`.
    Enclosure evaluate(mpfi_srcptr t, bool with_derivative);

    /// The enclosures of the last evaluate().
    [[nodiscard]] mpfi_srcptr value() const { return value_[root_]; }
    [[nodiscard]] mpfi_srcptr derivative() const { return slope_[root_]; }

    [[nodiscard]] std::uint64_t evaluations() const { return evaluations_; }

private:
    struct Node {
        Op op;
        std::uint32_t a;
        std::uint32_t b;
        int n;            // Powi's exponent
        double constant;  // Const's value
    };

    static std::vector<Node> compile(const Expr& f);

    /// Node i's value (and slope) from its operands at t; false when it is undefined.
    bool apply(std::size_t i, mpfi_srcptr t, bool with_derivative);
    /// value = a^n (n ≥ 1) with the tightest bounds, from exactly rounded endpoint powers.
    void power(mpfi_ptr value, mpfi_srcptr a, unsigned long n);
    /// value = a^n for any integer n; false when undefined (0 to a negative power).
    bool integer_power(mpfi_ptr value, mpfi_srcptr a, long n);

    std::vector<Node> nodes_;  // topological order; the root is last
    std::uint32_t root_ = 0;
    MpfiArray value_;
    MpfiArray slope_;
    MpfiArray scratch_;
    std::vector<char> defined_;
    Ray ray_{};
    bool clipped_ = false;  // some op met its argument outside its regular domain
    std::uint64_t evaluations_ = 0;
};

}  // namespace zeroset::test
