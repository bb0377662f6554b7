// Sampling, bracketed Newton and the piece-by-piece scan.
#include "zeroset/roots/monotone_pieces.hpp"

#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>

#include "zeroset/roots/bracket.hpp"
#include "zeroset/roots/polynomial_roots.hpp"

namespace zeroset {

namespace {
constexpr double eps = std::numeric_limits<double>::epsilon();

/// The root of a line or a quadratic in [a, b] by its closed form (the
/// quadratic's stable pair, Numerical Recipes §5.6), if rounding leaves it
/// there; nothing for a higher degree.
std::optional<double> closed_form_root(std::span<const double> p, double a, double b) {
    std::size_t n = p.size();
    while (n > 0 && p[n - 1] == 0.0) --n;
    if (n == 2) {
        const double t = -p[0] / p[1];
        if (a <= t && t <= b) return t;
        return std::nullopt;
    }
    if (n != 3) return std::nullopt;
    const double disc = p[1] * p[1] - 4.0 * p[2] * p[0];
    if (!(disc >= 0.0)) return std::nullopt;
    const double q = -0.5 * (p[1] + std::copysign(std::sqrt(disc), p[1]));
    for (const double t : {q / p[2], q != 0.0 ? p[0] / q : q / p[2]})
        if (a <= t && t <= b) return t;
    return std::nullopt;
}
}  // namespace

namespace {
/// sample_polynomial over `size` coefficients; with a size fixed at compile
/// time the loop unrolls (a hit's Newton steps take a few of these).
template <std::size_t Size = 0>
PolynomialSample sample_coefficients(const double* p, std::size_t size, double t) {
    if constexpr (Size > 0) size = Size;
    double value = 0.0;
    double derivative = 0.0;
    double bound = 0.0;
    const double x = std::abs(t);
    for (std::size_t i = size; i-- > 0;) {
        derivative = derivative * t + value;
        value = value * t + p[i];
        bound = bound * x + std::abs(p[i]);
    }
    const double n2u = static_cast<double>(size) * eps;
    return {t, value, derivative, std::abs(value) <= n2u / (1.0 - n2u) * bound};
}
}  // namespace

PolynomialSample sample_polynomial(std::span<const double> p, double t) {
    // Quartics (POV-Ray's blobs and quartic surfaces) and sextics (soft objects, Barth's) come most.
    switch (p.size()) {
        case 5: return sample_coefficients<5>(p.data(), 5, t);
        case 7: return sample_coefficients<7>(p.data(), 7, t);
        default: return sample_coefficients(p.data(), p.size(), t);
    }
}

double monotone_root(std::span<const double> p, PolynomialSample lo, PolynomialSample hi, int& evaluations,
                     double tolerance, double first_guess) {
    double a = lo.t;
    double b = hi.t;
    if (const auto t = closed_form_root(p, a, b)) {
        // One Newton step polishes it, kept if it lowers |p|.
        const PolynomialSample v = sample_polynomial(p, *t);
        ++evaluations;
        if (v.value == 0.0 || v.derivative == 0.0) return *t;
        const double polished = *t - v.value / v.derivative;
        if (!(a <= polished && polished <= b)) return *t;
        ++evaluations;
        return std::abs(horner(p, polished).value) <= std::abs(v.value) ? polished : *t;
    }
    const bool a_negative = lo.value < 0.0;
    double x = a < first_guess && first_guess < b ? first_guess : a + (b - a) * (lo.value / (lo.value - hi.value));
    double previous_step = b - a;
    bool by_newton = false;  // whether x came from a Newton step (not a bisection or the first guess)
    for (int i = 0; i < max_bisections; ++i) {
        if (!(a < x && x < b)) x = 0.5 * a + 0.5 * b;
        if (!(a < x && x < b)) break;  // a and b are adjacent doubles
        const PolynomialSample v = sample_polynomial(p, x);
        ++evaluations;
        if (v.value == 0.0) return x;
        ((v.value < 0.0) == a_negative ? a : b) = x;
        const double step = v.value / v.derivative;
        // Within the tolerance, shrinking, and x itself a Newton step's: converging.
        if (by_newton && std::abs(step) <= tolerance && std::abs(step) <= 0.5 * std::abs(previous_step)) {
            const double last = x - step;
            return a <= last && last <= b ? last : x;
        }
        // In the noise (the bound is pessimistic) one last Newton step helps —
        // if it lowers |p|: near a double root p′ is nearly 0 too, and the
        // step is noise divided by almost nothing.
        if (v.zero || std::abs(step) <= 8.0 * eps * std::abs(x)) {
            const double last = x - step;
            if (!(a <= last && last <= b)) return x;
            ++evaluations;
            return std::abs(horner(p, last).value) <= std::abs(v.value) ? last : x;
        }
        const bool steady = std::abs(step) <= 0.5 * std::abs(previous_step);
        previous_step = step;
        by_newton = steady;
        x = steady ? x - step : 0.5 * a + 0.5 * b;
    }
    return std::abs(horner(p, a).value) <= std::abs(horner(p, b).value) ? a : b;
}

int roots_between(std::span<const double> p, double t0, double t1, std::span<const double> extrema, double* roots,
                  int limit, int& evaluations, double tolerance) {
    int k = 0;
    PolynomialSample previous = sample_polynomial(p, t0);
    ++evaluations;
    if (previous.zero) roots[k++] = t0;
    for (std::size_t i = 0; i <= extrema.size() && k < limit; ++i) {
        const double t = i < extrema.size() ? extrema[i] : t1;
        if (t <= previous.t) continue;
        const PolynomialSample current = sample_polynomial(p, t);
        ++evaluations;
        if (!previous.zero && !current.zero && (previous.value < 0.0) != (current.value < 0.0)) {
            roots[k++] = monotone_root(p, previous, current, evaluations, tolerance);
        }
        if (current.zero && !previous.zero && k < limit) roots[k++] = t;
        previous = current;
    }
    return k;
}

}  // namespace zeroset
