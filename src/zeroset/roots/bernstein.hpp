// A polynomial on [t0, t1] in the Bernstein basis: its coefficients bound it
// there (the convex-hull property), so all of them positive proves it has
// no root on the interval. Descartes' rule of signs (descartes.hpp) counts
// their sign changes; the blob's segments (trace/blob_segment.hpp) use the
// bound alone to reject a segment before solving it.
#pragma once

#include <limits>
#include <span>

#include "zeroset/roots/polynomial_roots.hpp"

namespace zeroset {

/// The Bernstein coefficients on [t0, t1] of p (ascending powers, degree n
/// ≤ 32), into out[0..n] (out holds at least n + 1; the rest is left as it
/// was); `magnitude` gets the largest of the same computed on |p| and |t0|,
/// the scale of the conversion's rounding.
void to_bernstein(std::span<const double> p, int n, double t0, double t1, std::span<double> out, double& magnitude);

/// Splits the Bernstein coefficients b[0..n] of a piece at its middle into
/// those of its halves (de Casteljau). `left` or `right` (not both) may be
/// b itself: before b is read whole, only its own end values are written
/// back (left[0] = b[0], right[n] = b[n]).
/// Each result is at most n roundings of averages of coefficients: a split
/// adds at most n·ε/2·max|b| to their error.
void split_bernstein(const double* b, int n, double* left, double* right);

/// A bound on the conversion's rounding error in each coefficient: n + 1
/// roundings of terms up to `magnitude`.
inline double bernstein_noise(int n, double magnitude) {
    return 2.0 * static_cast<double>(n + 1) * std::numeric_limits<double>::epsilon() * magnitude;
}

}  // namespace zeroset
