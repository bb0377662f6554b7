// Roots of a polynomial between its extrema. Once the roots of p′ in [t0, t1]
// are known, they cut the span into pieces on which p is monotone: each piece
// holds at most one root, and holds one exactly when p changes sign across
// it. This is the step the recursive-derivative solver (Yuksel, HPG 2022)
// repeats at every level, and the step that turns any solver's extrema into
// a guarded first hit (roots/polynomial_enclosure.hpp).
#pragma once

#include <limits>
#include <span>

namespace zeroset {

/// p(t), p′(t), and whether p(t) is within the rounding-error bound of its
/// own Horner evaluation of 0.
struct PolynomialSample {
    double t;
    double value;
    double derivative;
    bool zero;
};

PolynomialSample sample_polynomial(std::span<const double> p, double t);

/// The root of p on [lo.t, hi.t], where p is monotone and lo.value,
/// hi.value differ in sign. A line or a quadratic: its closed form and one
/// Newton step. Otherwise safeguarded Newton from the secant point, kept
/// inside the shrinking bracket (Numerical Recipes' rtsafe). It stops, after
/// one last Newton step (kept if it lowers |p|), when p is within its
/// rounding-error bound of 0 or the step is within a few ulps of the point
/// — or, given a `tolerance` in t, at once after a steady step shorter than
/// it (Newton's next error is about the square of its step: for the ends
/// of monotone pieces, full precision costs one or two evaluations more and
/// buys nothing). Counts its evaluations. Only the ends' t and value are
/// read. `first_guess`, when inside the bracket, replaces the secant point
/// as Newton's start.
double monotone_root(std::span<const double> p, PolynomialSample lo, PolynomialSample hi, int& evaluations,
                     double tolerance = 0.0, double first_guess = std::numeric_limits<double>::quiet_NaN());

/// The roots of p in [t0, t1] given the roots of p′ there (increasing): at
/// most `limit` of them, increasing. A point where p is indistinguishable
/// from 0 is a root (a double root shows up so, at p′'s root), and a run of
/// such points is one root.
int roots_between(std::span<const double> p, double t0, double t1, std::span<const double> extrema, double* roots,
                  int limit, int& evaluations, double tolerance = 0.0);

}  // namespace zeroset
