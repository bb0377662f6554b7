// The two distance estimates, and the balls their sets lie in.
#include "zeroset/trace/fractal_estimate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace zeroset {

namespace {

constexpr std::array<FractalKindInfo, 2> kinds{{
    {FractalKind::QuaternionJulia, "julia", "quaternion Julia set z² + c (Hart, Sandin and Kauffman 1989)"},
    {FractalKind::Mandelbulb, "mandelbulb", "Mandelbulb (White and Nylander's triplex power)"},
}};

bool finite(const Quaternion& q) {
    return std::isfinite(q.r) && std::isfinite(q.i) && std::isfinite(q.j) && std::isfinite(q.k);
}

}  // namespace

std::span<const FractalKindInfo> fractal_kinds() { return kinds; }

const FractalKindInfo& fractal_kind_info(FractalKind kind) {
    return *std::find_if(kinds.begin(), kinds.end(), [kind](const FractalKindInfo& k) { return k.kind == kind; });
}

std::optional<FractalKind> fractal_kind_named(std::string_view name) {
    for (const FractalKindInfo& k : kinds)
        if (k.name == name) return k.kind;
    return std::nullopt;
}

FractalEstimate::FractalEstimate(FractalParameters parameters) : parameters_(parameters) {
    const FractalParameters& p = parameters_;
    if (p.iterations < 1 || p.iterations > max_fractal_iterations)
        throw std::invalid_argument("the iterations must be between 1 and " + std::to_string(max_fractal_iterations));
    if (p.kind == FractalKind::Mandelbulb) {
        if (!(p.power >= min_mandelbulb_power && p.power <= max_mandelbulb_power))
            throw std::invalid_argument("a Mandelbulb's power must be between 2 and 16");
        // For |z₀| > 2 every step grows |z| by at least |z|ᵖ⁻¹ − 1 > 1: the set lies within 2.
        bounding_radius_ = 2.0;
        escape_radius_ = 4.0;
        return;
    }
    if (!finite(p.c) || !std::isfinite(p.slice)) throw std::invalid_argument("c and the slice must be finite");
    // Past R = (1 + √(1 + 4|c|))/2, |z² + c| ≥ |z|² − |c| > |z|: the orbit escapes.
    const double radius = 0.5 * (1.0 + std::sqrt(1.0 + 4.0 * std::sqrt(norm_squared(p.c))));
    if (std::abs(p.slice) >= radius)
        throw std::invalid_argument("the slice k = " + std::to_string(p.slice) +
                                    " misses the Julia set, which lies within |q| < " + std::to_string(radius));
    bounding_radius_ = std::sqrt(radius * radius - p.slice * p.slice);
    escape_radius_ = std::max(16.0, 2.0 * radius);
}

double FractalEstimate::distance(const Vec3d& p) const {
    const double d = parameters_.kind == FractalKind::Mandelbulb ? mandelbulb_distance(p) : julia_distance(p);
    return d > 0.0 ? d : 0.0;  // NaN (an overflow) too: as if in the set, the careful side
}

double FractalEstimate::julia_distance(const Vec3d& p) const {
    Quaternion z{p.x, p.y, p.z, parameters_.slice};
    Quaternion dz{1.0, 0.0, 0.0, 0.0};
    const double escape2 = escape_radius_ * escape_radius_;
    double scale = 1.0;  // 2ⁿ
    for (int n = 0; n < parameters_.iterations; ++n) {
        dz = 2.0 * (z * dz);
        z = squared(z) + parameters_.c;
        scale *= 2.0;
        const double r2 = norm_squared(z);
        if (r2 > escape2) {
            // sinh G / (2·e^G·|∇G|) = (1 − e^(−2G)) / (4·|∇G|), G = log|z|/2ⁿ, |∇G| = |z′|/(|z|·2ⁿ).
            const double r = std::sqrt(r2);
            const double potential = std::log(r) / scale;
            return -std::expm1(-2.0 * potential) * r * scale / (4.0 * std::sqrt(norm_squared(dz)));
        }
    }
    return 0.0;
}

double FractalEstimate::mandelbulb_distance(const Vec3d& p) const {
    const double power = parameters_.power;
    Vec3d z = p;
    double dr = 1.0;
    double r = length(z);
    for (int n = 0; n < parameters_.iterations && r <= escape_radius_; ++n) {
        if (r == 0.0) {
            z = p;  // 0ᵖ + z₀; r′ = p·0 + 1
            dr = 1.0;
        } else {
            dr = power * std::pow(r, power - 1.0) * dr + 1.0;
            const double theta = power * std::acos(std::clamp(z.z / r, -1.0, 1.0));
            const double phi = power * std::atan2(z.y, z.x);
            const double rp = std::pow(r, power);
            z = Vec3d{rp * std::sin(theta) * std::cos(phi), rp * std::sin(theta) * std::sin(phi), rp * std::cos(theta)} + p;
        }
        r = length(z);
    }
    if (r <= escape_radius_) return 0.0;
    return 0.5 * std::log(r) * r / dr;
}

}  // namespace zeroset
