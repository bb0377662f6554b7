#include "zeroset/roots/laguerre.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>

namespace zeroset {

namespace {

using Complex = std::complex<double>;
using ComplexScratch = std::array<Complex, max_polynomial_degree + 1>;

constexpr std::size_t at(int i) { return static_cast<std::size_t>(i); }

/// Improves x towards a root of a[0] + … + a[n]xⁿ by Laguerre's iteration,
/// until the value is within its rounding error of 0 or the step vanishes.
/// Every tenth step is shortened by a varying fraction, which breaks the
/// rare limit cycles. Returns the iterations spent.
int laguerre(const ComplexScratch& a, int n, Complex& x) {
    constexpr int max_iterations = 80;
    constexpr std::array<double, 9> fractions{0.0, 0.5, 0.25, 0.75, 0.13, 0.38, 0.62, 0.88, 1.0};
    const double degree = static_cast<double>(n);
    for (int iteration = 1; iteration <= max_iterations; ++iteration) {
        Complex value = a[at(n)];
        Complex d1 = 0.0;
        Complex d2 = 0.0;  // half the second derivative
        double error = std::abs(value);
        const double abs_x = std::abs(x);
        for (int j = n - 1; j >= 0; --j) {
            d2 = x * d2 + d1;
            d1 = x * d1 + value;
            value = x * value + a[at(j)];
            error = std::abs(value) + abs_x * error;
        }
        if (std::abs(value) <= error * std::numeric_limits<double>::epsilon()) return iteration;
        const Complex g = d1 / value;
        const Complex g2 = g * g;
        const Complex h = g2 - 2.0 * d2 / value;
        const Complex root = std::sqrt((degree - 1.0) * (degree * h - g2));
        const Complex plus = g + root;
        const Complex minus = g - root;
        const Complex denominator = std::abs(plus) >= std::abs(minus) ? plus : minus;
        const Complex step = std::abs(denominator) > 0.0
                                 ? degree / denominator
                                 : std::polar(1.0 + abs_x, static_cast<double>(iteration));
        const Complex next = x - step;
        if (next == x) return iteration;
        x = iteration % 10 != 0 ? next : x - fractions[at(iteration / 10)] * step;
    }
    return max_iterations;
}

}  // namespace

PolynomialRoots laguerre_roots(std::span<const double> c, double t0, double t1, std::span<double> out) {
    const int n = checked_degree(c, t0, t1);
    PolynomialRoots result;
    if (n < 1 || out.empty()) return result;
    ComplexScratch original{};
    std::copy_n(c.begin(), n + 1, original.begin());
    ComplexScratch deflated = original;
    PolynomialScratch real{};
    int real_count = 0;
    for (int m = n; m >= 1; --m) {
        Complex x = 0.0;
        result.evaluations += laguerre(deflated, m, x);
        result.evaluations += laguerre(original, n, x);  // polish: deflation has moved the roots
        // Divide out (t − x) from the deflated polynomial (synthetic division).
        Complex carry = deflated[at(m)];
        for (int j = m - 1; j >= 0; --j) {
            const Complex coefficient = deflated[at(j)];
            deflated[at(j)] = carry;
            carry = x * carry + coefficient;
        }
        const double t = x.real();
        const double slack = 8.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(t));
        if (std::abs(x.imag()) <= laguerre_real_tolerance * std::max(1.0, std::abs(t)) && t >= t0 - slack &&
            t <= t1 + slack) {
            real[at(real_count++)] = std::clamp(t, t0, t1);
        }
    }
    std::sort(real.begin(), real.begin() + real_count);
    result.count = std::min(real_count, static_cast<int>(out.size()));
    std::copy_n(real.begin(), result.count, out.begin());
    return result;
}

}  // namespace zeroset
