// Sphere tracing a fractal by its distance estimate, spans by sampling inside.
#include "zeroset/accel/fractal.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "zeroset/accel/trace_scratch.hpp"

namespace zeroset {

namespace {

/// The part of the ray in the ball of `radius` about the origin.
std::optional<Span> in_ball(const Ray& ray, double radius) {
    const double a = dot(ray.dir, ray.dir), b = dot(ray.origin, ray.dir);
    const double c = dot(ray.origin, ray.origin) - radius * radius;
    const double discriminant = b * b - a * c;
    if (!(discriminant >= 0.0) || !(a > 0.0)) return std::nullopt;
    const double root = std::sqrt(discriminant);
    return Span{(-b - root) / a, (-b + root) / a};
}

}  // namespace

struct Fractal::Walk {
    const Fractal& fractal;
    const Ray& ray;
    TraceCounters& counters;
    double speed;        // |d|: length in space per unit of t
    double inside_step;  // t per inside sample: 1/inside_samples of the chord
    int steps = 0;
    bool gave_up = false;

    /// The estimate at t, and whether it is below the tolerance there.
    struct Sample {
        double distance;
        bool near;
    };
    Sample at(double t) {
        ++steps;
        ++counters.point_evaluations;
        const double d = fractal.estimate().distance(ray.at(t));
        return {d, d < fractal.tolerance_at(std::abs(t) * speed)};
    }
    /// Whether the step budget is spent (and so the query gives up).
    bool spent() {
        if (steps >= max_steps) gave_up = true;
        return gave_up;
    }
    /// The tolerance at t, in t.
    [[nodiscard]] double tolerance_t(double t) const { return fractal.tolerance_at(std::abs(t) * speed) / speed; }
};

Fractal::Fractal(FractalDescription description) : description_(std::move(description)) {
    if (!description_.estimate) throw std::invalid_argument("a fractal needs its estimate");
    if (!(description_.detail > 0.0) || !std::isfinite(description_.detail))
        throw std::invalid_argument("a fractal's detail must be positive");
    if (!(description_.footprint >= 0.0) || !std::isfinite(description_.footprint))
        throw std::invalid_argument("the pixel footprint must be finite and not negative");
    radius_ = estimate().bounding_radius();
    bounds_ = {{-radius_, -radius_, -radius_}, {radius_, radius_, radius_}};
}

double Fractal::tolerance_at(double distance) const {
    const double pixel = description_.footprint > 0.0 ? description_.footprint * distance : 1e-4 * radius_;
    return std::max(description_.detail * pixel, 1e-6 * radius_);
}

std::optional<double> Fractal::march(Walk& walk, double t, double t_end) const {
    while (t <= t_end && !walk.spent()) {
        const Walk::Sample s = walk.at(t);
        if (s.near) return t;
        t += s.distance / walk.speed;  // ≥ the tolerance: every step moves on
    }
    return std::nullopt;
}

std::optional<double> Fractal::exit_after(Walk& walk, double t, double t_end) const {
    while (!walk.spent()) {
        const double tolerance = walk.tolerance_t(t);
        const double next = t + std::max(tolerance, walk.inside_step);
        if (next >= t_end) return std::nullopt;
        if (!walk.at(next).near) {  // out between t and next: bisect down to the tolerance
            double in = t, out = next;
            while (out - in > tolerance && !walk.spent()) {
                const double mid = 0.5 * (in + out);
                (walk.at(mid).near ? in : out) = mid;
            }
            return out;
        }
        t = next;
    }
    return std::nullopt;
}

Hit Fractal::boundary(const Ray& ray, double t, BoundaryKind kind) const {
    return {t, leaf_surface(*this, kind, description_.material, ray.at(t), 2.0 * radius_)};
}

std::optional<Hit> Fractal::first_hit(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const {
    const std::optional<Span> ball = in_ball(ray, radius_);
    if (!ball) return std::nullopt;
    const double from = std::max(t_min, ball->t0), to = std::min(t_max, ball->t1);
    if (!(from <= to)) return std::nullopt;
    const double speed = length(ray.dir);
    Walk walk{*this, ray, scratch.counters, speed, (ball->t1 - ball->t0) / inside_samples};
    const std::optional<double> t = march(walk, from, to);
    if (walk.gave_up) {
        ++scratch.counters.failed_queries;
        return std::nullopt;
    }
    if (!t) return std::nullopt;
    const bool starts_inside = *t == t_min && estimate().distance(ray.at(t_min)) == 0.0;
    return boundary(ray, *t, starts_inside ? BoundaryKind::Open : BoundaryKind::Surface);
}

void Fractal::spans(const Ray& ray, double t_min, double t_max, TraceScratch& scratch, SpanList& out) const {
    const std::optional<Span> ball = in_ball(ray, radius_);
    if (!ball) return;
    const double from = std::max(t_min, ball->t0), to = std::min(t_max, ball->t1);
    if (!(from <= to)) return;
    Walk walk{*this, ray, scratch.counters, length(ray.dir), (ball->t1 - ball->t0) / inside_samples};
    double t = from;
    while (const std::optional<double> enter = march(walk, t, to)) {
        const bool starts_inside = *enter == t_min && estimate().distance(ray.at(t_min)) == 0.0;
        const Hit in = boundary(ray, *enter, starts_inside ? BoundaryKind::Open : BoundaryKind::Surface);
        const std::optional<double> exit = exit_after(walk, *enter, to);
        if (!exit) {  // in the solid up to the end (or the budget ran out there)
            out.push_back({in, to == t_max ? boundary(ray, t_max, BoundaryKind::Open) : boundary(ray, to, BoundaryKind::Surface)});
            break;
        }
        out.push_back({in, boundary(ray, *exit, BoundaryKind::Surface)});
        t = *exit;
    }
    if (walk.gave_up) ++scratch.counters.failed_queries;
}

Vec3d Fractal::local_normal(const SurfaceRef& surface, TraceScratch& scratch) const {
    // Eq. 34: the gradient by central differences, over half the estimate at
    // the point (the pixel's scale where a ray stopped).
    const Vec3d p = surface.local_point;
    const double h = std::max(0.5 * estimate().distance(p), 1e-6 * radius_);
    const auto difference = [&](const Vec3d& step) { return estimate().distance(p + step) - estimate().distance(p - step); };
    const Vec3d g{difference({h, 0.0, 0.0}), difference({0.0, h, 0.0}), difference({0.0, 0.0, h})};
    scratch.counters.point_evaluations += 7;
    const double size = length(g);
    return size > 0.0 && std::isfinite(size) ? g / size : Vec3d{};
}

}  // namespace zeroset
