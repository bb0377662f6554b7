// The scenes shipped in scenes/: all of them parse, the built-in default is
// exactly scenes/hart1993/blinn_blobs.zs, and the blob scene's bounds hold
// its whole surface.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "scene_test_support.hpp"

namespace zeroset {
namespace {

const std::filesystem::path source_dir = ZEROSET_SOURCE_DIR;

std::string read(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The cells of `region` outside `skip` where interval evaluation cannot show
/// f > 0, after subdividing each doubtful cell `depth` more times.
int cells_not_proven_positive(Evaluator<Interval>& f, const Box3& skip, const Box3& region, int depth) {
    const bool inside_skip = skip.contains(region.lo) && skip.contains(region.hi);
    if (inside_skip || evaluate_box(f, region.lo, region.hi).lo > 0.0) return 0;
    if (depth == 0) return 1;
    const Vec3d mid = region.center();
    int count = 0;
    for (int octant = 0; octant < 8; ++octant) {
        const Vec3d lo{octant & 1 ? mid.x : region.lo.x, octant & 2 ? mid.y : region.lo.y, octant & 4 ? mid.z : region.lo.z};
        const Vec3d hi{octant & 1 ? region.hi.x : mid.x, octant & 2 ? region.hi.y : mid.y, octant & 4 ? region.hi.z : mid.z};
        count += cells_not_proven_positive(f, skip, {lo, hi}, depth - 1);
    }
    return count;
}

TEST(SceneFiles, DefaultSceneIsTheBlinnBlobsFileWordForWord) {
    EXPECT_EQ(default_scene_text(), read(source_dir / "scenes/hart1993/blinn_blobs.zs"));
}

TEST(SceneFiles, DefaultSceneIsFigureOne) {
    const Scene s = default_scene();
    ASSERT_EQ(placed_objects(s).size(), 2U);  // the blobs and the floor that catches their shadow
    EXPECT_EQ(placed_objects(s).at(0).name(), "blobs");
    EXPECT_EQ(s.image.width, 800);
    EXPECT_EQ(s.image.height, 600);
    EXPECT_FALSE(s.lights.empty());
    // h = 1 - e^-f - e^-g (eq. 12) at a few points, by hand.
    const Tape tape(placed_objects(s).at(0).object().surface);
    Evaluator<double> h(tape);
    const auto expected = [](double x, double y, double z) {
        const double f = (x - 1.2) * (x - 1.2) + y * y + z * z - 1;
        const double g = (x + 1.2) * (x + 1.2) + y * y + z * z - 1;
        return 1 - std::exp(-f) - std::exp(-g);
    };
    for (const Vec3d p : {Vec3d{0, 0, 0}, Vec3d{1.2, 0, 0}, Vec3d{-2, 0.5, 0.3}, Vec3d{0.3, -0.9, 1.4}})
        EXPECT_NEAR(h(p.x, p.y, p.z), expected(p.x, p.y, p.z), 1e-15);
}

TEST(SceneFiles, BlinnBlobBoundsHoldTheWholeSurface) {
    // Interval arithmetic proves h > 0 everywhere in [-20, 20]³ outside the
    // bounds box; beyond that f, g > 300, so h > 0 plainly.
    const Scene s = default_scene();
    const Box3 box = placed_objects(s).at(0).object().bounds.enclosing_box();
    const Tape tape(placed_objects(s).at(0).object().surface);
    Evaluator<Interval> h(tape);
    const double r = 20.0;
    EXPECT_EQ(cells_not_proven_positive(h, box, {{-r, -r, -r}, {r, r, r}}, 10), 0);
}

TEST(SceneFiles, EveryShippedSceneParses) {
    int count = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(source_dir / "scenes")) {
        if (entry.path().extension() != ".zs") continue;
        ++count;
        try {
            const Scene s = load_scene(entry.path());
            EXPECT_FALSE(placed_objects(s).empty()) << entry.path();
        } catch (const SceneError& e) {
            ADD_FAILURE() << e.what();
        }
    }
    EXPECT_GE(count, 5);
}

}  // namespace
}  // namespace zeroset
