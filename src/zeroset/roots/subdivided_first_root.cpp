// Front-to-back Bernstein subdivision with the rounding bound (see the header).
#include "zeroset/roots/subdivided_first_root.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "zeroset/roots/bernstein.hpp"
#include "zeroset/roots/fast_polynomial.hpp"
#include "zeroset/roots/monotone_pieces.hpp"

namespace zeroset {

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
/// Splits before a piece the signs leave undecided goes to the scan over
/// F̂'s extrema on it: enough to shed the parts of the span that are plainly
/// clear (Barth's sextic: 4 and 8 trace alike, 2 is 15 % slower).
constexpr int scan_depth = 6;

enum class Signs { Positive, OneCrossing, Undecided };

/// The signs of F's Bernstein coefficients on a piece, those within δ of 0
/// having none: all positive, or a run of positive ones, at most one
/// without a sign, and a run of negative ones (exactly one sign change
/// whatever that one's sign) — or anything else.
Signs classify(const double* b, int n, double delta) {
    int k = 0;
    while (k <= n && b[k] > delta) ++k;
    if (k > n) return Signs::Positive;
    if (k == 0) return Signs::Undecided;
    if (!(b[k] < -delta)) ++k;
    for (int i = k; i <= n; ++i)
        if (!(b[i] < -delta)) return Signs::Undecided;
    return Signs::OneCrossing;
}

/// Where the control polygon of the Bernstein coefficients b[0..n] on
/// [a, end] first crosses 0 (b[0] > 0): near F's root on a piece with one
/// sign change, and nearer the finer the piece (a start for Newton); NaN
/// when it does not cross.
double control_polygon_crossing(const double* b, int n, double a, double end) {
    int k = 0;
    while (k < n && b[k + 1] > 0.0) ++k;
    if (k == n) return std::numeric_limits<double>::quiet_NaN();
    const double at = static_cast<double>(k) + b[k] / (b[k] - b[k + 1]);
    return a + (end - a) * (at / static_cast<double>(n));
}

/// The scan of polynomial_enclosure.hpp over F̂'s extrema in [a, b].
PossibleRoot scan(const PolynomialEnclosure& f, double a, double b) {
    std::array<double, max_polynomial_degree> extrema{};
    const PolynomialRoots e = fast_polynomial_extrema(f.value, a, b, extrema);
    PossibleRoot r =
        first_possible_root(f, a, b, std::span<const double>(extrema.data(), static_cast<std::size_t>(e.count)), false);
    r.evaluations += e.evaluations;
    return r;
}

/// The subdivision with coefficient arrays of `Capacity` (> the degree).
template <int Capacity>
PossibleRoot subdivide(const PolynomialEnclosure& f, double t0, double t1, const PolynomialScratch& bernstein,
                       double magnitude, double span_radius, double tolerance, PossibleRoot r) {
    struct Piece {
        double a, b;
        int depth;
        std::array<double, Capacity> c;
    };
    const int n = static_cast<int>(f.value.size()) - 1;
    // Pieces still to look at, the leftmost on top: each split replaces one
    // by two, so the depth bounds the size.
    std::array<Piece, scan_depth + 2> stack;
    std::size_t top = 0;
    // Field by field: an aggregate with {} for the coefficients would zero
    // them all first (a `rep stos`, slow to start, on every ray).
    stack[top].a = t0;
    stack[top].b = t1;
    stack[top].depth = 0;
    std::copy_n(bernstein.begin(), n + 1, stack[top].c.begin());
    ++top;
    const double noise = bernstein_noise(n, magnitude);
    const double per_split = static_cast<double>(n) * eps * magnitude;
    while (top > 0) {
        // The piece on top, read where it lies: copied whole, its
        // coefficients (written one by one by the split) were read back in
        // wider loads than they were stored with, which stalls.
        Piece& piece = stack[--top];
        // F − F̂'s Bernstein coefficients on [a, b] are at most R(max(|a|, |b|)),
        // and at most R at the span's far end: that bound, found once, settles
        // most pieces; only those it leaves undecided pay for their own.
        const double rounding = noise + piece.depth * per_split;
        double delta = rounding + span_radius;
        Signs signs = classify(piece.c.data(), n, delta);
        if (signs == Signs::Undecided && piece.depth > 0) {
            delta = rounding + enclosure_bound(f, std::max(-piece.a, piece.b));
            signs = classify(piece.c.data(), n, delta);
        }
        if (signs == Signs::Positive) continue;
        if (signs == Signs::OneCrossing) {
            // The end coefficients are F̂ at the ends: beyond δ, their signs
            // need no evaluation. The first always is (the signs start with
            // a run above δ); the last may be the one within δ.
            const double* b = piece.c.data();
            double end = b[n];
            if (!(end < -delta)) {
                ++r.evaluations;
                end = sample_polynomial(f.value, piece.b).value;
            }
            const PolynomialSample lo{piece.a, b[0], 0.0, false};
            const PolynomialSample hi{piece.b, end, 0.0, false};
            if (lo.value > 0.0 && hi.value < 0.0) {
                r.found = true;
                r.sign_change = true;
                r.t = monotone_root(f.value, lo, hi, r.evaluations, tolerance, control_polygon_crossing(b, n, piece.a, piece.b));
                return r;
            }
        }
        const double m = 0.5 * piece.a + 0.5 * piece.b;
        if (piece.depth == scan_depth || !(piece.a < m && m < piece.b)) {
            const PossibleRoot scanned = scan(f, piece.a, piece.b);
            r.evaluations += scanned.evaluations;
            if (!scanned.found) continue;
            r.found = true;
            r.t = scanned.t;
            r.sign_change = scanned.sign_change;
            return r;
        }
        ++r.evaluations;
        // The right half takes the piece's place (its coefficients in place)
        // and the left goes on top.
        Piece& left = stack[top + 1];
        left.a = piece.a;
        left.b = m;
        left.depth = piece.depth + 1;
        split_bernstein(piece.c.data(), n, left.c.data(), piece.c.data());
        piece.a = m;
        piece.depth += 1;
        top += 2;
    }
    return r;
}

}  // namespace

