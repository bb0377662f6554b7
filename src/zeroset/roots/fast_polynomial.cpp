#include "zeroset/roots/fast_polynomial.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "zeroset/roots/bracket.hpp"

namespace zeroset {

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

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

/// p(t), p′(t), and whether p(t) is within the rounding error of its
/// evaluation of 0 (horner_error_bound, computed in the same pass).
struct Sample {
    double t;
    double value;
    double derivative;
    bool zero;
};

Sample sample(std::span<const double> p, double t) {
    double value = 0.0;
    double derivative = 0.0;
    double bound = 0.0;
    const double x = std::abs(t);
    for (std::size_t i = p.size(); i-- > 0;) {
        derivative = derivative * t + value;
        value = value * t + p[i];
        bound = bound * x + std::abs(p[i]);
    }
    const double n2u = static_cast<double>(p.size()) * eps;
    return {t, value, derivative, std::abs(value) <= n2u / (1.0 - n2u) * bound};
}

/// The root of p on [a, b], where p is monotone and p(a), p(b) differ in
/// sign: Newton from the secant point, kept inside the shrinking bracket,
/// bisecting whenever a step lands outside it or is not at most half the
/// step before (the safeguard of Numerical Recipes' rtsafe). It stops, after
/// one last Newton step, when p is within its rounding error bound of 0 or
/// the step is within a few ulps of the point. Unlike refine_root it
/// reuses the known end values, which saves two evaluations a root.
double monotone_root(std::span<const double> p, Sample lo, Sample hi, int& evaluations) {
    double a = lo.t;
    double b = hi.t;
    const bool a_negative = lo.value < 0.0;
    double x = a + (b - a) * (lo.value / (lo.value - hi.value));
    double previous_step = b - a;
    for (int i = 0; i < max_bisections; ++i) {
        if (!(a < x && x < b)) x = 0.5 * a + 0.5 * b;
        if (!(a < x && x < b)) break;  // a and b are adjacent doubles
        const Sample v = sample(p, x);
        ++evaluations;
        if (v.value == 0.0) return x;
        ((v.value < 0.0) == a_negative ? a : b) = x;
        const double step = v.value / v.derivative;
        // In the noise (the bound is pessimistic) one last Newton step helps.
        if (v.zero || std::abs(step) <= 8.0 * eps * std::abs(x)) return a <= x - step && x - step <= b ? x - step : x;
        const bool steady = std::abs(step) <= 0.5 * std::abs(previous_step);
        previous_step = step;
        x = steady ? x - step : 0.5 * a + 0.5 * b;
    }
    return std::abs(horner(p, a).value) <= std::abs(horner(p, b).value) ? a : b;
}

/// The roots of p in [t0, t1], given the roots of p′ there (increasing):
/// at most `limit` of them, increasing.
int roots_between(std::span<const double> p, double t0, double t1, const double* splits, int split_count,
                  double* roots, int limit, int& evaluations) {
    int k = 0;
    Sample previous = sample(p, t0);
    ++evaluations;
    if (previous.zero) roots[k++] = t0;
    for (int i = 0; i <= split_count && k < limit; ++i) {
        const double t = i < split_count ? splits[i] : t1;
        if (t <= previous.t) continue;
        const Sample current = sample(p, t);
        ++evaluations;
        if (!previous.zero && !current.zero && (previous.value < 0.0) != (current.value < 0.0)) {
            roots[k++] = monotone_root(p, previous, current, evaluations);
        }
        // A run of points indistinguishable from 0 is one root.
        if (current.zero && !previous.zero && k < limit) roots[k++] = t;
        previous = current;
    }
    return k;
}

}  // namespace

PolynomialRoots fast_polynomial_roots(std::span<const double> c, double t0, double t1, std::span<double> out) {
    const int n = checked_degree(c, t0, t1);
    PolynomialRoots result;
    if (n < 1 || out.empty()) return result;
    const int wanted = static_cast<int>(std::min<std::size_t>(out.size(), static_cast<std::size_t>(n)));
    PolynomialScratch roots{};
    int count = 0;
    ++result.evaluations;  // the closed-form root(s) at the bottom
    if (n == 1) {
        const double t = -c[0] / c[1];
        if (t >= t0 && t <= t1) roots[count++] = t;
    } else {
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
        count = quadratic_roots(derivatives[static_cast<std::size_t>(n - 2)].data(), t0, t1, roots.data());
        PolynomialScratch next{};
        for (int j = n - 3; j >= 0; --j) {
            const std::span<const double> p(derivatives[static_cast<std::size_t>(j)].data(),
                                            static_cast<std::size_t>(n - j + 1));
            count = roots_between(p, t0, t1, roots.data(), count, next.data(), j == 0 ? wanted : n - j,
                                  result.evaluations);
            std::swap(roots, next);
        }
    }
    result.count = std::min(count, wanted);
    std::copy_n(roots.begin(), result.count, out.begin());
    return result;
}

}  // namespace zeroset
