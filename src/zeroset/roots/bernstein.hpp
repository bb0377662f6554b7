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
/// ≤ 32); `magnitude` gets the largest of the same computed on |p| and |t0|,
/// the scale of the conversion's rounding.
PolynomialScratch to_bernstein(std::span<const double> p, int n, double t0, double t1, double& magnitude);

namespace bernstein_detail {

/// de Casteljau's triangle at the middle for a degree N known at compile
/// time: unrolled, every value in a register. The generic loop kept the
/// triangle's rows in memory, and each row's paired loads read the stores
/// of the row before at another offset, which the store buffer cannot
/// forward (a stall per row).
template <int N>
[[gnu::always_inline]] inline void split_fixed(const double* b, double* left, double* right) {
    double w[N + 1];
    for (int i = 0; i <= N; ++i) w[i] = b[i];
    left[0] = w[0];
    right[N] = w[N];
    for (int r = 1; r <= N; ++r) {
        for (int i = 0; i <= N - r; ++i) w[i] = 0.5 * (w[i] + w[i + 1]);
        left[r] = w[0];
        right[N - r] = w[N - r];
    }
}

inline void split_any(const double* b, int n, double* left, double* right) {
    PolynomialScratch w{};  // zeroed: GCC cannot see that n ≥ 9 here, and warns
    for (int i = 0; i <= n; ++i) w[static_cast<std::size_t>(i)] = b[i];
    left[0] = w[0];
    right[n] = w[static_cast<std::size_t>(n)];
    for (int r = 1; r <= n; ++r) {
        for (int i = 0; i <= n - r; ++i)
            w[static_cast<std::size_t>(i)] = 0.5 * (w[static_cast<std::size_t>(i)] + w[static_cast<std::size_t>(i) + 1]);
        left[r] = w[0];
        right[n - r] = w[static_cast<std::size_t>(n - r)];
    }
}

}  // namespace bernstein_detail

/// Splits the Bernstein coefficients b[0..n] of a piece at its middle into
/// those of its halves (de Casteljau); b is read whole before either half
/// is written, so `left` or `right` (not both) may be b itself.
/// Each result is at most n roundings of averages of coefficients: a split
/// adds at most n·ε/2·max|b| to their error. Degrees up to 8 run unrolled
/// (the same operations in the same order, so the same bits).
inline void split_bernstein(const double* b, int n, double* left, double* right) {
    using namespace bernstein_detail;
    switch (n) {
        case 1: split_fixed<1>(b, left, right); return;
        case 2: split_fixed<2>(b, left, right); return;
        case 3: split_fixed<3>(b, left, right); return;
        case 4: split_fixed<4>(b, left, right); return;
        case 5: split_fixed<5>(b, left, right); return;
        case 6: split_fixed<6>(b, left, right); return;
        case 7: split_fixed<7>(b, left, right); return;
        case 8: split_fixed<8>(b, left, right); return;
        default: split_any(b, n, left, right); return;
    }
}

/// A bound on the conversion's rounding error in each coefficient: n + 1
/// roundings of terms up to `magnitude`.
inline double bernstein_noise(int n, double magnitude) {
    return 2.0 * static_cast<double>(n + 1) * std::numeric_limits<double>::epsilon() * magnitude;
}

}  // namespace zeroset