PossibleRoot first_possible_root_subdividing(const PolynomialEnclosure& f, double t0, double t1, double tolerance) {
    PossibleRoot r;
    const int n = static_cast<int>(f.value.size()) - 1;
    double magnitude = 0.0;
    PolynomialScratch bernstein;
    to_bernstein(f.value, n, t0, t1, bernstein, magnitude);
    ++r.evaluations;
    // The first coefficient is F̂(t0) within the conversion's noise, and the
    // bound at the span's far end (t0 ≤ t1) is at least the one at t0: above both, F
    // is proven positive at the start, as it mostly is, without its own test.
    const double span_radius = enclosure_bound(f, std::max(-t0, t1));
    if (!(bernstein[0] > bernstein_noise(n, magnitude) + span_radius)) {
        const PolynomialSample start = sample_polynomial(f.value, t0);
        ++r.evaluations;
        if (std::abs(start.value) <= enclosure_bound(f, t0)) {  // F may vanish at once
            r.found = true;
            r.t = t0;
            r.sign_change = start.value == 0.0;
            return r;
        }
        // Below 0 at the start (a shadow ray from a hair inside): the signs'
        // runs assume the start is above, so the scan takes the whole span.
        if (start.value < 0.0) {
            const PossibleRoot scanned = scan(f, t0, t1);
            r.found = scanned.found;
            r.t = scanned.t;
            r.sign_change = scanned.sign_change;
            r.evaluations += scanned.evaluations;
            return r;
        }
    }
    if (n < 8) return subdivide<8>(f, t0, t1, bernstein, magnitude, span_radius, tolerance, r);
    return subdivide<max_polynomial_degree + 1>(f, t0, t1, bernstein, magnitude, span_radius, tolerance, r);
}

}  // namespace zeroset
