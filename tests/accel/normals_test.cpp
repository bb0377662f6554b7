// The normal study (survey §8): the angular error of each way of computing
// normals — the exact gradient (eq. 33), forward differences (eq. 34) and
// central differences — on curved surfaces, for a range of steps ε, at
// points where rays meet the surface. References are closed-form normals
// (sphere, torus); on Blinn's blobs, whose normal has no closed form, the
// exact gradient is the reference. The table is printed (it is the one in
// docs/rendering.md#normals) and the defaults are checked to sit where the
// error is least.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <random>

#include "zeroset/accel/implicit_leaf.hpp"
#include "zeroset/accel/trace_scratch.hpp"

namespace zeroset {
namespace {

const Expr x = var_x(), y = var_y(), z = var_z();

struct Surface {
    const char* name;
    Expr f;
    Box3 box;
    Vec3d (*exact_normal)(const Vec3d& p);  // null: the exact gradient is the reference
};

std::vector<Surface> surfaces() {
    const auto ball = [](double cx) { return square(x - cx) + square(y) + square(z) - 1.0; };
    return {
        {"sphere (polynomial)", square(x) + square(y) + square(z) - 1.0, {{-1.1, -1.1, -1.1}, {1.1, 1.1, 1.1}},
         [](const Vec3d& p) { return normalize(p); }},
        {"torus (distance)", sqrt(square(sqrt(square(x) + square(y)) - 1.0) + square(z)) - 0.4,
         {{-1.5, -1.5, -0.5}, {1.5, 1.5, 0.5}},
         [](const Vec3d& p) {
             const double rho = std::hypot(p.x, p.y);
             return normalize(Vec3d{p.x - p.x / rho, p.y - p.y / rho, p.z});
         }},
        {"Blinn blobs (eq. 12)", 1.0 - exp(-ball(1.2)) - exp(-ball(-1.2)), {{-2.4, -1.2, -1.2}, {2.4, 1.2, 1.2}},
         nullptr},
    };
}

double angle(const Vec3d& a, const Vec3d& b) { return std::atan2(length(cross(a, b)), dot(a, b)); }

/// Surface points: first hits of random rays aimed at the bounds' centre region.
std::vector<SurfaceRef> surface_points(const ImplicitLeaf& leaf, TraceScratch& scratch, int count) {
    std::mt19937 random(21);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<SurfaceRef> points;
    const Box3 box = leaf.bounds();
    while (static_cast<int>(points.size()) < count) {
        const Vec3d d = normalize(Vec3d{u(random), u(random), u(random)});
        const Vec3d target = box.center() + hadamard(box.size() * 0.3, Vec3d{u(random), u(random), u(random)});
        const auto hit = leaf.first_hit({target - d * 5.0, d}, 0.0, INFINITY, scratch);
        if (hit && hit->surface.kind == BoundaryKind::Surface) points.push_back(hit->surface);
    }
    return points;
}

constexpr std::array relative_steps{1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10};

/// The median angular error of a mode with a relative step (0: its default) over the points.
double median_error(const Surface& s, NormalMode mode, double step, const std::vector<SurfaceRef>& points) {
    LeafDescription d;
    d.surface = s.f;
    d.bounds = Bounds::make_box(s.box);
    d.normals = mode;
    d.normal_step = step;
    const ImplicitLeaf leaf(0, d);
    LeafDescription exact = d;
    exact.normals = NormalMode::Analytic;
    const ImplicitLeaf reference(1, exact);
    TraceScratch scratch(2);
    std::vector<double> errors;
    for (SurfaceRef p : points) {
        p.leaf = &leaf;
        const Vec3d expected = s.exact_normal ? s.exact_normal(p.local_point) : reference.local_normal(p, scratch);
        errors.push_back(angle(leaf.local_normal(p, scratch), expected));
    }
    std::nth_element(errors.begin(), errors.begin() + static_cast<std::ptrdiff_t>(errors.size() / 2), errors.end());
    return errors[errors.size() / 2];
}

TEST(Normals, AngularErrorOfEachModeForSeveralSteps) {
    std::printf("median angular error (radians) over 400 surface points; step = ε × bounds diagonal\n");
    std::printf("%-22s %-8s", "surface", "mode");
    for (const double e : relative_steps) std::printf(" %8.0e", e);
    std::printf("  default\n");
    for (const Surface& s : surfaces()) {
        LeafDescription d;
        d.surface = s.f;
        d.bounds = Bounds::make_box(s.box);
        const ImplicitLeaf leaf(0, d);
        TraceScratch scratch(1);
        const std::vector<SurfaceRef> points = surface_points(leaf, scratch, 400);
        if (s.exact_normal) {
            const double analytic = median_error(s, NormalMode::Analytic, 0.0, points);
            std::printf("%-22s %-8s %8.1e (any step)\n", s.name, "analytic", analytic);
            EXPECT_LT(analytic, 1e-13) << s.name;  // exact up to rounding
        }
        for (const NormalMode mode : {NormalMode::ForwardDifference, NormalMode::CentralDifference}) {
            std::printf("%-22s %-8s", s.name, std::string(normal_mode_name(mode)).c_str());
            std::map<double, double> by_step;
            for (const double e : relative_steps) {
                by_step[e] = median_error(s, mode, e, points);
                std::printf(" %8.1e", by_step[e]);
            }
            const double chosen = median_error(s, mode, 0.0, points);
            std::printf("  %8.1e\n", chosen);
            double best = INFINITY;
            for (const auto& [e, error] : by_step) best = std::min(best, error);
            EXPECT_LE(chosen, std::max(10.0 * best, 1e-9)) << s.name << ": the default step is far from the best one";
            // Truncation error: forward differences lose accuracy in proportion to ε, central ones to ε².
            const double coarse = by_step[1e-2], finer = by_step[1e-3];
            if (mode == NormalMode::ForwardDifference) {
                EXPECT_NEAR(coarse / finer, 10.0, 3.0) << s.name;
            } else if (coarse > 1e-12) {  // (central differences are exact on a quadric, up to rounding)
                EXPECT_NEAR(coarse / finer, 100.0, 30.0) << s.name;
            }
        }
    }
}

}  // namespace
}  // namespace zeroset

namespace zeroset {
namespace {

TEST(Normals, AnalyticNormalsSurviveAVanishingGradient) {
    // On the cap of a capped cylinder's distance, exactly at its height, the
    // max(·, 0) in the formula ties; the normal must still point up.
    LeafDescription d;
    d.surface = max(sqrt(square(x) + square(y)) - 0.5, abs(z) - 0.4);
    d.bounds = Bounds::make_box({{-1, -1, -1}, {1, 1, 1}});
    const ImplicitLeaf leaf(0, d);
    TraceScratch scratch(1);
    SurfaceRef s;
    s.leaf = &leaf;
    s.kind = BoundaryKind::Surface;
    s.local_point = {0.1, 0.2, 0.4};
    const Vec3d n = leaf.local_normal(s, scratch);
    EXPECT_NEAR(n.z, 1.0, 1e-6);
}

}  // namespace
}  // namespace zeroset
