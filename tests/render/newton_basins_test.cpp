// Newton basins (survey Fig. 5) on cases with known answers: a quadratic with
// two real roots splits the plane along their perpendicular bisector (Cayley's
// theorem); one with complex conjugate roots sends every start off the real
// axis to a complex root; and the survey's blobs along the survey's ray have
// four real roots and reproduce, on the real axis, the walk of Figure 4.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "zeroset/render/newton_basins.hpp"
#include "zeroset/render/render_settings.hpp"

namespace zeroset {
namespace {

const Expr X = var_x(), Y = var_y(), Z = var_z();
const Expr unit_sphere = square(X) + square(Y) + square(Z) - 1.0;
// The survey's eq. 12: two unit spheres at (±1.2, 0, 0) blended as Blinn's blobs.
const Expr blobs = 1.0 - exp(-(square(X - 1.2) + square(Y) + square(Z) - 1.0)) -
                   exp(-(square(X + 1.2) + square(Y) + square(Z) - 1.0));
const Ray survey_ray{{-4.905, -0.67, 0.364}, {0.981, 0.174, 0.0872}};

BasinSettings small(ComplexRect region, int width, int height) {
    BasinSettings s;
    s.region = region;
    s.width = width;
    s.height = height;
    return s;
}

/// The pixel is the basin colour of `label`, dimmed by a factor in (0, 1].
::testing::AssertionResult has_basin_colour(const Vec3f& pixel, int label) {
    const Vec3f c = basin_colour(label);
    const float k = pixel.x / c.x;
    if (k > 0.0f && k <= 1.0f && std::abs(pixel.y - k * c.y) < 1e-5f && std::abs(pixel.z - k * c.z) < 1e-5f)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "pixel (" << pixel.x << ", " << pixel.y << ", " << pixel.z
                                         << ") is not a shade of basin colour " << label;
}

TEST(NewtonBasins, TwoRealRootsSplitThePlaneAtTheirBisector) {
    // H(t) = (t − 3)² − 1: roots 2 and 4, bisector Re t = 3 (between pixel columns 31 and 32).
    const Tape tape(unit_sphere);
    const BasinSettings settings = small({0.0, 6.0, -2.0, 2.0}, 64, 32);
    const BasinMap map = newton_basins(tape, {{-3.0, 0.0, 0.0}, {1.0, 0.0, 0.0}}, settings);
    ASSERT_EQ(map.real_roots.size(), 2u);
    EXPECT_NEAR(map.real_roots[0], 2.0, 1e-12);
    EXPECT_NEAR(map.real_roots[1], 4.0, 1e-12);
    for (int y = 0; y < settings.height; ++y) {
        for (int x = 0; x < settings.width; ++x) {
            const int expected = basin_start(settings, x, y).re < 3.0 ? 0 : 1;
            ASSERT_EQ(map.label_at(x, y), expected) << x << ", " << y;
            ASSERT_TRUE(has_basin_colour(map.image.at(x, y), expected)) << x << ", " << y;
        }
    }
    // Fast convergence is drawn brighter: next to a root, brighter than near the bisector.
    EXPECT_GT(map.image.at(21, 15).x, map.image.at(31, 0).x);
}

TEST(NewtonBasins, UsesTheDirectionAsGiven) {
    // Twice the direction halves the roots: t = 1 and 2.
    const Tape tape(unit_sphere);
    const BasinMap map = newton_basins(tape, {{-3.0, 0.0, 0.0}, {2.0, 0.0, 0.0}}, small({0.0, 3.0, -1.0, 1.0}, 16, 8));
    ASSERT_EQ(map.real_roots.size(), 2u);
    EXPECT_NEAR(map.real_roots[0], 1.0, 1e-12);
    EXPECT_NEAR(map.real_roots[1], 2.0, 1e-12);
}

TEST(NewtonBasins, ComplexConjugateRootsAreBlack) {
    // The ray misses the sphere: H(t) = (t − 3)² + 3, roots 3 ± i√3. Every
    // start off the real axis converges to the root in its half-plane.
    const Tape tape(unit_sphere);
    const BasinSettings settings = small({0.0, 6.0, -2.0, 2.0}, 32, 16);
    const BasinMap map = newton_basins(tape, {{-3.0, 2.0, 0.0}, {1.0, 0.0, 0.0}}, settings);
    EXPECT_TRUE(map.real_roots.empty());
    for (int y = 0; y < settings.height; ++y) {
        for (int x = 0; x < settings.width; ++x) {
            ASSERT_EQ(map.label_at(x, y), BasinMap::complex_root);
            ASSERT_EQ(map.image.at(x, y), Vec3f(0.0f, 0.0f, 0.0f));
        }
    }
    Evaluator<Jet<Complex>> eval(tape);
    const NewtonOutcome upper = newton_from(eval, {{-3.0, 2.0, 0.0}, {1.0, 0.0, 0.0}}, {1.0, 0.5}, 100);
    ASSERT_EQ(upper.kind, NewtonOutcome::Kind::ComplexRoot);
    EXPECT_NEAR(upper.limit.re, 3.0, 1e-12);
    EXPECT_NEAR(upper.limit.im, std::sqrt(3.0), 1e-12);
}

/// The real roots of H along the survey's ray, by sign changes and bisection in double.
std::vector<double> blob_roots_by_bisection() {
    const Tape tape(blobs);
    Evaluator<double> eval(tape);
    const auto h = [&](double t) {
        const Vec3d p = survey_ray.at(t);
        return eval(p.x, p.y, p.z);
    };
    std::vector<double> roots;
    for (double t = 0.0; t < 10.0; t += 0.01) {
        double lo = t, hi = t + 0.01;
        if ((h(lo) < 0.0) == (h(hi) < 0.0)) continue;
        for (int i = 0; i < 60; ++i) {
            const double mid = 0.5 * (lo + hi);
            ((h(lo) < 0.0) == (h(mid) < 0.0) ? lo : hi) = mid;
        }
        roots.push_back(lo);
    }
    return roots;
}

TEST(NewtonBasins, SurveyBlobsHaveFourRealRootsAndAllThreeKindsOfRegion) {
    const std::vector<double> expected = blob_roots_by_bisection();
    ASSERT_EQ(expected.size(), 4u);
    const Tape tape(blobs);
    BasinSettings settings;  // the default rectangle is made for this case
    settings.width = 96;
    settings.height = 54;
    const BasinMap map = newton_basins(tape, survey_ray, settings);
    ASSERT_EQ(map.real_roots.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(map.real_roots[i], expected[i], 1e-9);
    std::vector<int> counts(6, 0);  // diverged, complex, roots 0…3
    for (const int label : map.labels) ++counts[static_cast<std::size_t>(label + 2)];
    for (std::size_t i = 0; i < counts.size(); ++i) EXPECT_GT(counts[i], 0) << "label " << static_cast<int>(i) - 2;
}

TEST(NewtonBasins, RealStartsRetraceFigure4) {
    // Figure 4: from t₀ = 3.5 the first intersection; 3.6 the third; 3.7
    // shoots back to about −5 and diverges; 3.8 the fourth; 3.9 diverges;
    // 4.0 the second.
    const std::vector<double> roots = blob_roots_by_bisection();
    const Tape tape(blobs);
    Evaluator<Jet<Complex>> eval(tape);
    const auto converges_to = [&](double t0, std::size_t root) {
        const NewtonOutcome o = newton_from(eval, survey_ray, Complex(t0), 100);
        EXPECT_EQ(o.kind, NewtonOutcome::Kind::RealRoot) << t0;
        EXPECT_NEAR(o.limit.re, roots[root], 1e-9) << t0;
    };
    converges_to(3.5, 0);
    converges_to(3.6, 2);
    EXPECT_NEAR(newton_from(eval, survey_ray, Complex(3.7), 1).limit.re, -4.9, 0.1);
    EXPECT_EQ(newton_from(eval, survey_ray, Complex(3.7), 100).kind, NewtonOutcome::Kind::Diverged);
    converges_to(3.8, 3);
    EXPECT_EQ(newton_from(eval, survey_ray, Complex(3.9), 100).kind, NewtonOutcome::Kind::Diverged);
    converges_to(4.0, 1);
}

TEST(NewtonBasins, OutputDoesNotDependOnTheThreadCount) {
    const Tape tape(blobs);
    BasinSettings settings = small({2.0, 8.0, -2.0, 2.0}, 40, 23);
    settings.threads = 1;
    const BasinMap one = newton_basins(tape, survey_ray, settings);
    settings.threads = 3;
    const BasinMap three = newton_basins(tape, survey_ray, settings);
    EXPECT_EQ(one.real_roots, three.real_roots);
    EXPECT_EQ(one.labels, three.labels);
    EXPECT_TRUE(one.image.pixels == three.image.pixels);
}

TEST(NewtonBasins, RejectsBadSettings) {
    const Tape tape(unit_sphere);
    const Ray ray{{-3.0, 0.0, 0.0}, {1.0, 0.0, 0.0}};
    EXPECT_THROW(newton_basins(tape, ray, small({0.0, 6.0, -2.0, 2.0}, 0, 8)), RenderError);
    EXPECT_THROW(newton_basins(tape, ray, small({0.0, 6.0, -2.0, 2.0}, 8, -1)), RenderError);
    EXPECT_THROW(newton_basins(tape, ray, small({6.0, 6.0, -2.0, 2.0}, 8, 8)), RenderError);
    EXPECT_THROW(newton_basins(tape, ray, small({0.0, 6.0, 2.0, -2.0}, 8, 8)), RenderError);
    constexpr double inf = std::numeric_limits<double>::infinity();
    EXPECT_THROW(newton_basins(tape, ray, small({0.0, inf, -2.0, 2.0}, 8, 8)), RenderError);
    BasinSettings no_iterations = small({0.0, 6.0, -2.0, 2.0}, 8, 8);
    no_iterations.max_iterations = 0;
    EXPECT_THROW(newton_basins(tape, ray, no_iterations), RenderError);
    EXPECT_THROW(newton_basins(tape, {{-3.0, 0.0, 0.0}, {0.0, 0.0, 0.0}}, small({0.0, 6.0, -2.0, 2.0}, 8, 8)),
                 RenderError);
}

}  // namespace
}  // namespace zeroset
