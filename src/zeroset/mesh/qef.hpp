// The vertex of dual contouring (Ju, Losasso, Schaefer and Warren 2002): the
// point x of a cell closest, in least squares, to the tangent planes of the
// surface where it crosses the cell's edges — Σ (nᵢ·(x − pᵢ))², the quadric
// error function. Where the planes meet at a corner or along an edge of the
// surface, x lands on it, which keeps sharp features that a vertex on a grid
// edge would cut. Directions in which the planes barely constrain x (a flat
// or smoothly curved patch) are left at the crossings' mean (the "mass
// point"), so x stays near the crossings instead of running off to where
// nearly parallel planes meet; then x is clamped into the box it may use.
#pragma once

#include <array>

#include "zeroset/math/box3.hpp"

namespace zeroset {

class Qef {
public:
    /// A crossing of the surface and its unit normal — a zero normal where
    /// the gradient there is not usable (the crossing then counts only in
    /// the mass point).
    void add(const Vec3d& point, const Vec3d& unit_normal) {
        points_[static_cast<std::size_t>(count_)] = point;
        normals_[static_cast<std::size_t>(count_)] = unit_normal;
        ++count_;
    }

    /// The minimiser, clamped into `bounds`; their centre when no crossing
    /// was added. A cell has at most 12 crossings.
    [[nodiscard]] Vec3d solve(const Box3& bounds) const;

    /// Eigenvalues below this fraction of the largest are treated as zero:
    /// two planes less than about 16° apart do not make a feature
    /// (their eigenvalues are 1 ± cos θ).
    static constexpr double flatness = 0.02;

private:
    std::array<Vec3d, 12> points_{};
    std::array<Vec3d, 12> normals_{};
    int count_ = 0;
};

}  // namespace zeroset
