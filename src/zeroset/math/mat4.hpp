// Mat4: homogeneous 4×4 transforms. Affine deformations act on rays through
// their inverse (survey §9, eq. 36), so the inverse is a first-class operation.
#pragma once

#include <array>
#include <optional>

#include "zeroset/math/box3.hpp"
#include "zeroset/math/vec3.hpp"

namespace zeroset {

struct Mat4 {
    std::array<std::array<double, 4>, 4> m{};  // m[row][column]

    static Mat4 identity();
    static Mat4 translate(const Vec3d& t);
    static Mat4 scale(const Vec3d& s);
    /// Rotation by `radians` about the (normalised) `axis`, right-handed.
    static Mat4 rotate(const Vec3d& axis, double radians);
    /// The same in degrees, with exact sines and cosines at multiples of 90°
    /// (a quarter turn about z takes x exactly to y).
    static Mat4 rotate_degrees(const Vec3d& axis, double degrees);
    /// Rotation about x by angles.x degrees, then about y, then about z.
    static Mat4 rotate_xyz_degrees(const Vec3d& angles);

    [[nodiscard]] Mat4 operator*(const Mat4& o) const;
    [[nodiscard]] Mat4 transpose() const;
    /// The inverse, or nothing when the matrix is singular.
    [[nodiscard]] std::optional<Mat4> inverse() const;

    // Inline: every ray through an instance takes two of these.
    /// Applies the matrix to (p, 1).
    [[nodiscard]] Vec3d transform_point(const Vec3d& p) const {
        return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
                m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
                m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
    }
    /// Applies the matrix to (v, 0).
    [[nodiscard]] Vec3d transform_vector(const Vec3d& v) const {
        return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
    }
    /// Applies the transpose of the linear part to v: for the map from a
    /// parent's space into a child's, this takes a child's gradient (normal)
    /// to the parent's (survey §8: normals by the inverse transpose).
    [[nodiscard]] Vec3d transpose_transform_vector(const Vec3d& v) const {
        return {m[0][0] * v.x + m[1][0] * v.y + m[2][0] * v.z, m[0][1] * v.x + m[1][1] * v.y + m[2][1] * v.z,
                m[0][2] * v.x + m[1][2] * v.y + m[2][2] * v.z};
    }
    /// The smallest box containing the image of `box` (its eight corners'
    /// images, rounded outward); an unbounded box stays unbounded.
    [[nodiscard]] Box3 transform_box(const Box3& box) const;
    /// The largest length of a column of the linear part: how much the map
    /// may stretch a length, to within a factor of √3.
    [[nodiscard]] double max_stretch() const;
    [[nodiscard]] bool is_identity() const { return *this == identity(); }
    /// Whether every entry is a finite number.
    [[nodiscard]] bool is_finite() const;
    /// |det A| over the product of A's column lengths, for the linear part
    /// A: 1 for a rotation or any scale, 0 for a map that flattens space —
    /// how far from singular the map is, whatever its size.
    [[nodiscard]] double squareness() const;

    friend bool operator==(const Mat4&, const Mat4&) = default;
};

}  // namespace zeroset
