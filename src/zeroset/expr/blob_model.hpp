// BlobModel: a blobby object as its kernels (survey §2, §3.1, §3.2) — a
// threshold T and components, each a kernel K of the scaled squared distance
// u = |L⁻¹(p − c)|² / R² from its center c (L an affine map, the identity for
// a sphere, a scale or shear for an ellipsoid), times a strength s. The field is
// F(p) = Σ sᵢ·K(uᵢ), the solid is F ≥ T, and the implicit function (negative
// inside, as everywhere in zeroset) is f = T − F.
//
// The four kernels, one table (blob_kernels()):
//   blinn     Blinn's Gaussian (eq. 12): K = e^(B·(u − 1)) with blobbiness
//             B < 0, so that K(1) = 1 — a lone component of strength T is a
//             sphere of radius R; eq. 12 is T = 1, s = 1, R = 1, B = −1.
//   metaball  Nishimura's piecewise quadratic in ρ = √u (§3.1): 1 − 3ρ² up to
//             ρ = 1/3, then (3/2)(1 − ρ)², 0 from ρ = 1.
//   soft      Wyvill's soft objects (eq. 23) with R the radius of influence:
//             1 − 22/9 u + 17/9 u² − 4/9 u³ for u < 1; eq. 24 is R = 2, s = 2, T = 1.
//   povray    POV-Ray's blob kernel (1 − u)² for u < 1.
//
// The model is what the blob primitive (accel/blob.hpp) traces; it also
// writes itself as an ordinary expression, so that every general method can
// trace the same field for comparison.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "zeroset/expr/expr.hpp"
#include "zeroset/math/interval.hpp"
#include "zeroset/math/mat4.hpp"
#include "zeroset/math/scalar.hpp"
#include "zeroset/math/vec3.hpp"

namespace zeroset {

enum class BlobKernel : std::uint8_t { Blinn, Metaball, Soft, PovRay };

struct BlobKernelInfo {
    BlobKernel kernel;
    std::string_view name;         // in the scene language
    std::string_view description;  // for messages and the render summary
    /// K(u) = 0 for u ≥ 1 (Blinn's Gaussian never vanishes).
    bool finite_support;
    /// K as a polynomial in u on [0, 1), ascending powers; empty when it is none.
    std::span<const double> polynomial;
};

std::span<const BlobKernelInfo> blob_kernels();
const BlobKernelInfo& blob_kernel_info(BlobKernel kernel);
std::optional<BlobKernel> blob_kernel_named(std::string_view name);

/// POV-Ray's kernel (1 − u)² on [0, 1), for doubles and intervals: in this
/// factored form, not the table's expanded one, so that near u = 1, where K
/// is small, it is found to a few units of itself (1 − u is exact there)
/// rather than of 1.
template <class T>
T povray_kernel(const T& u) {
    const T w = T(1.0) - u;
    return w * w;
}
/// Its slope dK/du = −2(1 − u).
template <class T>
T povray_kernel_slope(const T& u) {
    return T(-2.0) * (T(1.0) - u);
}

/// K(u) and dK/du for u ≥ 0 (`blobbiness` is Blinn's B; the others ignore it).
struct KernelValue {
    double value;
    double slope;
};
/// kernel_at and kernel_value_at for the kernels other than POV-Ray's.
KernelValue other_kernel_at(BlobKernel kernel, double u, double blobbiness);
double other_kernel_value_at(BlobKernel kernel, double u, double blobbiness);
/// POV-Ray's inline: blobs ask for it once a component and segment, a point and a normal.
inline KernelValue kernel_at(BlobKernel kernel, double u, double blobbiness) {
    if (kernel != BlobKernel::PovRay) return other_kernel_at(kernel, u, blobbiness);
    if (u >= 1.0) return {0.0, 0.0};
    return {povray_kernel(u), povray_kernel_slope(u)};
}
/// K(u) alone (one exponential for Blinn's, not two).
inline double kernel_value_at(BlobKernel kernel, double u, double blobbiness) {
    if (kernel != BlobKernel::PovRay) return other_kernel_value_at(kernel, u, blobbiness);
    return u >= 1.0 ? 0.0 : povray_kernel(u);
}
/// An upper bound on the exact K(u), u ≥ 0 (the polynomials' as their
/// double coefficients give them), from the computed value and a bound on
/// its rounding, r the unit roundoff: POV-Ray's (1 − u)² is within 3r of
/// itself; Blinn's e^(B(u − 1)) within (2|B(u − 1)| + 3)r of itself (the
/// argument's two roundings, then glibc's exp, under an ulp); soft
/// objects' cubic by Horner within γ₆·Σ|cᵢ| on [0, 1); the metaball's
/// pieces (each term below 1) within 8r. Each is taken with room to spare.
double other_kernel_value_above(BlobKernel kernel, double u, double blobbiness);
inline double kernel_value_above(BlobKernel kernel, double u, double blobbiness) {
    if (kernel != BlobKernel::PovRay) return other_kernel_value_above(kernel, u, blobbiness);
    return u >= 1.0 ? 0.0 : povray_kernel(u) * (1.0 + 4.0 * unit_roundoff);
}
/// An outward-rounded enclosure of K over u ∈ U (U ≥ 0): every kernel
/// decreases in u, so it is [K(U.hi), K(U.lo)] widened by the evaluations'
/// rounding.
Interval kernel_over(BlobKernel kernel, const Interval& u, double blobbiness);
/// The same for dK/du over U.
Interval kernel_slope_over(BlobKernel kernel, const Interval& u, double blobbiness);

/// Blinn's Gaussians are cut off where a component's contribution falls
/// below this fraction of the threshold.
inline constexpr double default_blinn_tolerance = 1e-7;

struct BlobComponent {
    Vec3d center{};
    double radius = 1.0;    // R > 0
    double strength = 1.0;  // s ≠ 0; negative subtracts
    /// Blinn's B < 0 (blinn only).
    double blobbiness = -1.0;
    /// L: the component's shape, applied to its kernel about the origin
    /// before it moves to its center (an ellipsoid's axes); the identity for
    /// a sphere.
    Mat4 shape = Mat4::identity();
    /// A cylinder (POV-Ray's cylinder component): the segment from `center`
    /// to `end`, u the squared distance to it over R² — round at both ends,
    /// where it is the sphere about the end. A cylinder has no shape.
    std::optional<Vec3d> end;

