// FractalEstimate: the distance estimates of deterministic 3-D fractals that
// sphere tracing was first made for (Hart, Sandin and Kauffman 1989; the
// survey's §5.2). A point is iterated; if it escapes, the rate at which it
// does bounds its distance to the set; if it has not escaped after the given
// number of iterations it counts as in the set (distance 0).
//
// Quaternion Julia sets: z ← z² + c over quaternions, z₀ = x + y·i + z·j +
// slice·k (the 3-D set is the slice of the 4-D one at k = slice). With the
// Hubbard–Douady potential G(z) = log|zₙ| / 2ⁿ and |∇G| = |z′ₙ| / (|zₙ|·2ⁿ),
// z′ ← 2·z·z′, Hart et al. bound the distance from below by
//     d ≥ sinh G / (2·e^G·|∇G|)          (≈ |zₙ|·log|zₙ| / (2·|z′ₙ|) near the set)
// — a theorem for complex Julia sets in the limit n → ∞, which the paper
// carries over to quaternions; evaluated after finitely many iterations it is
// an estimate, not a proof.
//
// Mandelbulbs (White and Nylander 2009, one more family): the power-p
// "triplex" map z ← zᵖ + z₀ in spherical coordinates, with the customary
// estimate d ≈ ½·r·log r / r′, r′ ← p·rᵖ⁻¹·r′ + 1. No bound is proven for it.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "zeroset/math/quaternion.hpp"
#include "zeroset/math/vec3.hpp"

namespace zeroset {

enum class FractalKind { QuaternionJulia, Mandelbulb };

struct FractalKindInfo {
    FractalKind kind;
    std::string_view name;  // in the scene language
    std::string_view description;
};
std::span<const FractalKindInfo> fractal_kinds();
const FractalKindInfo& fractal_kind_info(FractalKind kind);
std::optional<FractalKind> fractal_kind_named(std::string_view name);

struct FractalParameters {
    FractalKind kind = FractalKind::QuaternionJulia;
    Quaternion c{-0.2, 0.8, 0.0, 0.0};  // Julia: the constant of z² + c
    double slice = 0.0;                 // Julia: the k part of every point
    double power = 8.0;                 // Mandelbulb: p
    int iterations = 12;
};

/// The iteration counts a fractal may ask for, and the Mandelbulb's powers.
inline constexpr int max_fractal_iterations = 100;
inline constexpr double min_mandelbulb_power = 2.0;
inline constexpr double max_mandelbulb_power = 16.0;

class FractalEstimate {
public:
    /// Throws std::invalid_argument for iterations outside 1 … 100, a power
    /// outside 2 … 16, a non-finite c or slice, or a slice that misses the
    /// Julia set's ball.
    explicit FractalEstimate(FractalParameters parameters);

    [[nodiscard]] const FractalParameters& parameters() const { return parameters_; }
    /// The estimated distance from p to the set, ≥ 0; 0 for a point that has
    /// not escaped after the iterations (in the set, as far as they tell).
    [[nodiscard]] double distance(const Vec3d& p) const;
    /// The set lies in the ball of this radius about the origin.
    [[nodiscard]] double bounding_radius() const { return bounding_radius_; }
    /// Where an orbit counts as escaped, |z| > escape_radius.
    [[nodiscard]] double escape_radius() const { return escape_radius_; }

private:
    [[nodiscard]] double julia_distance(const Vec3d& p) const;
    [[nodiscard]] double mandelbulb_distance(const Vec3d& p) const;

    FractalParameters parameters_;
    double bounding_radius_ = 2.0;
    double escape_radius_ = 16.0;
};

}  // namespace zeroset
