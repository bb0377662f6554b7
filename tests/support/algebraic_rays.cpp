// Ray construction for the algebraic accuracy study.
#include "support/algebraic_rays.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "support/surface_nodes.hpp"
#include "zeroset/expr/evaluator.hpp"

namespace zeroset::test {

namespace {

Vec3d random_unit(std::mt19937_64& rng) {
    std::normal_distribution<double> g(0.0, 1.0);
    for (;;) {
        const Vec3d v{g(rng), g(rng), g(rng)};
        if (length(v) > 1e-6) return normalize(v);
    }
}

/// A point of the surface near the ray's first sign change, by sampling and
/// bisection in double; nothing if the ray shows no sign change.
std::optional<Vec3d> surface_point(Evaluator<double>& f, const Ray& ray, Span span) {
    constexpr int samples = 256;
    const auto h = [&](double t) {
        const Vec3d p = ray.at(t);
        return f(p.x, p.y, p.z);
    };
    double a = span.t0, fa = h(a);
    for (int i = 1; i <= samples; ++i) {
        const double b = span.t0 + (span.t1 - span.t0) * i / samples, fb = h(b);
        if ((fa <= 0.0) != (fb <= 0.0)) {
            double lo = a, hi = b;
            for (int k = 0; k < 80; ++k) {
                const double mid = 0.5 * (lo + hi);
                if ((h(mid) <= 0.0) == (fa <= 0.0)) lo = mid;
                else hi = mid;
            }
            return ray.at(0.5 * (lo + hi));
        }
        a = b;
        fa = fb;
    }
    return std::nullopt;
}

/// A ray in the direction u through `node` rounded to the multiples of a
/// power of two q (about 1e-16 × scale), reached at the parameter s ≥ scale,
/// a power of two: origin, point and s·dir are multiples of q below 2^53·q,
/// so all are doubles and origin + s·dir is the rounded node exactly. Only a
/// node that is itself on the grid (the cone's apex) is hit exactly; the ray
/// passes any other about an ulp off and, in some directions, misses the
/// surface there — as it may where the surface's coefficients are rounded
/// (φ, √2) and a node has become a neck or a gap about 1e-8 × scale wide.
/// The oracle's reference says which.
Ray node_ray(const Vec3d& node, const Vec3d& u, double scale) {
    const double s = std::ldexp(1.0, std::ilogb(scale) + 1);
    const double reach = std::max({std::abs(node.x), std::abs(node.y), std::abs(node.z)}) + s;
    const double q = std::ldexp(1.0, std::ilogb(reach) + 2 - 53);
    const auto on_grid = [q](double v) { return std::nearbyint(v / q) * q; };
    Ray ray;
    for (int axis = 0; axis < 3; ++axis) {
        const double p = on_grid(node[axis]);
        ray.origin[axis] = on_grid(p - s * u[axis]);
        ray.dir[axis] = (p - ray.origin[axis]) / s;
    }
    return ray;
}

}  // namespace

std::vector<AlgebraicRay> algebraic_rays(const Object& object, int count, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const Box3 box = object.bounds.enclosing_box();
    const double scale = box.diagonal();
    const Vec3d centre = box.center();
    const Tape tape(object.surface);
    Evaluator<double> f(tape);
    Evaluator<Dual<double>> gradient(tape);
    MpfiRayOracle oracle(object.surface, scale);
    const std::vector<Vec3d> nodes = surface_nodes(object.surface, object.bounds);
    std::vector<AlgebraicRayKind> cycle = {AlgebraicRayKind::Random, AlgebraicRayKind::Grazing};
    if (!nodes.empty()) cycle.push_back(AlgebraicRayKind::Node);
    std::uniform_int_distribution<std::size_t> pick_node(0, nodes.empty() ? 0 : nodes.size() - 1);

    const auto random_inside = [&] {
        return Vec3d{box.lo.x + unit(rng) * (box.hi.x - box.lo.x), box.lo.y + unit(rng) * (box.hi.y - box.lo.y),
                     box.lo.z + unit(rng) * (box.hi.z - box.lo.z)};
    };
    std::vector<AlgebraicRay> rays;
    // A ray the oracle cannot decide within its evaluation budget (a graze of
    // a degenerate point, say) is left out and the next one drawn instead.
    const auto add = [&](const Ray& ray, Span span, AlgebraicRayKind kind) {
        try {
            rays.push_back({ray, span, oracle.first_root(ray, span), kind});
        } catch (const std::runtime_error&) {
        }
    };
    while (static_cast<int>(rays.size()) < count) {
        const AlgebraicRayKind kind = cycle[rays.size() % cycle.size()];
        if (kind == AlgebraicRayKind::Node) {
            const Vec3d& node = nodes[pick_node(rng)];  // before the direction: one draw order
            const Ray ray = node_ray(node, random_unit(rng), scale);
            const auto span = object.bounds.clip(ray, 0.0, 4.0 * scale);
            if (!span) continue;
            add(ray, *span, kind);
            continue;
        }
        // A random ray from outside through a random point of the bounds.
        const Vec3d origin = centre + random_unit(rng) * scale;
        Ray ray{origin, normalize(random_inside() - origin)};
        auto span = object.bounds.clip(ray, 0.0, 4.0 * scale);
        if (!span) continue;
        // A grazing ray is the random one rebuilt to graze the surface where
        // it met it: tangent to it there, or passing it at an offset of 1e-12
        // to 1e-3 × scale on either side.
        if (kind == AlgebraicRayKind::Grazing) {
            const auto p = surface_point(f, ray, *span);
            if (!p) continue;
            const Vec3d g = evaluate_gradient(gradient, *p).g;
            if (!(length(g) > 0.0)) continue;
            const Vec3d n = normalize(g);
            const Vec3d tangent = normalize(cross(n, random_unit(rng)));
            const double offset = (unit(rng) < 0.25 ? 0.0 : (unit(rng) < 0.5 ? -1.0 : 1.0)) *
                                  std::pow(10.0, -12.0 + 9.0 * unit(rng)) * scale;
            const Vec3d touch = *p + n * offset;
            ray = {touch - tangent * scale, tangent};
            span = object.bounds.clip(ray, 0.0, 4.0 * scale);
            if (!span) continue;
        }
        add(ray, *span, kind);
    }
    return rays;
}

}  // namespace zeroset::test
