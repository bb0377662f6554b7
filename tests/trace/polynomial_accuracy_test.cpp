// The polynomial method against MPFI references on every named algebraic
// surface (issue: algebraic surfaces, "Accuracy"): random, grazing and
// node rays. The guaranteed solvers — Sturm, Descartes, and the fast solver
// `auto` uses — must miss nothing beyond the documented tolerance
// (support/algebraic_accuracy.hpp), and every hit they report where no root
// is must lie where the exact |H| is below the method's proven rounding
// bound. The full study (10 000 rays a surface, every solver) is the
// algebraic_accuracy tool.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "support/algebraic_accuracy.hpp"
#include "zeroset/scene/load_scene.hpp"

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

}  // namespace
}  // namespace zeroset::test
