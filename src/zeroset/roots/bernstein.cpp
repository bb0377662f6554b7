// The power basis to the Bernstein basis: a Taylor shift, a scaling, and
// the binomial weights.
#include "zeroset/roots/bernstein.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace zeroset {

namespace {

constexpr std::size_t at(int i) { return static_cast<std::size_t>(i); }

/// Binomial coefficients C(n, k) for n ≤ 32, exact in doubles.
constexpr auto binomials = [] {
    std::array<PolynomialScratch, max_polynomial_degree + 1> b{};
    for (std::size_t n = 0; n < b.size(); ++n) {
        b[n][0] = 1.0;
        for (std::size_t k = 1; k <= n; ++k) b[n][k] = b[n - 1][k - 1] + (k < n ? b[n - 1][k] : 0.0);
    }
    return b;
}();

}  // namespace

PolynomialScratch to_bernstein(std::span<const double> p, int n, double t0, double t1, double& magnitude) {
    // Taylor shift to t0 (repeated synthetic division), then scale by t1 − t0;
    // the same on |cᵢ| and |t0| gives the scale of each result's rounding.
    PolynomialScratch a{};
    PolynomialScratch abs_a{};
    std::copy(p.begin(), p.end(), a.begin());
    for (int i = 0; i <= n; ++i) abs_a[at(i)] = std::abs(a[at(i)]);
    for (int i = 0; i < n; ++i) {
        for (int j = n - 1; j >= i; --j) {
            a[at(j)] += t0 * a[at(j + 1)];
            abs_a[at(j)] += std::abs(t0) * abs_a[at(j + 1)];
        }
    }
    double scale = 1.0;
    for (int i = 0; i <= n; ++i, scale *= t1 - t0) {
        a[at(i)] *= scale;
        abs_a[at(i)] *= scale;
    }
    PolynomialScratch b{};
    magnitude = 0.0;
    for (int k = 0; k <= n; ++k) {
        double sum = 0.0;
        double abs_sum = 0.0;
        for (int i = 0; i <= k; ++i) {
            const double weight = binomials[at(k)][at(i)] / binomials[at(n)][at(i)];
            sum += weight * a[at(i)];
            abs_sum += weight * abs_a[at(i)];
        }
        b[at(k)] = sum;
        magnitude = std::max(magnitude, abs_sum);
    }
    return b;
}

}  // namespace zeroset
