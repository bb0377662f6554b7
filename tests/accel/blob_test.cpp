// The blob primitive (accel/blob.hpp) against the same field written as an
// expression and traced by the general interval method: on ten thousand
// rays per kernel — grazing rays among them — the first hits must agree,
// and neither may miss what the other proves is there. Also the kernels'
// formulas and enclosures, spans, normals, and the cost per ray (cylinders:
// blob_cylinder_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <memory>
#include <random>

#include "support/camera_tiles.hpp"
#include "zeroset/accel/blob.hpp"
#include "zeroset/accel/implicit_leaf.hpp"
#include "zeroset/accel/trace_scratch.hpp"
#include "zeroset/expr/evaluator.hpp"

namespace zeroset {
namespace {

TEST(BlobKernels, MatchTheSurveysFormulas) {
    // POV-Ray: (1 − u)²; soft objects: eq. 23 with R = 2, u = r²/4.
    EXPECT_DOUBLE_EQ(kernel_at(BlobKernel::PovRay, 0.25, 0).value, 0.5625);
    for (const double r2 : {0.0, 0.5, 1.7, 3.2, 3.99}) {
        const double c = -r2 * r2 * r2 / 144.0 + 17.0 * r2 * r2 / 144.0 - 11.0 * r2 / 18.0 + 1.0;
        EXPECT_NEAR(kernel_at(BlobKernel::Soft, r2 / 4.0, 0).value, c, 1e-15) << r2;
    }
    EXPECT_EQ(kernel_at(BlobKernel::Soft, 1.0, 0).value, 0.0);
    // Metaballs: 1 − 3ρ², then (3/2)(1 − ρ)², meeting at ρ = 1/3 with value and slope.
    EXPECT_DOUBLE_EQ(kernel_at(BlobKernel::Metaball, 0.0, 0).value, 1.0);
    const double below = 1.0 / 9.0 - 1e-9, above = 1.0 / 9.0 + 1e-9;
    EXPECT_NEAR(kernel_at(BlobKernel::Metaball, below, 0).value, kernel_at(BlobKernel::Metaball, above, 0).value, 1e-8);
    EXPECT_NEAR(kernel_at(BlobKernel::Metaball, below, 0).slope, kernel_at(BlobKernel::Metaball, above, 0).slope, 1e-6);
    EXPECT_DOUBLE_EQ(kernel_at(BlobKernel::Metaball, 0.25, 0).value, 1.5 * 0.25);
    // Blinn: e^(B(u − 1)), 1 at u = 1.
    EXPECT_DOUBLE_EQ(kernel_at(BlobKernel::Blinn, 1.0, -3.0).value, 1.0);
    EXPECT_NEAR(kernel_at(BlobKernel::Blinn, 0.0, -1.0).value, std::exp(1.0), 1e-15);
}

TEST(BlobKernels, SlopesAndEnclosuresAreRight) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.3);
    for (const BlobKernelInfo& info : blob_kernels()) {
        for (int i = 0; i < 2000; ++i) {
            double a = unit(random), b = unit(random);
            if (a > b) std::swap(a, b);
            const Interval value = kernel_over(info.kernel, Interval(a, b), -2.0);
            const Interval slope = kernel_slope_over(info.kernel, Interval(a, b), -2.0);
            for (const double u : {a, b, 0.5 * (a + b), a + 0.3 * (b - a)}) {
                const KernelValue k = kernel_at(info.kernel, u, -2.0);
                EXPECT_TRUE(value.contains(k.value)) << info.name << " at " << u;
                EXPECT_TRUE(slope.contains(k.slope)) << info.name << " at " << u;
            }
            const double u = 0.5 * (a + b), h = 1e-6;
            if (std::abs(u - 1.0 / 9.0) > 2 * h && std::abs(u - 1.0) > 2 * h) {
                const double difference =
                    (kernel_at(info.kernel, u + h, -2.0).value - kernel_at(info.kernel, u - h, -2.0).value) / (2 * h);
                EXPECT_NEAR(kernel_at(info.kernel, u, -2.0).slope, difference, 1e-6) << info.name << " at " << u;
            }
        }
    }
}

