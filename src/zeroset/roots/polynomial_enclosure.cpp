// The piece-by-piece scan for the first possible root.
#include "zeroset/roots/polynomial_enclosure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "zeroset/roots/bernstein.hpp"
#include "zeroset/roots/monotone_pieces.hpp"
#include "zeroset/roots/polynomial_roots.hpp"

namespace zeroset {

namespace {

/// F̂ at t and the bound on |F(t) − F̂(t)|.
struct EnclosureSample {
    PolynomialSample value;
    double bound;

    [[nodiscard]] bool uncertain() const { return std::abs(value.value) <= bound; }
};

EnclosureSample sample_enclosure(const PolynomialEnclosure& f, double t) {
    return {sample_polynomial(f.value, t), enclosure_bound(f, t)};
}

/// Where p, monotone on [a.t, b.t] and of one sign there, first comes within
/// `bound` of 0 — b being within it and a not: the root of p ∓ bound. No
/// root of the exact polynomial lies before it on the piece.
double first_within(std::span<const double> p, PolynomialSample a, PolynomialSample b, double bound, int& evaluations) {
    std::array<double, max_polynomial_degree + 1> shifted{};
    std::copy(p.begin(), p.end(), shifted.begin());
    const double shift = a.value > 0.0 ? bound : -bound;
    shifted[0] -= shift;
    a.value -= shift;
    b.value -= shift;
    if (b.value == 0.0) return b.t;
    return monotone_root(std::span<const double>(shifted.data(), p.size()), a, b, evaluations);
}

}  // namespace

namespace {
/// γ₂ₙ = 2nu/(1 − 2nu) for n coefficients, found once.
constexpr auto horner_gammas = [] {
    constexpr double u = std::numeric_limits<double>::epsilon() / 2.0;
    std::array<double, max_polynomial_degree + 2> g{};
    for (std::size_t n = 0; n < g.size(); ++n) g[n] = 2.0 * static_cast<double>(n) * u / (1.0 - 2.0 * static_cast<double>(n) * u);
    return g;
}();
}  // namespace

double enclosure_bound(const PolynomialEnclosure& f, double t) {
    const double x = std::abs(t);
    double radius = 0.0;
    double magnitude = 0.0;
    if (f.radius.size() == f.value.size()) {  // as every caller has them: one pass
        for (std::size_t i = f.value.size(); i-- > 0;) {
            radius = radius * x + f.radius[i];
            magnitude = magnitude * x + std::abs(f.value[i]);
        }
    } else {
        for (std::size_t i = f.radius.size(); i-- > 0;) radius = radius * x + f.radius[i];
        for (std::size_t i = f.value.size(); i-- > 0;) magnitude = magnitude * x + std::abs(f.value[i]);
    }
    const std::size_t n = std::max(f.value.size(), f.radius.size());
    constexpr double u = std::numeric_limits<double>::epsilon() / 2.0;
    const double horner = n < horner_gammas.size() ? horner_gammas[n]
                                                   : 2.0 * static_cast<double>(n) * u / (1.0 - 2.0 * static_cast<double>(n) * u);
    return (radius + horner * magnitude) * (1.0 + horner);
}

double root_radius(const PolynomialEnclosure& f, double within, double largest) {
    constexpr double none = std::numeric_limits<double>::infinity();
    const std::size_t size = f.value.size();
    if (size < 2 || size > max_polynomial_degree + 1 || f.radius.size() != size) return none;
    if (!(largest > 0.0 && largest <= within && within < none)) return none;
    const double* value = f.value.data();
    const double* radius = f.radius.data();
    const auto weight = [&](std::size_t i) { return std::abs(value[i]) + radius[i]; };
    // The leading term: the highest whose coefficient cannot be 0 once the
    // terms above it, at most their weight·within^(j−m)·|t|^m for |t| ≤
    // within, are taken from it (a ray along which the top form vanishes,
    // as steiner's along its axes, has a lower effective degree).
    std::size_t n = size - 1;
    double lead = std::abs(value[n]) - radius[n];
    for (std::size_t m = n; !(lead > 0.0) && m-- > 1;) {
        double above = 0.0;
        for (std::size_t j = size - 1; j > m; --j) above = above * within + weight(j);
        n = m;
        lead = std::abs(value[m]) - radius[m] - above * within;
    }
    if (!(lead > 0.0 && lead < none)) return none;
    // Whether ρ is a bound: every lower term, with its radius, below
    // lead·(ρ/2)^k. Then beyond ρ they sum to less than Σ 2^−k ≤ 1 − 2^−n of
    // the leading term — room for the products' rounding many times over.
    const auto bounds = [&](double rho) {
        const double half = 0.5 * rho;
        double power = lead;
        for (std::size_t k = 1; k <= n; ++k) {
            power *= half;
            if (!(weight(n - k) < power)) return false;
        }
        return true;
    };
    // Halved while it still bounds: no division and no k-th root, and
    // within a factor 2 of the least such radius (or largest·2^−64).
    if (!bounds(largest)) return none;
    double rho = largest;
    for (int halving = 0; halving < 64 && bounds(0.5 * rho); ++halving) rho *= 0.5;
    return rho;
}

bool provably_positive(const PolynomialEnclosure& f, double t0, double t1) {
    const int n = static_cast<int>(f.value.size()) - 1;
    double magnitude = 0.0;
    PolynomialScratch b;
    to_bernstein(f.value, n, t0, t1, b, magnitude);
    const double noise = bernstein_noise(n, magnitude) + enclosure_bound(f, std::max(-t0, t1));
    return std::all_of(b.begin(), b.begin() + n + 1, [noise](double c) { return c > noise; });
}

PossibleRoot first_possible_root(const PolynomialEnclosure& f, double t0, double t1, std::span<const double> extrema,
                                 bool t1_is_root) {
    PossibleRoot r;
    EnclosureSample a = sample_enclosure(f, t0);
    ++r.evaluations;
    if (a.uncertain()) {
        r.found = true;
        r.t = t0;
        r.sign_change = a.value.value == 0.0;
        return r;
    }
    for (std::size_t i = 0; i <= extrema.size(); ++i) {
        const double t = i < extrema.size() ? extrema[i] : t1;
        if (t <= a.value.t || t > t1) continue;
        if (t1_is_root && (i == extrema.size() || t == t1)) break;  // the last piece ends at the known root
        const EnclosureSample b = sample_enclosure(f, t);
        ++r.evaluations;
        r.found = true;
        if (b.value.value == 0.0 || (a.value.value < 0.0) != (b.value.value < 0.0)) {
            r.sign_change = true;
            r.t = b.value.value == 0.0 ? t : monotone_root(f.value, a.value, b.value, r.evaluations);
            return r;
        }
        const double bound = std::max(a.bound, b.bound);
        if (std::min(std::abs(a.value.value), std::abs(b.value.value)) <= bound) {
            r.t = std::abs(a.value.value) <= bound ? a.value.t : first_within(f.value, a.value, b.value, bound, r.evaluations);
            return r;
        }
        r.found = false;
        a = b;
    }
    if (t1_is_root) {
        r.found = true;
        r.t = t1;
        r.sign_change = true;
    }
    return r;
}

int possible_roots(const PolynomialEnclosure& f, double t0, double t1, std::span<const double> extrema,
                   std::span<double> out, int& evaluations) {
    int count = 0;
    const auto add = [&](double t) {
        if (count < static_cast<int>(out.size()) && (count == 0 || t > out[static_cast<std::size_t>(count) - 1]))
            out[static_cast<std::size_t>(count++)] = t;
    };
    EnclosureSample a = sample_enclosure(f, t0);
    ++evaluations;
    for (std::size_t i = 0; i <= extrema.size(); ++i) {
        const double t = i < extrema.size() ? extrema[i] : t1;
        if (t <= a.value.t || t > t1) continue;
        const EnclosureSample b = sample_enclosure(f, t);
        ++evaluations;
        if (b.value.value == 0.0) {
            add(t);
        } else if (a.value.value != 0.0 && (a.value.value < 0.0) != (b.value.value < 0.0)) {
            add(monotone_root(f.value, a.value, b.value, evaluations));
        } else if (b.uncertain()) {
            add(t);  // the piece ends within R of 0 without crossing: a graze (or F's double root)
        }
        a = b;
    }
    return count;
}

}  // namespace zeroset
