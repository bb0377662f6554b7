// Qef::solve (qef.hpp): the normal equations AᵀA (x − m) = Aᵀr about the
// mass point m, solved by a Jacobi eigen-decomposition of the symmetric 3×3
// matrix with its small eigenvalues dropped (a truncated pseudo-inverse).
#include "zeroset/mesh/qef.hpp"

#include <algorithm>
#include <cmath>

namespace zeroset {

namespace {

using Mat3 = std::array<std::array<double, 3>, 3>;

/// Eigenvalues (the diagonal of `a`, on return) and eigenvectors (the
/// columns of the result) of a symmetric matrix, by cyclic Jacobi rotations.
/// Jacobi converges quadratically; 16 sweeps is far more than a 3×3 needs.
Mat3 jacobi_eigen(Mat3& a) {
    Mat3 v{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    for (int sweep = 0; sweep < 16; ++sweep) {
        const double off = std::abs(a[0][1]) + std::abs(a[0][2]) + std::abs(a[1][2]);
        const double scale = std::abs(a[0][0]) + std::abs(a[1][1]) + std::abs(a[2][2]);
        if (off <= 1e-15 * scale || off == 0.0) break;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (a[p][q] == 0.0) continue;
                const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                const double t = std::copysign(1.0, theta) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                for (int r = 0; r < 3; ++r) {  // a ← a·J
                    const double arp = a[r][p], arq = a[r][q];
                    a[r][p] = c * arp - s * arq;
                    a[r][q] = s * arp + c * arq;
                }
                for (int r = 0; r < 3; ++r) {  // a ← Jᵀ·a
                    const double apr = a[p][r], aqr = a[q][r];
                    a[p][r] = c * apr - s * aqr;
                    a[q][r] = s * apr + c * aqr;
                }
                for (int r = 0; r < 3; ++r) {  // v ← v·J
                    const double vrp = v[r][p], vrq = v[r][q];
                    v[r][p] = c * vrp - s * vrq;
                    v[r][q] = s * vrp + c * vrq;
                }
            }
    }
    return v;
}

}  // namespace

Vec3d Qef::solve(const Box3& bounds) const {
    if (count_ == 0) return bounds.center();
    Vec3d mass{};
    for (int n = 0; n < count_; ++n) mass += points_[static_cast<std::size_t>(n)];
    mass = mass / static_cast<double>(count_);
    Mat3 a{};
    Vec3d rhs{};  // Σ nᵢ (nᵢ·(pᵢ − m))
    for (int n = 0; n < count_; ++n) {
        const Vec3d& normal = normals_[static_cast<std::size_t>(n)];
        const double d = dot(normal, points_[static_cast<std::size_t>(n)] - mass);
        for (int r = 0; r < 3; ++r) {
            rhs[r] += normal[r] * d;
            for (int c = 0; c < 3; ++c) a[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] += normal[r] * normal[c];
        }
    }
    const Mat3 v = jacobi_eigen(a);
    const double largest = std::max({a[0][0], a[1][1], a[2][2]});
    Vec3d x = mass;
    for (int e = 0; e < 3; ++e) {
        const double lambda = a[static_cast<std::size_t>(e)][static_cast<std::size_t>(e)];
        if (!(lambda > flatness * largest)) continue;
        const Vec3d u{v[0][static_cast<std::size_t>(e)], v[1][static_cast<std::size_t>(e)], v[2][static_cast<std::size_t>(e)]};
        x += u * (dot(u, rhs) / lambda);
    }
    return max(bounds.lo, min(bounds.hi, x));
}

}  // namespace zeroset