/// K(u) in long double (64-bit mantissa), with the same double coefficients.
long double exact_kernel(BlobKernel kernel, double u, double blobbiness) {
    const long double w = u;
    switch (kernel) {
        case BlobKernel::Blinn: return std::exp(static_cast<long double>(blobbiness) * (w - 1.0L));
        case BlobKernel::PovRay: return u >= 1.0 ? 0.0L : (1.0L - w) * (1.0L - w);
        case BlobKernel::Metaball: {
            if (u >= 1.0) return 0.0L;
            if (u <= 1.0 / 9.0) return 1.0L - 3.0L * w;
            const long double m = 1.0L - std::sqrt(w);
            return 1.5L * m * m;
        }
        case BlobKernel::Soft: {
            if (u >= 1.0) return 0.0L;
            const std::span<const double> c = blob_kernel_info(kernel).polynomial;
            long double sum = c.back();
            for (std::size_t i = c.size() - 1; i-- > 0;) sum = sum * w + c[i];
            return sum;
        }
    }
    return 0.0L;
}

TEST(BlobKernels, ValueAboveBoundsTheExactKernel) {
    // The segments' skip test sums these bounds: one below K would let a
    // segment that reaches T by a graze be skipped.
    std::mt19937_64 random(20261207);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const BlobKernelInfo& info : blob_kernels()) {
        int value_alone_below = 0;
        for (int i = 0; i < 200000; ++i) {
            // Mostly near u = 1, where K is small and the rounding of the
            // terms that cancel there is not.
            const double u = i % 3 == 0 ? 1.3 * unit(random) : 1.0 - std::ldexp(unit(random), -(i % 40));
            const double b = -std::ldexp(0.5 + unit(random), i % 6);  // Blinn's B, −0.5 to −64
            const long double exact = exact_kernel(info.kernel, u, b);
            const double above = kernel_value_above(info.kernel, u, b);
            ASSERT_GE(static_cast<long double>(above), exact) << info.name << " at u = " << u << ", B = " << b;
            const long double room = info.kernel == BlobKernel::Blinn ? 1e-13L * exact : 1e-13L;
            ASSERT_LE(static_cast<long double>(above), exact + room) << info.name << " at u = " << u;
            if (static_cast<long double>(kernel_value_at(info.kernel, u, b)) < exact) ++value_alone_below;
        }
        // The computed value alone is no bound: it is below K as often as above.
        EXPECT_GT(value_alone_below, 1000) << info.name;
    }
}

/// Twelve components in [−1, 1]³: two of them negative, one an ellipsoid,
/// two cylinders (one along z) unless only round ones are wanted (the
/// metaballs' quadratic pieces).
std::shared_ptr<const BlobModel> random_blob(BlobKernel kernel, std::uint32_t seed, bool cylinders = true) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0), radius(0.5, 0.9);
    std::vector<BlobComponent> components;
    for (int i = 0; i < 12; ++i) {
        BlobComponent c;
        c.center = {u(random), u(random), u(random)};
        c.radius = radius(random);
        c.strength = i < 2 ? -0.5 : 1.0;
        c.blobbiness = -2.0;
        if (i == 5) c.shape = Mat4::rotate_xyz_degrees({30, 40, 0}) * Mat4::scale({1.0, 0.4, 1.6});
        if (cylinders && i == 6) c.end = c.center + Vec3d{0.8, -0.3, 0.5};
        if (cylinders && i == 7) c.end = c.center + Vec3d{0.0, 0.0, 0.9};
        if (c.end) c.radius *= 0.6;
        components.push_back(c);
    }
    return std::make_shared<const BlobModel>(kernel, 0.5, std::move(components));
}

struct Comparison {
    int rays = 0, hits = 0, misses = 0, false_hits = 0, grazes = 0;
    double max_dt = 0.0;          // over the rays aimed at random
    double max_grazing_dt = 0.0;  // over the grazing rays, where a root is ill-conditioned
};

class BlobAgainstExpression : public ::testing::TestWithParam<BlobKernel> {};

