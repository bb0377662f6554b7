#include "zeroset/roots/descartes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "zeroset/roots/bernstein.hpp"
#include "zeroset/roots/refine.hpp"

namespace zeroset {

namespace {

constexpr std::size_t at(int i) { return static_cast<std::size_t>(i); }

/// A piece [a, b] of [t0, t1] and p's Bernstein coefficients on it.
struct Piece {
    double a, b;
    PolynomialScratch bernstein;
};

enum class Verdict { NoRoot, OneRoot, Zero, Split };

/// What Descartes' rule says of a piece, coefficients within `noise` of 0
/// having no sign.
Verdict classify(const PolynomialScratch& b, int n, double noise) {
    int variations = 0;
    int previous = 0;
    bool any_zero = false;
    for (int i = 0; i <= n; ++i) {
        const int sign = b[at(i)] > noise ? 1 : b[at(i)] < -noise ? -1 : 0;
        if (sign == 0) {
            any_zero = true;
            continue;
        }
        if (previous != 0 && sign != previous) ++variations;
        previous = sign;
    }
    if (previous == 0) return Verdict::Zero;
    if (variations == 0) return any_zero ? Verdict::Split : Verdict::NoRoot;
    const bool ends_signed = std::abs(b[0]) > noise && std::abs(b[at(n)]) > noise;
    return variations == 1 && ends_signed ? Verdict::OneRoot : Verdict::Split;
}

}  // namespace

PolynomialRoots descartes_roots(std::span<const double> c, double t0, double t1, std::span<double> out) {
    const int n = checked_degree(c, t0, t1);
    PolynomialRoots result;
    if (n < 1 || out.empty()) return result;
    const std::span<const double> p = c.first(at(n + 1));
    PolynomialFunction f(p);
    double magnitude = 0.0;
    // Pieces still to look at, the leftmost on top: each split replaces one
    // by two, so the depth bounds the size.
    std::array<Piece, 64> stack;
    std::size_t top = 0;
    stack[top].a = t0;
    stack[top].b = t1;
    to_bernstein(p, n, t0, t1, stack[top++].bernstein, magnitude);
    ++result.evaluations;
    // De Casteljau only averages, which adds little to the conversion's rounding.
    const double noise = bernstein_noise(n, magnitude);
    // Adjacent Zero pieces (a zero at a split point shows on both sides, a
    // double root over several) are one root: the run from zero_run_start to
    // zero_run_end, reported as out[count − 1].
    double zero_run_start = 0.0;
    double zero_run_end = std::numeric_limits<double>::quiet_NaN();
    double zero_run_value = 0.0;  // p(zero_run_start)
    bool run_at_midpoint = false;  // out[count − 1] is the run's midpoint, moved as it grows
    const auto emit = [&](double t) { out[at(result.count++)] = std::clamp(t, t0, t1); };
    // Past the last root wanted, only a piece that may extend the run is looked at.
    while (top > 0 && (at(result.count) < out.size() || stack[top - 1].a == zero_run_end)) {
        const Piece piece = stack[--top];
        const double m = 0.5 * piece.a + 0.5 * piece.b;
        Verdict verdict = classify(piece.bernstein, n, noise);
        if (verdict == Verdict::Split && (!(piece.a < m && m < piece.b) || top + 2 > stack.size())) {
            verdict = Verdict::Zero;  // the minimum width: a tangent or a cluster
        }
        const bool extends_run = piece.a == zero_run_end && verdict != Verdict::OneRoot;
        if (at(result.count) == out.size() && !extends_run) break;
        switch (verdict) {
            case Verdict::NoRoot:
                break;
            case Verdict::OneRoot:
                emit(refine_root(f, piece.a, piece.b).t);
                break;
            case Verdict::Zero: {
                // A run with a sign change (simple roots in noise) is refined
                // to its root; one without (a double root) stands at its middle.
                const double pb = f(piece.b).value;
                if (!extends_run) {
                    zero_run_start = piece.a;
                    zero_run_value = f(piece.a).value;
                    run_at_midpoint = zero_run_value != 0.0;
                    emit(run_at_midpoint ? m : piece.a);
                }
                if (run_at_midpoint) {
                    const bool sign_change = pb == 0.0 || (pb < 0.0) != (zero_run_value < 0.0);
                    out[at(result.count - 1)] = sign_change ? refine_root(f, zero_run_start, piece.b).t
                                                            : 0.5 * zero_run_start + 0.5 * piece.b;
                    run_at_midpoint = !sign_change;
                }
                zero_run_end = piece.b;
                break;
            }
            case Verdict::Split:
                ++result.evaluations;
                stack[top + 1].a = piece.a;
                stack[top + 1].b = m;
                stack[top].a = m;
                stack[top].b = piece.b;
                split_bernstein(piece.bernstein.data(), n, stack[top + 1].bernstein.data(), stack[top].bernstein.data());
                top += 2;
                break;
        }
    }
    result.evaluations += f.evaluations();
    return result;
}

}  // namespace zeroset
