// The polynomial method against MPFI references on every named algebraic
// surface (issue: algebraic surfaces, "Accuracy"): random, grazing and
// node rays. The guaranteed solvers — Sturm, Descartes, and the fast solver
// `auto` uses — must miss nothing beyond the documented tolerance
// (support/algebraic_accuracy.hpp), and every hit they report where no root
// is must lie where the exact |H| is below the method's proven rounding
// bound. The full study (10 000 rays a surface, every solver) is the
// algebraic_accuracy tool.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "support/algebraic_accuracy.hpp"
#include "zeroset/scene/load_scene.hpp"
#include "zeroset/trace/polynomial_method.hpp"

namespace zeroset::test {
namespace {

TEST(PolynomialAccuracy, GuaranteedSolversMissNothingOnAnyNamedSurface) {
    std::vector<std::filesystem::path> scenes;
    for (const auto& entry : std::filesystem::directory_iterator(ZEROSET_SOURCE_DIR "/scenes/algebraic"))
        scenes.push_back(entry.path());
    ASSERT_EQ(scenes.size(), 17u);
    for (const auto& file : scenes) {
        const Scene scene = load_scene(file);
        const Object& object = placed_objects(scene).at(0).object();
        const auto rays = algebraic_rays(object, 150, 77);
        for (const PolynomialSolver solver : {PolynomialSolver::Sturm, PolynomialSolver::Descartes, PolynomialSolver::Fast}) {
            SCOPED_TRACE(file.stem().string() + " / " + std::string(polynomial_solver_name(solver)));
            const SolverAccuracy a = measure_solver(object, rays, solver);
            EXPECT_EQ(a.rays, 150);
            EXPECT_EQ(a.misses, 0);
            EXPECT_LE(a.worst_unresolved, 2.0);
            EXPECT_GT(a.errors.size(), 10u);  // the rays do meet the surface
            EXPECT_LE(a.median_error(), 1e-12);
        }
    }
}

// A compact surface in bounds 10⁴ times its size (a POV-Ray poly without
// bounded_by, a sheet's ±10⁴ box): F̂ formed about the span's middle,
// thousands of units away, blurs the surface itself. The first hits must be
// as accurate as on the surface's own span.
TEST(PolynomialAccuracy, ASpanReachingFarPastTheSurfaceLosesNoAccuracy) {
    for (const char* name : {"steiner", "torus", "kummer"}) {
        const Scene scene = load_scene(std::string(ZEROSET_SOURCE_DIR "/scenes/algebraic/") + name + ".zs");
        const Object& object = placed_objects(scene).at(0).object();
        const auto rays = algebraic_rays(object, 60, 91);
        for (const PolynomialSolver solver : {PolynomialSolver::Sturm, PolynomialSolver::Fast}) {
            SCOPED_TRACE(std::string(name) + " / " + std::string(polynomial_solver_name(solver)));
            const SolverAccuracy a = measure_solver(object, rays, solver, 2e4);
            EXPECT_EQ(a.misses, 0);
            EXPECT_LE(a.worst_unresolved, 2.0);
            EXPECT_GT(a.errors.size(), 10u);
            EXPECT_LE(a.median_error(), 1e-12);
        }
    }
}

// The same for every hit (Roth CSG's spans): each simple root the MPFI
// oracle finds on the surface's span is among the hits on the long one.
TEST(PolynomialAccuracy, AllHitsOnASpanReachingFarPastTheSurfaceMissNoRoot) {
    for (const char* name : {"steiner", "torus"}) {
        SCOPED_TRACE(name);
        const Scene scene = load_scene(std::string(ZEROSET_SOURCE_DIR "/scenes/algebraic/") + name + ".zs");
        const Object& object = placed_objects(scene).at(0).object();
        const double scale = object.bounds.enclosing_box().diagonal();
        const Tape tape(object.surface);
        PolynomialMethod method(tape, settings_for_scale(scale));
        MpfiRayOracle oracle(object.surface, scale);
        RayFunction h(tape);
        int roots_checked = 0;
        for (const AlgebraicRay& r : algebraic_rays(object, 60, 92)) {
            h.set_ray(r.ray);
            std::vector<double> hits;
            TraceCounters counters;
            method.all_hits(h, Span{r.span.t0, r.span.t1 + 2e4}, hits, counters);
            for (const OracleRoot& root : oracle.all_roots(r.ray, r.span, 8)) {
                if (root.kind != RootKind::Simple || root.t == r.span.t0) continue;
                const double tolerance = std::max(1e-9 * scale, 2.0 * method.rounding_bound(r.ray, r.span) / root.slope);
                ++roots_checked;
                EXPECT_TRUE(std::ranges::any_of(hits, [&](double t) { return std::abs(t - root.t) <= tolerance; }))
                    << "root at t = " << root.t;
            }
        }
        EXPECT_GT(roots_checked, 20);
    }
}

}  // namespace
}  // namespace zeroset::test
