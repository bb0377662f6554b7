// The accuracy study of the polynomial method: for every scene in
// scenes/algebraic, N rays (default 10 000: random, grazing and near-miss, through nodes)
// with MPFI first-hit references, and for every solver the miss rate, the
// rate of hits where no root is (with the worst |H| / B at those hits: ≤ 1
// means the arithmetic could not tell H from 0 there), and the max and
// median |t − t_ref| / scale.
// Offline (minutes); the test runs a smaller sample.
//
//   algebraic_accuracy [RAYS_PER_SURFACE] [SCENE.zs …]
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "support/algebraic_accuracy.hpp"
#include "zeroset/scene/load_scene.hpp"

int main(int argc, char** argv) {
    using namespace zeroset;
    const int count = argc > 1 ? std::stoi(argv[1]) : 10000;
    std::vector<std::filesystem::path> scenes;
    for (int i = 2; i < argc; ++i) scenes.emplace_back(argv[i]);
    if (scenes.empty()) {
        for (const auto& entry : std::filesystem::directory_iterator(ZEROSET_SOURCE_DIR "/scenes/algebraic"))
            scenes.push_back(entry.path());
        std::ranges::sort(scenes);
    }
    std::printf("| surface | solver | rays | misses | hits with no root | worst abs(H)/B there | max err/scale | median err/scale |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    for (const auto& file : scenes) {
        const Scene scene = load_scene(file);
        const Object& object = placed_objects(scene).at(0).object();
        const auto rays = test::algebraic_rays(object, count, 2024);
        for (const PolynomialSolver solver : all_polynomial_solvers()) {
            const test::SolverAccuracy a = test::measure_solver(object, rays, solver);
            std::printf("| %s | %s | %d | %.3f %% | %.3f %% | %.2f | %.1e | %.1e |\n", file.stem().c_str(),
                        std::string(polynomial_solver_name(solver)).c_str(), a.rays, 100.0 * a.misses / a.rays,
                        100.0 * a.unresolved_hits / a.rays, a.worst_unresolved, a.max_error(), a.median_error());
            std::fflush(stdout);
        }
    }
}
