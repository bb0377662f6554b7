// The power basis to the Bernstein basis: a Taylor shift, a scaling, and
// the binomial weights.
#include "zeroset/roots/bernstein.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace zeroset {

namespace {

constexpr std::size_t at(int i) { return static_cast<std::size_t>(i); }

/// Binomial coefficients C(n, k) for n ≤ 32, exact in doubles.
constexpr auto binomials = [] {
    std::array<PolynomialScratch, max_polynomial_degree + 1> b{};
    for (std::size_t n = 0; n < b.size(); ++n) {
        b[n][0] = 1.0;
        for (std::size_t k = 1; k <= n; ++k) b[n][k] = b[n - 1][k - 1] + (k < n ? b[n - 1][k] : 0.0);
    }
    return b;
}();

/// A coefficient and the same computed on |cᵢ| and |t0|, side by side: one
/// 128-bit operation serves both (GCC's and Clang's vector extension; SSE2
/// is in every x86-64). In two arrays the compiler paired them itself and
/// read back as one 16-byte load what it had stored as two 8-byte halves,
/// which stalls.
using Pair = double __attribute__((vector_size(16)));

/// The conversion of a degree-n polynomial in arrays of `Capacity`: a
/// Taylor shift to t0 (repeated synthetic division), a scaling by t1 − t0
/// and the binomial weights C(k, i)/C(n, i). The same on |cᵢ| and |t0|
/// gives the scale of each result's rounding. Inlined with a constant n the
/// loops unroll and the weights fold.
template <std::size_t Capacity>
[[gnu::always_inline]] inline void convert(const double* p, int n, double t0, double t1, double* b, double& magnitude) {
    std::array<Pair, Capacity> a;
    for (int i = 0; i <= n; ++i) a[at(i)] = Pair{p[i], std::abs(p[i])};
    const Pair shift{t0, std::abs(t0)};
    for (int i = 0; i < n; ++i) {
        for (int j = n - 1; j >= i; --j) a[at(j)] += shift * a[at(j + 1)];
    }
    double scale = 1.0;
    for (int i = 0; i <= n; ++i, scale *= t1 - t0) a[at(i)] *= scale;
    magnitude = 0.0;
    for (int k = 0; k <= n; ++k) {
        Pair sum{0.0, 0.0};
        for (int i = 0; i <= k; ++i) {
            const double weight = binomials[at(k)][at(i)] / binomials[at(n)][at(i)];
            sum += weight * a[at(i)];
        }
        b[k] = sum[0];
        magnitude = std::max(magnitude, sum[1]);
    }
}

template <int N>
void convert_fixed(const double* p, double t0, double t1, double* b, double& magnitude) {
    convert<N + 1>(p, N, t0, t1, b, magnitude);
}

/// Degrees 1 to 8 (the ray polynomials of most surfaces) unrolled.
using FixedConversion = void (*)(const double*, double, double, double*, double&);
constexpr std::array<FixedConversion, 9> fixed_conversions = {
    nullptr,         convert_fixed<1>, convert_fixed<2>, convert_fixed<3>, convert_fixed<4>,
    convert_fixed<5>, convert_fixed<6>, convert_fixed<7>, convert_fixed<8>,
};

/// de Casteljau's triangle at the middle for a degree N known at compile
/// time: unrolled, every value in a register. The generic loop kept the
/// triangle's rows in memory, and each row's paired loads read the stores
/// of the row before at another offset, which the store buffer cannot
/// forward (a stall per row).
template <int N>
[[gnu::always_inline]] inline void split_fixed(const double* b, double* left, double* right) {
    // The first row straight from b: copied first, b went through the stack.
    double w[N];
    left[0] = b[0];
    right[N] = b[N];
    for (int i = 0; i < N; ++i) w[i] = 0.5 * (b[i] + b[i + 1]);
    left[1] = w[0];
    right[N - 1] = w[N - 1];
    for (int r = 2; r <= N; ++r) {
        for (int i = 0; i <= N - r; ++i) w[i] = 0.5 * (w[i] + w[i + 1]);
        left[r] = w[0];
        right[N - r] = w[N - r];
    }
}

[[gnu::always_inline]] inline void split_any(const double* b, int n, double* left, double* right) {
    PolynomialScratch w{};  // zeroed: GCC cannot see that n ≥ 9 here, and warns
    for (int i = 0; i <= n; ++i) w[at(i)] = b[i];
    left[0] = w[0];
    right[n] = w[at(n)];
    for (int r = 1; r <= n; ++r) {
        for (int i = 0; i <= n - r; ++i) w[at(i)] = 0.5 * (w[at(i)] + w[at(i) + 1]);
        left[r] = w[0];
        right[n - r] = w[at(n - r)];
    }
}

}  // namespace

// Into the caller's array, not a returned one: zeroing a whole scratch
// array (33 doubles) for a quartic's five coefficients was most of the cost
// of a call.
void to_bernstein(std::span<const double> p, int n, double t0, double t1, std::span<double> out, double& magnitude) {
    if (n >= 1 && n < static_cast<int>(fixed_conversions.size()))
        fixed_conversions[at(n)](p.data(), t0, t1, out.data(), magnitude);
    else
        convert<max_polynomial_degree + 1>(p.data(), n, t0, t1, out.data(), magnitude);
}

// Not vectorised: GCC's vectorisers pack the triangle's neighbours
// into pairs through the stack (stores of one row, unaligned loads of the
// next), the very stall the unrolled form is there to avoid; in scalars
// the triangle stays in registers. Degrees up to 8 run unrolled (the same
// operations in the same order as the generic loop, so the same bits).
#if defined(__GNUC__) && !defined(__clang__)
#define ZEROSET_SCALAR_ONLY [[gnu::optimize("no-tree-vectorize")]]
#else
#define ZEROSET_SCALAR_ONLY  // clang has no per-function optimize attribute
#endif
ZEROSET_SCALAR_ONLY void split_bernstein(const double* b, int n, double* left, double* right) {
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
#undef ZEROSET_SCALAR_ONLY

}  // namespace zeroset
