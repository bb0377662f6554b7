// A ray against a plane, in closed form.
#include "zeroset/accel/half_space.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/ray_polynomial.hpp"

namespace zeroset {

HalfSpace::HalfSpace(std::string name, const Expr& f, MaterialId material) : name_(std::move(name)), material_(material) {
    const Tape tape(f);
    if (polynomial_degree(tape) != 1)
        throw std::invalid_argument("an object without bounds must be a plane: its surface must be of degree 1 in "
                                    "x, y and z (give it bounds otherwise)");
    Evaluator<Dual<double>> gradient(tape);
    const Dual<double> at_origin = evaluate_gradient(gradient, {0.0, 0.0, 0.0});
    n_ = at_origin.g;
    c_ = at_origin.v;
    if (!(length(n_) > 0.0) || !std::isfinite(length(n_)) || !std::isfinite(c_))
        throw std::invalid_argument("the plane's surface has no direction (its gradient is zero or not finite)");
}

Box3 HalfSpace::bounds() const {
    constexpr double inf = std::numeric_limits<double>::infinity();
    return {{-inf, -inf, -inf}, {inf, inf, inf}};
}

Hit HalfSpace::boundary(const Ray& ray, double t, BoundaryKind kind) const {
    SurfaceRef s;
    s.kind = kind;
    s.material = material_;
    if (kind != BoundaryKind::Open) {
        s.leaf = this;
        s.local_point = ray.at(t);
        s.scale = std::max(1.0, length(s.local_point));  // no size of its own: the distance from the origin
    }
    return {t, s};
}

std::optional<Hit> HalfSpace::first_hit(const Ray& ray, double t_min, double t_max, TraceScratch&) const {
    const double f0 = dot(n_, ray.at(t_min)) + c_, slope = dot(n_, ray.dir);
    if (f0 <= 0.0) return boundary(ray, t_min, f0 == 0.0 ? BoundaryKind::Surface : BoundaryKind::Open);
    if (!(slope < 0.0)) return std::nullopt;
    const double t = t_min - f0 / slope;
    if (!(t <= t_max)) return std::nullopt;
    return boundary(ray, t, BoundaryKind::Surface);
}

void HalfSpace::spans(const Ray& ray, double t_min, double t_max, TraceScratch&, SpanList& out) const {
    const double f0 = dot(n_, ray.at(t_min)) + c_, slope = dot(n_, ray.dir);
    const double crossing = slope != 0.0 ? t_min - f0 / slope : std::numeric_limits<double>::infinity();
    if (f0 <= 0.0) {  // inside at t_min, until the ray leaves through the plane
        const bool leaves = slope > 0.0 && crossing < t_max;
        out.push_back({boundary(ray, t_min, f0 == 0.0 ? BoundaryKind::Surface : BoundaryKind::Open),
                       leaves ? boundary(ray, crossing, BoundaryKind::Surface) : boundary(ray, t_max, BoundaryKind::Open)});
    } else if (slope < 0.0 && crossing <= t_max) {
        out.push_back({boundary(ray, crossing, BoundaryKind::Surface), boundary(ray, t_max, BoundaryKind::Open)});
    }
}

Vec3d HalfSpace::local_normal(const SurfaceRef&, TraceScratch&) const { return normalize(n_); }

}  // namespace zeroset