TEST_P(BlobAgainstExpression, FirstHitsAgreeOnTenThousandRays) {
    const BlobKernel kernel = GetParam();
    const auto model = random_blob(kernel, 11);
    const Blob blob(BlobDescription{"blob", model, no_material, 1e-9, 1});
    LeafDescription d;
    d.name = "expression";
    d.surface = model->field_expression();
    d.bounds = Bounds::make_box(blob.bounds());
    d.method = Method::Interval;
    d.partition = Partition::None;
    const ImplicitLeaf reference(0, d);
    Evaluator<double> f(reference.tape());
    const auto f_at = [&](const Vec3d& p) { return f(p.x, p.y, p.z); };
    TraceScratch scratch(1);

    // Does the ray dip below −depth somewhere near t (sampled)? Then a hit there is real.
    const auto enters = [&](const Ray& ray, double t, double depth) {
        for (int k = 0; k <= 400; ++k)
            if (f_at(ray.at(t + (k - 50) * 1e-4)) < -depth) return true;
        return false;
    };

    std::mt19937 random(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Comparison c;
    std::vector<Ray> rays;
    std::vector<bool> grazing;
    while (rays.size() < 10000) {
        const Vec3d target{1.3 * u(random), 1.3 * u(random), 1.3 * u(random)};
        const Vec3d dir = normalize(Vec3d{u(random), u(random), u(random)});
        const Ray ray{target - 6.0 * dir, dir};
        rays.push_back(ray);
        grazing.push_back(false);
        // Every fourth: a ray grazing the surface where this one hits it.
        if (rays.size() % 4 != 0) continue;
        const auto hit = reference.first_hit(ray, 0.0, 1e9, scratch);
        if (!hit) continue;
        const Vec3d p = ray.at(hit->t), n = normalize(blob.gradient_at(p));
        Vec3d tangent = cross(n, Vec3d{u(random), u(random), u(random)});
        if (!(length(tangent) > 1e-3)) continue;
        tangent = normalize(tangent);
        const double offset = std::array{0.0, 1e-3, -1e-3, 1e-7, -1e-7}[rays.size() / 4 % 5];
        rays.push_back({p + offset * n - 6.0 * tangent, tangent});
        grazing.push_back(true);
    }
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const Ray& ray = rays[i];
        ++c.rays;
        const auto mine = blob.first_hit(ray, 0.0, 1e9, scratch);
        const auto theirs = reference.first_hit(ray, 0.0, 1e9, scratch);
        if (mine && theirs) {
            ++c.hits;
            const double dt = std::abs(mine->t - theirs->t);
            if (dt > 1e-6) {
                // Different roots: the earlier one must be a graze the other passed.
                const Hit& early = mine->t < theirs->t ? *mine : *theirs;
                EXPECT_LT(std::abs(f_at(ray.at(early.t))), 1e-6) << "t " << mine->t << " vs " << theirs->t;
                ++c.grazes;
            } else {
                double& largest = grazing[i] ? c.max_grazing_dt : c.max_dt;
                largest = std::max(largest, dt);
                // Both are roots: f at each is 0 to within its rounding —
                // and for Gaussians the components cut off, each below
                // tolerance·T, 12 of them at most.
                EXPECT_LT(std::abs(f_at(ray.at(mine->t))), kernel == BlobKernel::Blinn ? 12 * 1e-9 * 0.5 : 1e-10);
            }
        } else if (theirs) {
            if (enters(ray, theirs->t, 1e-7)) ++c.misses;
            else ++c.grazes;
        } else if (mine) {
            if (std::abs(f_at(ray.at(mine->t))) > 1e-6) ++c.false_hits;
            else ++c.grazes;
        }
    }
    std::cout << blob_kernel_info(kernel).name << ": " << c.rays << " rays, " << c.hits << " hit by both, max |dt| "
              << c.max_dt << " (grazing rays " << c.max_grazing_dt << "), " << c.grazes << " grazes told apart, " << c.misses << " misses, " << c.false_hits
              << " false hits\n";
    EXPECT_EQ(c.misses, 0);
    EXPECT_EQ(c.false_hits, 0);
    EXPECT_LT(c.max_dt, 1e-8);
    EXPECT_GT(c.hits, 3000);
}

