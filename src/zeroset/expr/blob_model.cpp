// The kernels' table and formulas, once for doubles and once for intervals,
// and the field written as an expression.
#include "zeroset/expr/blob_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "zeroset/expr/functions.hpp"

namespace zeroset {

namespace {

constexpr std::array<double, 4> soft_polynomial{1.0, -22.0 / 9.0, 17.0 / 9.0, -4.0 / 9.0};
constexpr std::array<double, 3> povray_polynomial{1.0, -2.0, 1.0};

constexpr std::array<BlobKernelInfo, 4> kernels{{
    {BlobKernel::Blinn, "blinn", "Blinn's Gaussian e^(B(u-1)) (eq. 12)", false, {}},
    {BlobKernel::Metaball, "metaball", "Nishimura's piecewise quadratic metaball (sec. 3.1)", true, {}},
    {BlobKernel::Soft, "soft", "Wyvill's soft-object polynomial C (eq. 23)", true, soft_polynomial},
    {BlobKernel::PovRay, "povray", "POV-Ray's (1 - u)^2", true, povray_polynomial},
}};

/// K(u) for a number type T (double, or Interval for a point enclosure);
/// u ≥ 0 is a point, so the pieces are chosen exactly.
template <class T>
T kernel_value(BlobKernel kernel, double u, double blobbiness) {
    const T w(u);
    switch (kernel) {
        case BlobKernel::Blinn: return exp(T(blobbiness) * (w - T(1.0)));
        case BlobKernel::Metaball: {
            if (u >= 1.0) return T(0.0);
            if (u <= 1.0 / 9.0) return T(1.0) - T(3.0) * w;
            const T one_minus = T(1.0) - sqrt(w);
            return T(1.5) * one_minus * one_minus;
        }
        case BlobKernel::PovRay: return u >= 1.0 ? T(0.0) : povray_kernel(w);
        case BlobKernel::Soft: {
            if (u >= 1.0) return T(0.0);
            const std::span<const double> c = blob_kernel_info(kernel).polynomial;
            T sum(c.back());
            for (std::size_t i = c.size() - 1; i-- > 0;) sum = sum * w + T(c[i]);
            return sum;
        }
    }
    return T(0.0);
}

/// dK/du for a number type T, as kernel_value.
template <class T>
T kernel_slope(BlobKernel kernel, double u, double blobbiness) {
    const T w(u);
    switch (kernel) {
        case BlobKernel::Blinn: return T(blobbiness) * exp(T(blobbiness) * (w - T(1.0)));
        case BlobKernel::Metaball: {
            if (u >= 1.0) return T(0.0);
            if (u <= 1.0 / 9.0) return T(-3.0);
            return T(-1.5) * (T(1.0) / sqrt(w) - T(1.0));
        }
        case BlobKernel::PovRay: return u >= 1.0 ? T(0.0) : povray_kernel_slope(w);
        case BlobKernel::Soft: {
            if (u >= 1.0) return T(0.0);
            const std::span<const double> c = blob_kernel_info(kernel).polynomial;
            T sum(static_cast<double>(c.size() - 1) * c.back());
            for (std::size_t i = c.size() - 1; i-- > 1;) sum = sum * w + T(static_cast<double>(i) * c[i]);
            return sum;
        }
    }
    return T(0.0);
}

/// The kernel of one component as an expression in the scaled squared distance u.
Expr kernel_expression(BlobKernel kernel, const Expr& u, double blobbiness) {
    switch (kernel) {
        case BlobKernel::Blinn: return exp(blobbiness * (u - 1.0));
        case BlobKernel::Metaball: {
            // The inner piece clamped at ρ = 1/3 plus the outer piece clamped
            // to [1/3, 1], less their common value 2/3 at ρ = 1/3: each
            // piece is constant where the other one holds.
            const Expr inner = 1.0 - 3.0 * min(u, Expr(1.0 / 9.0));
            const Expr rho = min(max(sqrt(u), Expr(1.0 / 3.0)), Expr(1.0));
            return inner + 1.5 * square(1.0 - rho) - 2.0 / 3.0;
        }
        case BlobKernel::Soft:
        case BlobKernel::PovRay: {
            const Expr w = min(u, Expr(1.0));  // K(1) = K′(1) = 0: the clamp is K's zero tail
            const std::span<const double> c = blob_kernel_info(kernel).polynomial;
            Expr sum(c.back());
            for (std::size_t i = c.size() - 1; i-- > 0;) sum = sum * w + c[i];
            return sum;
        }
    }
    return Expr();
}

/// Throws for a cylinder that cannot be traced: ends not finite, too close
/// or too far apart to measure, or a shape.
void check_cylinder(const BlobComponent& c, const std::string& which) {
    const Vec3d& end = *c.end;
    if (!(std::isfinite(end.x) && std::isfinite(end.y) && std::isfinite(end.z)))
        throw std::invalid_argument(which + "the cylinder's end must be finite");
    const Vec3d w = end - c.center;
    const double length2 = dot(w, w);
    if (w == Vec3d{}) throw std::invalid_argument(which + "the cylinder's ends must differ (a sphere has one center)");
    if (!(length2 > 0.0 && std::isfinite(length2)))
        throw std::invalid_argument(which + "the cylinder's length is beyond what a double can square");
    if (!(c.shape == Mat4::identity()))
        throw std::invalid_argument(which + "a cylinder takes no shape: move its ends instead");
}

/// The point of the segment [a, b] nearest p.
Vec3d nearest_on_segment(const Vec3d& a, const Vec3d& b, const Vec3d& p) {
    const Vec3d w = b - a;
    const double s = std::clamp(dot(p - a, w) / dot(w, w), 0.0, 1.0);
    return a + s * w;
}

/// The terms summed pairwise, so that a blob of n components is an
/// expression of depth log₂ n rather than n.
Expr balanced_sum(std::vector<Expr>& terms, std::size_t lo, std::size_t hi) {
    if (hi - lo == 1) return terms[lo];
    const std::size_t mid = lo + (hi - lo) / 2;
    return balanced_sum(terms, lo, mid) + balanced_sum(terms, mid, hi);
}

}  // namespace

std::span<const BlobKernelInfo> blob_kernels() { return kernels; }

const BlobKernelInfo& blob_kernel_info(BlobKernel kernel) { return kernels[static_cast<std::size_t>(kernel)]; }

std::optional<BlobKernel> blob_kernel_named(std::string_view name) {
    for (const BlobKernelInfo& k : kernels)
        if (k.name == name) return k.kernel;
    return std::nullopt;
}

KernelValue other_kernel_at(BlobKernel kernel, double u, double blobbiness) {
    if (kernel == BlobKernel::Blinn) {  // K′ = B·K: one exponential
        const double v = kernel_value<double>(kernel, u, blobbiness);
        return {v, blobbiness * v};
    }
    return {kernel_value<double>(kernel, u, blobbiness), kernel_slope<double>(kernel, u, blobbiness)};
}

double other_kernel_value_at(BlobKernel kernel, double u, double blobbiness) {
    return kernel_value<double>(kernel, u, blobbiness);
}

double other_kernel_value_above(BlobKernel kernel, double u, double blobbiness) {
    if (kernel == BlobKernel::PovRay) return kernel_value_above(kernel, u, blobbiness);  // the inline one's
    constexpr double soft_magnitude = [] {
        double sum = 0.0;
        for (const double c : soft_polynomial) sum += c < 0.0 ? -c : c;
        return sum;
    }();
    const double k = kernel_value<double>(kernel, u, blobbiness);
    if (kernel == BlobKernel::Blinn) return k * (1.0 + (4.0 * std::abs(blobbiness * (u - 1.0)) + 8.0) * unit_roundoff);
    if (u >= 1.0) return 0.0;  // soft objects and metaballs vanish there exactly
    return k + 8.0 * unit_roundoff * (kernel == BlobKernel::Soft ? soft_magnitude : 1.0);
}

Interval kernel_over(BlobKernel kernel, const Interval& u, double blobbiness) {
    // Blinn's in one interval exponential (two calls of exp, not four).
    if (kernel == BlobKernel::Blinn) return exp(Interval(blobbiness) * (u - Interval(1.0)));
    // Every kernel decreases in u ≥ 0.
    return {kernel_value<Interval>(kernel, u.hi, blobbiness).lo, kernel_value<Interval>(kernel, u.lo, blobbiness).hi};
}

Interval kernel_slope_over(BlobKernel kernel, const Interval& u, double blobbiness) {
    // Blinn's slope is B·K, so one enclosure serves both.
    if (kernel == BlobKernel::Blinn) return Interval(blobbiness) * kernel_over(kernel, u, blobbiness);
    // Every kernel's slope increases in u ≥ 0 (it is convex there).
    return {kernel_slope<Interval>(kernel, u.lo, blobbiness).lo, kernel_slope<Interval>(kernel, u.hi, blobbiness).hi};
}

BlobModel::BlobModel(BlobKernel kernel, double threshold, std::vector<BlobComponent> components)
    : kernel_(kernel), threshold_(threshold), components_(std::move(components)) {
    if (!(std::isfinite(threshold) && threshold > 0.0))
        throw std::invalid_argument("a blob's threshold must be a positive number");
    if (components_.empty()) throw std::invalid_argument("a blob needs at least one component");
    to_kernel_.reserve(components_.size());
    for (std::size_t i = 0; i < components_.size(); ++i) {
        const BlobComponent& c = components_[i];
        const std::string which = "component " + std::to_string(i + 1) + ": ";
        if (!(std::isfinite(c.radius) && c.radius > 0.0))
            throw std::invalid_argument(which + "the radius must be a positive number");
        if (!(std::isfinite(c.strength) && c.strength != 0.0))
            throw std::invalid_argument(which + "the strength must be a nonzero number");
        if (kernel == BlobKernel::Blinn && !(std::isfinite(c.blobbiness) && c.blobbiness < 0.0))
            throw std::invalid_argument(which + "Blinn's blobbiness must be a negative number");
        if (kernel == BlobKernel::Blinn && !std::isfinite(std::abs(c.strength) * std::exp(-c.blobbiness)))
            throw std::invalid_argument(which + "its peak, strength × e^(-blobbiness), overflows a double");
        if (!(std::isfinite(c.center.x) && std::isfinite(c.center.y) && std::isfinite(c.center.z)))
            throw std::invalid_argument(which + "the center must be finite");
        if (c.is_cylinder()) check_cylinder(c, which);
        const std::optional<Mat4> inverse = c.shape.inverse();
        if (!c.shape.is_finite() || !inverse || !(c.shape.squareness() > 1e-12))
            throw std::invalid_argument(which + "the shape is singular (it flattens the component)");
        // q = (1/R)·L⁻¹·(p − c)
        const Mat4 map = Mat4::scale({1.0 / c.radius, 1.0 / c.radius, 1.0 / c.radius}) * *inverse * Mat4::translate(-c.center);
        const std::optional<Mat4> back = map.inverse();
        if (!map.is_finite() || !back || !back->is_finite())
        {
            char radius[32];
            std::snprintf(radius, sizeof radius, "%.3g", c.radius);
            throw std::invalid_argument(which + "its radius and shape map it outside what a double holds (radius " +
                                        radius + ")");
        }
        to_kernel_.push_back(map);
    }
}

double BlobModel::reach(std::size_t i, double tolerance) const {
    if (blob_kernel_info(kernel_).finite_support) return 1.0;
    const BlobComponent& c = components_[i];
    return 1.0 + std::log(tolerance * threshold_ / std::abs(c.strength)) / c.blobbiness;
}

double BlobModel::u_at(std::size_t i, const Vec3d& p) const {
    const BlobComponent& c = components_[i];
    if (c.is_cylinder()) {
        const Vec3d q = (p - nearest_on_segment(c.center, *c.end, p)) / c.radius;
        return dot(q, q);
    }
    const Vec3d q = to_kernel_[i].transform_point(p);
    return dot(q, q);
}

Box3 BlobModel::reach_box(std::size_t i, double reach) const {
    const BlobComponent& c = components_[i];
    if (c.is_cylinder()) {  // the spheres about its ends, and everything between
        const double r = std::sqrt(reach) * c.radius * (1.0 + 1e-12);
        const Vec3d half{r, r, r};
        return {min(c.center, *c.end) - half, max(c.center, *c.end) + half};
    }
    // p = M⁻¹(q − m) over |q| ≤ √reach: the center ± √reach times the rows' lengths.
    const Mat4 from_kernel = *to_kernel_[i].inverse();
    const Vec3d center = from_kernel.transform_point({0.0, 0.0, 0.0});
    const double r = std::sqrt(reach);
    Vec3d half;
    for (int j = 0; j < 3; ++j) {
        const auto& row = from_kernel.m[static_cast<std::size_t>(j)];
        half[j] = r * std::sqrt(row[0] * row[0] + row[1] * row[1] + row[2] * row[2]) * (1.0 + 1e-12);
    }
    return {center - half, center + half};
}

std::optional<Box3> BlobModel::solid_bounds(double tolerance) const {
    std::optional<Box3> box;
    for (std::size_t i = 0; i < components_.size(); ++i) {
        const double u = reach(i, tolerance);
        if (components_[i].strength < 0.0 || !(u > 0.0)) continue;
        const Box3 b = reach_box(i, u);
        box = box ? Box3{min(box->lo, b.lo), max(box->hi, b.hi)} : b;
    }
    return box;
}

Expr BlobModel::field_expression() const {
    std::vector<Expr> terms;
    terms.reserve(components_.size());
    const Expr x = var_x(), y = var_y(), z = var_z();
    for (std::size_t i = 0; i < components_.size(); ++i) {
        const BlobComponent& c = components_[i];
        if (c.is_cylinder()) {  // |p − a − s·w|² / R² with s = clamp((p − a)·w / w·w, 0, 1)
            const Vec3d w = *c.end - c.center;
            const Expr dx = x - c.center.x, dy = y - c.center.y, dz = z - c.center.z;
            const Expr s = clamp((dx * w.x + dy * w.y + dz * w.z) / dot(w, w), Expr(0.0), Expr(1.0));
            const Expr u = (square(dx - s * w.x) + square(dy - s * w.y) + square(dz - s * w.z)) / (c.radius * c.radius);
            terms.push_back(c.strength * kernel_expression(kernel_, u, c.blobbiness));
            continue;
        }
        const Mat4& m = to_kernel_[i];
        Expr u;
        for (int row = 0; row < 3; ++row) {
            const auto& r = m.m[static_cast<std::size_t>(row)];
            Expr coordinate(r[3]);  // the row's terms, zeros left out (x·0 is not folded away)
            for (int k = 0; k < 3; ++k)
                if (r[static_cast<std::size_t>(k)] != 0.0) coordinate = coordinate + r[static_cast<std::size_t>(k)] * (k == 0 ? x : k == 1 ? y : z);
            u = u + square(coordinate);
        }
        terms.push_back(components_[i].strength * kernel_expression(kernel_, u, components_[i].blobbiness));
    }
    return threshold_ - balanced_sum(terms, 0, terms.size());
}

}  // namespace zeroset
