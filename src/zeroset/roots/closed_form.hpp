// Closed-form real roots of polynomials of degree ≤ 4 (survey §3.4: "the
// quadratic equation finds all roots for degree two polynomials; similar
// symbolic methods exist for degree three and four"). Coefficients are
// ascending, c[0] + c[1]·t + … . Each solver returns how many real roots it
// wrote, sorted ascending, distinct (a double root found as such is written
// once), every one polished by up to two Newton steps on the original
// polynomial (a step is kept only if it lowers |F|).
//
// Care taken: coefficients are scaled by a power of two (exact) so squares
// cannot overflow; the quadratic never subtracts nearly equal numbers
// (q = −(b + sign(b)·√disc)/2, roots q/a and c/q) and forms b² − 4ac with an
// fma correction; a zero constant term gives the root 0 exactly and drops
// the degree; a leading coefficient of at most ε times the largest other one
// is treated as zero (its roots would lie beyond |t| ≈ ε^(−1/n) times the
// others' scale: they are not reported). The cubic uses the trigonometric
// form for three real roots and Cardano (cube roots chosen without
// cancellation) for one; the quartic is biquadratic when its depressed form
// has no linear term, else Ferrari via the resolvent cubic's largest root.
// An identically zero polynomial reports no roots.
#pragma once

#include <optional>
#include <span>

namespace zeroset {

inline constexpr int max_closed_form_degree = 4;

int solve_linear(const double* c, double roots[1]);
int solve_quadratic(const double* c, double roots[2]);
int solve_cubic(const double* c, double roots[3]);
int solve_quartic(const double* c, double roots[4]);

/// The real roots of the polynomial with coefficients c (degree c.size() − 1,
/// at most 4), sorted; returns their number.
int solve_closed_form(std::span<const double> c, std::span<double, max_closed_form_degree> roots);

/// The real roots in [t0, t1], sorted; returns their number.
int closed_form_roots_in(std::span<const double> c, double t0, double t1,
                         std::span<double, max_closed_form_degree> roots);

/// The smallest real root in [t0, t1] — the first hit along a ray segment.
std::optional<double> closed_form_first_root(std::span<const double> c, double t0, double t1);

}  // namespace zeroset