TEST_P(BlobAgainstExpression, SpansAndNormalsAgree) {
    const BlobKernel kernel = GetParam();
    const auto model = random_blob(kernel, 23);
    const Blob blob(BlobDescription{"blob", model, no_material, 1e-9, 1});
    LeafDescription d;
    d.surface = model->field_expression();
    d.bounds = Bounds::make_box(blob.bounds());
    d.method = Method::Interval;
    d.partition = Partition::None;
    const ImplicitLeaf reference(0, d);
    Evaluator<Dual<double>> gradient(reference.tape());
    TraceScratch scratch(1);
    std::mt19937 random(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int compared = 0;
    for (int i = 0; i < 500; ++i) {
        const Vec3d dir = normalize(Vec3d{u(random), u(random), u(random)});
        const Ray ray{Vec3d{u(random), u(random), u(random)} - 6.0 * dir, dir};
        SpanList mine, theirs;
        blob.spans(ray, 0.0, 20.0, scratch, mine);
        reference.spans(ray, 0.0, 20.0, scratch, theirs);
        ASSERT_EQ(mine.size(), theirs.size()) << "ray " << i;
        for (std::size_t k = 0; k < mine.size(); ++k) {
            EXPECT_NEAR(mine[k].enter.t, theirs[k].enter.t, 1e-8);
            EXPECT_NEAR(mine[k].exit.t, theirs[k].exit.t, 1e-8);
            const Vec3d n = blob.local_normal(mine[k].enter.surface, scratch);
            const Vec3d expected = normalize(evaluate_gradient(gradient, mine[k].enter.surface.local_point).g);
            EXPECT_NEAR(length(n - expected), 0.0, 1e-8);
            ++compared;
        }
    }
    EXPECT_GT(compared, 200);
}

INSTANTIATE_TEST_SUITE_P(EveryKernel, BlobAgainstExpression,
                         ::testing::Values(BlobKernel::Blinn, BlobKernel::Metaball, BlobKernel::Soft, BlobKernel::PovRay),
                         [](const auto& p) { return std::string(blob_kernel_info(p.param).name); });

// A blob of four components or fewer meets them all without walking its
// BVH. The same components and one more far away (five: the tree is
// walked) give the same hits — to rounding: the far one widens the blob's
// scale, and with it the width at which a crossing's Newton stops — and the
// same shadows.
TEST(Blob, AFewComponentsAreMetWithoutTheTree) {
    for (const BlobKernel kernel : {BlobKernel::Blinn, BlobKernel::Metaball, BlobKernel::Soft, BlobKernel::PovRay}) {
        SCOPED_TRACE(blob_kernel_info(kernel).name);
        const auto model = random_blob(kernel, 11);
        const std::vector<BlobComponent>& all = model->components();
        // A negative one, two round ones, a cylinder: four, the most a leaf holds.
        std::vector<BlobComponent> few{all[0], all[2], all[3], all[6]};
        BlobComponent far = all[3];
        far.center = {100, 100, 100};
        std::vector<BlobComponent> more = few;
        more.push_back(far);
        const Blob direct(BlobDescription{"few", std::make_shared<const BlobModel>(kernel, 0.5, few), no_material, 1e-9, 1});
        const Blob walked(BlobDescription{"more", std::make_shared<const BlobModel>(kernel, 0.5, more), no_material, 1e-9, 1});
        TraceScratch scratch(1);
        std::mt19937 random(7);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        int hits = 0;
        for (int i = 0; i < 2000; ++i) {
            const Vec3d dir = normalize(Vec3d{u(random), u(random), u(random)});
            const Ray ray{Vec3d{u(random), u(random), u(random)} - 6.0 * dir, dir};
            const auto a = direct.first_hit(ray, 0.0, 20.0, scratch);
            const auto b = walked.first_hit(ray, 0.0, 20.0, scratch);
            ASSERT_EQ(a.has_value(), b.has_value()) << "ray " << i;
            if (a) {
                EXPECT_NEAR(a->t, b->t, 1e-12 * a->t) << "ray " << i;
                ++hits;
            }
            EXPECT_EQ(direct.occluded(ray, 0.0, 20.0, scratch), walked.occluded(ray, 0.0, 20.0, scratch)) << "ray " << i;
        }
        EXPECT_GT(hits, 300);
    }
}

// A camera ray that comes with its tile meets the components by the tile's
// list (nearest the eye first) instead of the BVH's walk. On a cloud of 400
// components of every kind (ellipsoids, cylinders, negative ones), the
// tiles' rays find the same first hits either way — to rounding: the
// components come in another order, so a segment's terms are summed in
// another — and the lists did serve them.
TEST(Blob, ACameraTilesRaysMeetTheComponentsByItsList) {
    for (const BlobKernel kernel : {BlobKernel::Blinn, BlobKernel::Soft, BlobKernel::PovRay}) {
        SCOPED_TRACE(blob_kernel_info(kernel).name);
        std::vector<BlobComponent> components;
        for (std::uint32_t seed = 0; seed < 34; ++seed) {
            const auto part = random_blob(kernel, 100 + seed);  // held while its components are read
            for (BlobComponent c : part->components()) {
                c.center = c.center * 0.8 + Vec3d{(seed % 6) * 1.6 - 4.0, (seed / 6) * 1.6 - 4.0, 0.0};
                if (c.end) *c.end = *c.end * 0.8 + Vec3d{(seed % 6) * 1.6 - 4.0, (seed / 6) * 1.6 - 4.0, 0.0};
                c.radius *= 0.8;
                components.push_back(c);
            }
        }
        const Blob blob(BlobDescription{"cloud", std::make_shared<const BlobModel>(kernel, 0.5, components), no_material, 1e-9, 1});
        // An 8 × 8-pixel tile looking at the cloud from z = −12, slightly tilted.
        TraceScratch scratch(1);
        int hits = 0;
        for (int tile = 0; tile < 6; ++tile) {
            const CameraFrustum f = test::square_tile({0.4, -0.3, -12.0}, {-0.03, 0.02, 1.0}, 8, 0.006, -0.3 + 0.1 * tile,
                                                     0.25 - 0.09 * tile);
            for (int py = 0; py < f.rows; ++py)
                for (int px = 0; px < f.columns; ++px) {
                    const Ray ray{f.origin,
                                  normalize(f.forward + f.right * (f.u0 + (px + 0.5) * f.du) + f.up * (f.v0 + (py + 0.5) * f.dv))};
                    const auto walked = blob.first_hit(ray, 0.0, 1e9, scratch);
                    scratch.camera_frustum = &f;
                    const auto listed = blob.first_hit(ray, 0.0, 1e9, scratch);
                    scratch.camera_frustum = nullptr;
                    ASSERT_EQ(walked.has_value(), listed.has_value()) << "tile " << tile << ", pixel " << px << ", " << py;
                    if (walked) {
                        EXPECT_NEAR(walked->t, listed->t, 1e-9 * walked->t) << "tile " << tile << ", pixel " << px << ", " << py;
                        ++hits;
                    }
                }
        }
        EXPECT_GT(hits, 100);
        EXPECT_EQ(scratch.counters.blob_list_rays, 6u * 64u);  // every ray went down its tile's list
    }
}

// A tile the blob says its rays all miss (Blob::misses_tile: no
// component's reach, or a field bounded below the threshold) has no hit on
// any ray through its pixels or its corners — for every kernel, with
// negative, stretched and cylinder components — and the bound proves tiles
// whose rays do pass within reach of a component, not only those beside
// every reach box.
TEST(Blob, NoRayOfATileItMissesHitsIt) {
    for (const BlobKernel kernel : {BlobKernel::Blinn, BlobKernel::Soft, BlobKernel::PovRay, BlobKernel::Metaball}) {
        SCOPED_TRACE(blob_kernel_info(kernel).name);
        const Blob blob(BlobDescription{"blob", random_blob(kernel, 31), no_material, 1e-9, 1});
        TraceScratch scratch(1);
        int missed = 0, missed_within_reach = 0, rays = 0;
        for (int ty = 0; ty < 12; ++ty)
            for (int tx = 0; tx < 12; ++tx) {
                const CameraFrustum f =
                    test::square_tile({0.4, -0.3, -6.0}, {-0.05, 0.04, 1.0}, 8, 0.009, -0.45 + 0.072 * tx, 0.45 - 0.072 * ty);
                if (!blob.misses_tile(f, scratch)) continue;
                ++missed;
                bool within_reach = false;
                for (int py = 0; py <= 2 * f.rows; ++py)
                    for (int px = 0; px <= 2 * f.columns; ++px) {  // the pixels' corners and centres
                        const Ray ray{f.origin, normalize(f.forward + f.right * (f.u0 + 0.5 * px * f.du) +
                                                          f.up * (f.v0 + 0.5 * py * f.dv))};
                        const std::uint64_t kernels = scratch.counters.blob_kernels;
                        EXPECT_FALSE(blob.first_hit(ray, 0.0, 1e9, scratch).has_value())
                            << "tile " << tx << ", " << ty << ", point " << px << ", " << py;
                        within_reach |= scratch.counters.blob_kernels > kernels;
                        ++rays;
                    }
                missed_within_reach += within_reach;
            }
        EXPECT_GT(missed, 20);
        EXPECT_GT(missed_within_reach, 5);  // the field bound proved them
        EXPECT_GT(rays, 20 * 289);
    }
}

// A shadow ray is first tried against the components in reach where the
// last one found the inside (all strengths positive: their field alone is a
// lower bound). Rays from a grid of points towards a light, neighbours in
// turn, answer as each does with a scratch of its own; the cache settled
// many of them. A blob with a negative component never uses it.
TEST(Blob, AShadowRayIsFirstTriedAgainstTheLastBlockersComponents) {
    for (const bool negative : {false, true}) {
        SCOPED_TRACE(negative ? "a negative component" : "all positive");
        std::vector<BlobComponent> components;
        std::mt19937 random(21);
        std::uniform_real_distribution<double> place(-3.0, 3.0), size(0.5, 0.9);
        for (int i = 0; i < 150; ++i) {
            BlobComponent c;
            c.center = {place(random), place(random), place(random)};
            c.radius = size(random);
            if (negative && i == 7) c.strength = -0.5;
            components.push_back(c);
        }
        const Blob blob(BlobDescription{"cloud", std::make_shared<const BlobModel>(BlobKernel::PovRay, 0.5, components), no_material, 1e-9, 1});
        const Vec3d light{-20, 25, -15};
        TraceScratch shared(1);
        int blocked = 0, rays = 0;
        for (int y = 0; y < 40; ++y)
            for (int x = 0; x < 40; ++x) {
                const Vec3d from{-3.5 + 0.175 * x, -3.5 + 0.175 * y, 0.3 * std::sin(x * 0.7 + y)};
                const Ray ray{from, normalize(light - from)};
                const double far = length(light - from);
                TraceScratch alone(1);
                const bool expected = blob.occluded(ray, 1e-6, far, alone);
                ASSERT_EQ(blob.occluded(ray, 1e-6, far, shared), expected) << "ray " << x << ", " << y;
                blocked += expected;
                ++rays;
            }
        EXPECT_GT(blocked, rays / 5);
        if (negative) EXPECT_EQ(shared.counters.blob_cached_shadows, 0u);
        else EXPECT_GT(shared.counters.blob_cached_shadows, static_cast<std::uint64_t>(blocked / 3));
    }
}

TEST(Blob, MetaballQuadraticsApproximateTheExactKernel) {
    // The survey's §3.1 approximation against the exact metaball kernel on
    // the same blob: how far the first hits move, and how many rays change
    // between hit and miss (near the silhouette, where the field barely
    // reaches the threshold).
    const auto model = random_blob(BlobKernel::Metaball, 11, false);
    const Blob exact(BlobDescription{"exact", model, no_material, 1e-9, 1, false});
    const Blob approximate(BlobDescription{"quadratics", model, no_material, 1e-9, 1, true});
    TraceScratch scratch(0);
    std::mt19937 random(9);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    double max_dt = 0.0, sum_dt = 0.0;
    int both = 0, changed = 0;
    std::vector<double> dts;
    for (int i = 0; i < 10000; ++i) {
        const Vec3d dir = normalize(Vec3d{u(random), u(random), u(random)});
        const Ray ray{Vec3d{1.3 * u(random), 1.3 * u(random), 1.3 * u(random)} - 6.0 * dir, dir};
        const auto a = exact.first_hit(ray, 0.0, 1e9, scratch), b = approximate.first_hit(ray, 0.0, 1e9, scratch);
        if (a && b) {
            ++both;
            max_dt = std::max(max_dt, std::abs(a->t - b->t));
            sum_dt += std::abs(a->t - b->t);
            dts.push_back(std::abs(a->t - b->t));
        } else if (a || b) {
            ++changed;
        }
    }
    std::sort(dts.begin(), dts.end());
    std::cout << "metaball quadratics: " << both << " rays hit by both, max |dt| " << max_dt << ", median "
              << dts[dts.size() / 2] << ", 99th percentile " << dts[dts.size() * 99 / 100] << ", mean |dt| "
              << sum_dt / both << " (radii 0.5 to 0.9), " << changed << " of 10000 rays change between hit and miss\n";
    EXPECT_GT(both, 3000);
    // An approximation (measured: median 0.014, 99th percentile 0.13, on
    // radii of 0.5 to 0.9), not one that is off entirely.
    EXPECT_LT(dts[dts.size() / 2], 0.03);
    EXPECT_LT(dts[dts.size() * 99 / 100], 0.3);
    EXPECT_LT(changed, 150);
}

TEST(Blob, NoFirstHitLiesBehindAPartOfTheSolid) {
    // The blob's own field (cut-off Gaussians included, or metaballs'
    // quadratic pieces) sampled along each ray before its first hit must be
    // outside, and the spans' insides must be where it is inside. A coarse
    // Gaussian cut-off (10⁻²) makes the field jump where components enter;
    // the quadratic pieces differ from the exact kernel by a few per cent.
    struct Case {
        BlobKernel kernel;
        double tolerance;
        bool quadratics;
    };
    for (const Case c : {Case{BlobKernel::Blinn, 1e-2, false}, Case{BlobKernel::Metaball, 1e-7, true},
                         Case{BlobKernel::PovRay, 1e-7, false}}) {
        const auto model = random_blob(c.kernel, 17, !c.quadratics);
        const Blob blob(BlobDescription{"blob", model, no_material, c.tolerance, 1, c.quadratics});
        TraceScratch scratch(0);
        std::mt19937 random(4);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        int hits = 0, inside_before = 0, span_mismatches = 0;
        for (int i = 0; i < 2000; ++i) {
            const Vec3d dir = normalize(Vec3d{u(random), u(random), u(random)});
            const Ray ray{Vec3d{u(random), u(random), u(random)} - 6.0 * dir, dir};
            SpanList spans;
            blob.spans(ray, 0.0, 12.0, scratch, spans);
            // The quadratic pieces are the approximate field along this ray:
            // sample them through spans (the exact value_at would differ).
            const auto hit = blob.first_hit(ray, 0.0, 12.0, scratch);
            if (!c.quadratics) {
                const double end = hit ? hit->t : 12.0;
                for (int k = 0; k < 400; ++k)
                    if (blob.value_at(ray.at(end * k / 400.0)) < -1e-9) ++inside_before;
            }
            if (hit) ++hits;
            if (hit != std::nullopt && !spans.empty() && std::abs(spans.front().enter.t - hit->t) > 1e-9) ++span_mismatches;
            if (hit.has_value() != !spans.empty()) ++span_mismatches;
        }
        EXPECT_GT(hits, 300) << blob_kernel_info(c.kernel).name;
        EXPECT_EQ(inside_before, 0) << blob_kernel_info(c.kernel).name;
        EXPECT_EQ(span_mismatches, 0) << blob_kernel_info(c.kernel).name;
    }
}

TEST(Blob, OccludedAgreesWithTheFirstHitForLessWork) {
    // A shadow ray needs any point inside, not the first: the strongest
    // component's nearest approach is tried before a segment is solved.
    // Both answers agree on every ray, segments from the middle of the
    // solid included; rays through the solid cost fewer evaluations.
    for (const BlobKernel kernel : {BlobKernel::Blinn, BlobKernel::PovRay, BlobKernel::Soft, BlobKernel::Metaball}) {
        const auto model = random_blob(kernel, 17);
        const Blob blob(BlobDescription{"blob", model, no_material, 1e-7, 1});
        TraceScratch scratch(0);
        std::mt19937 random(6);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        int occluded = 0, disagreements = 0;
        std::uint64_t first_hit_cost = 0, occluded_cost = 0;
        for (int i = 0; i < 2000; ++i) {
            const Vec3d dir = normalize(Vec3d{u(random), u(random), u(random)});
            const Ray ray{Vec3d{u(random), u(random), u(random)} - 6.0 * dir, dir};
            const double t_min = i % 2 == 0 ? 0.0 : 6.0;  // half of them start near the middle
            std::uint64_t before = scratch.counters.evaluations();
            const bool hit = blob.first_hit(ray, t_min, 12.0, scratch).has_value();
            first_hit_cost += scratch.counters.evaluations() - before;
            before = scratch.counters.evaluations();
            const bool blocked = blob.occluded(ray, t_min, 12.0, scratch);
            occluded_cost += scratch.counters.evaluations() - before;
            if (hit != blocked) ++disagreements;
            if (blocked) ++occluded;
        }
        const std::string_view name = blob_kernel_info(kernel).name;
        EXPECT_GT(occluded, 300) << name;
        EXPECT_EQ(disagreements, 0) << name;
        EXPECT_LT(occluded_cost, first_hit_cost) << name;
        EXPECT_EQ(scratch.counters.failed_queries, 0u) << name;
    }
}

TEST(Blob, MetaballQuadraticsLetARayLeaveAlongTheNormal) {
    // A ray from a point a hair outside the approximate surface, along the
    // normal, is not blocked at its start, although its own quadratic pieces
    // may put that point inside by the approximation's error: its first hit
    // is its first entry. (Oblique rays from the surface may still meet
    // their own approximation of it: docs/blobs.md.)
    const auto model = random_blob(BlobKernel::Metaball, 11, false);
    const Blob blob(BlobDescription{"q", model, no_material, 1e-7, 1, true});
    TraceScratch scratch(0);
    std::mt19937 random(2);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int lit = 0, self_shadowed = 0;
    for (int i = 0; i < 5000; ++i) {
        const Vec3d dir = normalize(Vec3d{u(random), u(random), u(random)});
        const Ray ray{Vec3d{u(random), u(random), u(random)} - 6.0 * dir, dir};
        const auto hit = blob.first_hit(ray, 0.0, 12.0, scratch);
        if (!hit) continue;
        const Vec3d n = blob.local_normal(hit->surface, scratch), p = ray.at(hit->t);
        const auto shadow = blob.first_hit({p + 1e-4 * n, n}, 0.0, 12.0, scratch);
        ++lit;
        if (shadow && shadow->t == 0.0) ++self_shadowed;
    }
    EXPECT_GT(lit, 1000);
    EXPECT_LE(self_shadowed, lit / 200);
}

TEST(Blob, ARayMeetsOnlyTheComponentsAlongIt) {
    // 20 000 small components spread over a 40-unit cube: a ray through it
    // comes within reach of a few of them, not of thousands.
    std::mt19937 random(1);
    std::uniform_real_distribution<double> u(-20.0, 20.0);
    std::vector<BlobComponent> components(20000);
    for (BlobComponent& c : components) {
        c.center = {u(random), u(random), u(random)};
        c.radius = 0.3;
    }
    const Blob blob(BlobDescription{"cloud", std::make_shared<const BlobModel>(BlobKernel::PovRay, 0.5, components),
                                    no_material, 1e-7, 1});
    TraceScratch scratch(0);
    std::uniform_real_distribution<double> v(-1.0, 1.0);
    for (int i = 0; i < 200; ++i) {
        const Vec3d dir = normalize(Vec3d{v(random), v(random), v(random)});
        blob.first_hit({-60.0 * dir, dir}, 0.0, 1e9, scratch);
    }
    EXPECT_LT(static_cast<double>(scratch.counters.blob_kernels) / 200.0, 50.0);
}

TEST(Blob, RefusesWhatCannotBeTraced) {
    BlobComponent c;
    EXPECT_THROW(BlobModel(BlobKernel::PovRay, 0.0, {c}), std::invalid_argument);
    EXPECT_THROW(BlobModel(BlobKernel::PovRay, 1.0, {}), std::invalid_argument);
    c.radius = -1.0;
    EXPECT_THROW(BlobModel(BlobKernel::PovRay, 1.0, {c}), std::invalid_argument);
    c.radius = 1e-310;  // 1/R overflows
    EXPECT_THROW(BlobModel(BlobKernel::PovRay, 1.0, {c}), std::invalid_argument);
    c.radius = 1.0;
    c.blobbiness = -800.0;  // e^800 overflows
    EXPECT_THROW(BlobModel(BlobKernel::Blinn, 1.0, {c}), std::invalid_argument);
    c.blobbiness = -1.0;
    c.shape = Mat4::scale({1.0, 0.0, 1.0});
    EXPECT_THROW(BlobModel(BlobKernel::PovRay, 1.0, {c}), std::invalid_argument);
    c.shape = Mat4::identity();
    c.strength = -1.0;  // only negative: no solid
    const auto negative = std::make_shared<const BlobModel>(BlobKernel::PovRay, 1.0, std::vector{c});
    EXPECT_THROW(Blob(BlobDescription{"b", negative, no_material, 1e-7, 1}), std::invalid_argument);
    c.strength = 1.0;
    c.end = c.center;  // a cylinder of no length
    EXPECT_THROW(BlobModel(BlobKernel::PovRay, 1.0, {c}), std::invalid_argument);
    c.end = c.center + Vec3d{1, 0, 0};
    c.shape = Mat4::scale({1.0, 2.0, 1.0});  // a cylinder takes no shape
    EXPECT_THROW(BlobModel(BlobKernel::PovRay, 1.0, {c}), std::invalid_argument);
    c.shape = Mat4::identity();
    const auto tube = std::make_shared<const BlobModel>(BlobKernel::Metaball, 1.0, std::vector{c});
    EXPECT_THROW(Blob(BlobDescription{"b", tube, no_material, 1e-7, 1, true}), std::invalid_argument);  // quadratics
}

}  // namespace
}  // namespace zeroset
