// What the one-dimensional root finders are given: a function of one variable,
// in practice H(t) = f(x_o + t·x_d), the surface seen along a ray (survey
// eq. 13). Newton's method (eq. 22) also needs H′(t), the directional
// derivative of eq. 21. Functions are passed as templates, so a call inlines
// and nothing is allocated.
//
// Sign convention, shared by every routine here: the surface is H = 0 and the
// inside is H ≤ 0, so a sample with H exactly 0 counts as inside.
#pragma once

#include <concepts>
#include <type_traits>

namespace zeroset {

/// H(t) and H′(t) at one t.
struct ValueAndDerivative {
    double value = 0.0;
    double derivative = 0.0;
};

/// A callable giving H(t) as a number.
template <class F>
concept ScalarFunction = std::invocable<F&, double> && std::convertible_to<std::invoke_result_t<F&, double>, double>;

/// A callable giving H(t) and H′(t) together.
template <class F>
concept DifferentiableFunction =
    std::invocable<F&, double> && std::same_as<std::remove_cvref_t<std::invoke_result_t<F&, double>>, ValueAndDerivative>;

/// True when a value of H lies inside or on the surface. NaN gives false;
/// the bracketing routines stop at a NaN before they ask.
[[nodiscard]] constexpr bool is_inside(double h) { return h <= 0.0; }

}  // namespace zeroset