    [[nodiscard]] bool is_cylinder() const { return end.has_value(); }
};

class BlobModel {
public:
    /// Throws std::invalid_argument for a threshold that is not finite and
    /// positive, no components, or a component with a radius that is not
    /// finite and positive, a zero or non-finite strength, a blobbiness that
    /// is not negative (blinn), a singular shape, or a cylinder whose ends
    /// coincide or that has a shape.
    BlobModel(BlobKernel kernel, double threshold, std::vector<BlobComponent> components);

    [[nodiscard]] BlobKernel kernel() const { return kernel_; }
    [[nodiscard]] double threshold() const { return threshold_; }
    [[nodiscard]] const std::vector<BlobComponent>& components() const { return components_; }

    /// The map from blob space to component i's kernel space, where u = |q|²
    /// (its center at the origin, its radius 1): q = M·p + m. For a
    /// cylinder, the map about its start, which gives u only before the
    /// plane through it (u_at has the whole).
    [[nodiscard]] const Mat4& to_kernel(std::size_t i) const { return to_kernel_[i]; }
    /// u of component i at p (beyond its reach too).
    [[nodiscard]] double u_at(std::size_t i, const Vec3d& p) const;

    /// u up to which component i counts: 1 where a finite kernel ends; for
    /// Blinn's Gaussian, where |s|·K falls to tolerance·T (≤ 0: nowhere).
    [[nodiscard]] double reach(std::size_t i, double tolerance) const;
    /// The box of component i's reach (its ellipsoid u ≤ reach), rounded outward.
    [[nodiscard]] Box3 reach_box(std::size_t i, double reach) const;
    /// The union of the reach boxes of the components of positive strength,
    /// which holds the solid (F ≥ T > 0 needs one of them); nothing when
    /// there is none.
    [[nodiscard]] std::optional<Box3> solid_bounds(double tolerance) const;

    /// f = T − Σ sᵢ·K(uᵢ) as an expression in x, y, z, summed as a balanced
    /// tree (built on each call: it is large for a large blob).
    [[nodiscard]] Expr field_expression() const;

private:
    BlobKernel kernel_;
    double threshold_;
    std::vector<BlobComponent> components_;
    std::vector<Mat4> to_kernel_;
};

}  // namespace zeroset
