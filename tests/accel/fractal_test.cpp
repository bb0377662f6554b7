// The fractal primitive (accel/fractal.hpp) against independent answers:
// the Julia set of z² (c = 0) is the unit ball exactly, so hits and spans
// must match the sphere's closed form to the hit tolerance; for a c with a
// real fractal boundary, few rays may pass a point the iterations put in
// the set, and those by no more than a few hit tolerances; and the
// estimate is a lower bound on the distance to the ball.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include "zeroset/accel/fractal.hpp"
#include "zeroset/accel/trace_scratch.hpp"

namespace zeroset {
namespace {

Fractal julia(Quaternion c, int iterations = 30, double footprint = 1e-3) {
    FractalParameters p;
    p.c = c;
    p.iterations = iterations;
    FractalDescription d;
    d.name = "julia";
    d.estimate = std::make_shared<const FractalEstimate>(p);
    d.footprint = footprint;
    return Fractal(d);
}

/// A ray from a random point on a sphere of radius 4 towards a random point
/// within `aim` of the origin.
Ray random_ray(std::mt19937& rng, double aim) {
    std::normal_distribution<double> n;
    std::uniform_real_distribution<double> u(-aim, aim);
    const Vec3d from = normalize(Vec3d{n(rng), n(rng), n(rng)}) * 4.0;
    const Vec3d to{u(rng), u(rng), u(rng)};
    return {from, normalize(to - from)};
}

TEST(FractalEstimate, BoundsTheDistanceToTheUnitBallOfZSquared) {
    const FractalEstimate e(FractalParameters{FractalKind::QuaternionJulia, {}, 0.0, 8.0, 30});
    EXPECT_NEAR(e.bounding_radius(), 1.0, 1e-12);
    for (const double r : {1.001, 1.01, 1.1, 1.5, 3.0}) {
        const double d = e.distance({r / std::sqrt(3.0), r / std::sqrt(3.0), r / std::sqrt(3.0)});
        EXPECT_LE(d, r - 1.0) << r;       // a lower bound …
        EXPECT_GE(d, 0.2 * (r - 1.0)) << r;  // … and not a useless one
    }
    EXPECT_EQ(e.distance({0.3, -0.2, 0.5}), 0.0);  // inside
}

TEST(Fractal, HitsAndSpansOfTheBallMatchTheSphere) {
    const Fractal ball = julia({});
    TraceScratch scratch(0);
    std::mt19937 rng(7);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Ray ray = random_ray(rng, 1.2);
        const double b = dot(ray.origin, ray.dir), disc = b * b - (dot(ray.origin, ray.origin) - 1.0);
        const std::optional<Hit> hit = ball.first_hit(ray, 0.0, 100.0, scratch);
        if (disc <= 0.0) {
            // A miss, or a hit within the tolerance of the sphere (a near graze).
            if (hit) {
                EXPECT_LT(length(ray.at(hit->t)) - 1.0, ball.tolerance_at(hit->t) * 1.01) << i;
            }
            continue;
        }
        ++hits;
        const double enter = -b - std::sqrt(disc), exit = -b + std::sqrt(disc);
        ASSERT_TRUE(hit) << i;
        const double tolerance = ball.tolerance_at(enter);
        EXPECT_LE(hit->t, enter + 1e-12) << i;  // never inside
        // Stopped where the estimate (≥ a fifth of the distance here) fell below ε.
        if (exit - enter > 10 * tolerance) {
            EXPECT_LT(enter - hit->t, 5.0 * tolerance / std::abs(dot(normalize(ray.at(enter)), ray.dir))) << i;
        }
        SpanList spans;
        ball.spans(ray, 0.0, 100.0, scratch, spans);
        ASSERT_EQ(spans.size(), 1U) << i;
        EXPECT_EQ(spans[0].enter.t, hit->t);
        EXPECT_NEAR(spans[0].exit.t, exit, 5.0 * tolerance / std::abs(dot(normalize(ray.at(exit)), ray.dir))) << i;
        const Vec3d n = ball.local_normal(hit->surface, scratch);
        EXPECT_GT(dot(n, normalize(ray.at(hit->t))), 0.99) << i;
    }
    EXPECT_GT(hits, 1000);
    EXPECT_EQ(scratch.counters.failed_queries, 0U);
}

TEST(Fractal, RarelyStepsPastAJuliaSet) {
    const Fractal set = julia({-0.8, 0.16, 0.0, 0.0}, 20);
    TraceScratch scratch(0);
    std::mt19937 rng(11);
    int hits = 0, stepped_in = 0;
    double worst = 0.0;
    for (int i = 0; i < 300; ++i) {
        const Ray ray = random_ray(rng, 0.8);
        const std::optional<Hit> hit = set.first_hit(ray, 0.0, 100.0, scratch);
        if (!hit) continue;
        ++hits;
        // Dense samples before the hit: the deepest in the set (the estimate
        // 0 there), in tolerances before the hit. The estimate is not a proof
        // after finitely many iterations: it may step a little past a point
        // the iterations call inside.
        for (double t = hit->t * 0.5; t < hit->t; t += 2e-4)
            if (set.estimate().distance(ray.at(t)) == 0.0) {
                const double depth = (hit->t - t) / set.tolerance_at(hit->t);
                worst = std::max(worst, depth);
                if (depth > 1.0) ++stepped_in;
                break;
            }
        EXPECT_LT(set.estimate().distance(ray.at(hit->t)), set.tolerance_at(hit->t));
    }
    EXPECT_GT(hits, 50);
    std::cout << "julia (-0.8, 0.16): " << stepped_in << " of " << hits
              << " hits passed a point in the set more than one tolerance before; the deepest by " << worst
              << " tolerances\n";
    EXPECT_LE(stepped_in, hits / 20);
    EXPECT_LT(worst, 4.0);
}

TEST(Fractal, RefusesBadSettings) {
    FractalParameters p;
    p.iterations = 0;
    EXPECT_THROW(FractalEstimate{p}, std::invalid_argument);
    p.iterations = 10;
    p.slice = 5.0;  // past the ball the Julia set lies in
    EXPECT_THROW(FractalEstimate{p}, std::invalid_argument);
    p.slice = 0.0;
    p.kind = FractalKind::Mandelbulb;
    p.power = 40.0;
    EXPECT_THROW(FractalEstimate{p}, std::invalid_argument);
    p.power = 8.0;
    FractalDescription d;
    d.estimate = std::make_shared<const FractalEstimate>(p);
    d.detail = 0.0;
    EXPECT_THROW(Fractal{d}, std::invalid_argument);
}

}  // namespace
}  // namespace zeroset
