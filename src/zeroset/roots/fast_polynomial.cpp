// The recursive-derivative solver: extrema level by level, then the roots.
#include "zeroset/roots/fast_polynomial.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>

#include "zeroset/roots/monotone_pieces.hpp"

namespace zeroset {

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
/// How closely extrema are placed, relative to the span.
constexpr double extremum_tolerance = 1e-10;

/// The roots of c[0] + c[1]t + c[2]t² (c[2] ≠ 0) in [t0, t1], increasing,
/// without cancellation (Numerical Recipes §5.6). A discriminant within its
/// rounding error of 0 gives one (double) root.
int quadratic_roots(const double* c, double t0, double t1, double* roots) {
    const double a = c[2];
    const double b = c[1];
    const double cc = c[0];
    const double disc = b * b - 4.0 * a * cc;
    const double noise = 4.0 * eps * (b * b + 4.0 * std::abs(a * cc));
    double r[2];
    int n = 0;
    if (disc < -noise) return 0;
    if (disc <= noise) {
        r[n++] = -b / (2.0 * a);
    } else {
        const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
        r[0] = q / a;
        r[1] = cc / q;
        if (r[1] < r[0]) std::swap(r[0], r[1]);
        n = 2;
    }
    int k = 0;
    for (int i = 0; i < n; ++i) {
        if (r[i] >= t0 && r[i] <= t1) roots[k++] = r[i];
    }
    return k;
}

}  // namespace

PolynomialRoots fast_polynomial_extrema(std::span<const double> c, double t0, double t1, std::span<double> out) {
    const int n = checked_degree(c, t0, t1);
    PolynomialRoots result;
    if (n < 2) return result;
    if (out.size() < static_cast<std::size_t>(n - 1)) throw std::invalid_argument("fast_polynomial_extrema needs room for n - 1 roots");
    ++result.evaluations;  // the closed-form root(s) at the bottom
    if (n == 2) {
        const double t = -c[1] / (2.0 * c[2]);
        if (t >= t0 && t <= t1) {
            out[0] = t;
            result.count = 1;
        }
        return result;
    }
    // derivatives[j] is the j-th derivative of p, of degree n − j.
    std::array<PolynomialScratch, max_polynomial_degree - 1> derivatives;
    std::copy_n(c.begin(), n + 1, derivatives[0].begin());
    for (int j = 1; j <= n - 2; ++j) {
        const auto& from = derivatives[static_cast<std::size_t>(j - 1)];
        auto& to = derivatives[static_cast<std::size_t>(j)];
        for (int i = 0; i <= n - j; ++i) {
            to[static_cast<std::size_t>(i)] = static_cast<double>(i + 1) * from[static_cast<std::size_t>(i + 1)];
        }
    }
    PolynomialScratch roots{};
    int count = quadratic_roots(derivatives[static_cast<std::size_t>(n - 2)].data(), t0, t1, roots.data());
    PolynomialScratch next{};
    // These roots end monotone pieces. Placed within δ of the true one, an
    // extremum's value is off by about ½·|p″|·δ²: at δ = 10⁻¹⁰ of the span
    // some 10⁻²⁰ of p's variation across it, far below the rounding bound
    // of forming p (~10⁻¹⁵ of its size) that the guarded scan allows for.
    const double tolerance = extremum_tolerance * (t1 - t0);
    for (int j = n - 3; j >= 1; --j) {
        const std::span<const double> p(derivatives[static_cast<std::size_t>(j)].data(), static_cast<std::size_t>(n - j + 1));
        count = roots_between(p, t0, t1, std::span<const double>(roots.data(), static_cast<std::size_t>(count)),
                              next.data(), n - j, result.evaluations, tolerance);
        std::swap(roots, next);
    }
    result.count = count;
    std::copy_n(roots.begin(), count, out.begin());
    return result;
}

PolynomialRoots fast_polynomial_roots(std::span<const double> c, double t0, double t1, std::span<double> out) {
    const int n = checked_degree(c, t0, t1);
    PolynomialRoots result;
    if (n < 1 || out.empty()) return result;
    const int wanted = static_cast<int>(std::min<std::size_t>(out.size(), static_cast<std::size_t>(n)));
    if (n == 1) {
        ++result.evaluations;
        const double t = -c[0] / c[1];
        if (t >= t0 && t <= t1) {
            out[0] = t;
            result.count = 1;
        }
        return result;
    }
    PolynomialScratch extrema{};
    const PolynomialRoots e = fast_polynomial_extrema(c, t0, t1, extrema);
    result.evaluations = e.evaluations;
    PolynomialScratch roots{};
    const int count = roots_between(c.first(static_cast<std::size_t>(n) + 1), t0, t1,
                                    std::span<const double>(extrema.data(), static_cast<std::size_t>(e.count)),
                                    roots.data(), wanted, result.evaluations);
    result.count = count;
    std::copy_n(roots.begin(), count, out.begin());
    return result;
}

}  // namespace zeroset
