// write_scene: every shipped scene, written as text and read back, renders
// the same image; and the writer's forms of each kind of node read back as
// what they were.
#include "scene/scene_test_support.hpp"

#include <filesystem>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/tape.hpp"
#include "zeroset/render/renderer.hpp"
#include "zeroset/scene/scene_writer.hpp"

namespace zeroset::test {
namespace {

LargeBuffer<Vec3f> pixels(const Scene& scene) {
    RenderSettings settings;
    settings.width = 24;
    settings.height = 18;
    return render(scene, settings).image.pixels;
}

TEST(SceneWriter, EveryShippedSceneReadsBackAsTheSameImage) {
    int count = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(ZEROSET_SOURCE_DIR "/scenes")) {
        // The 100 000-component cloud takes seconds to read, twice: its own tests read it.
        if (entry.path().extension() != ".zs" || entry.path().filename() == "cloud_100k.zs") continue;
        const Scene original = load_scene(entry.path());
        const std::string text = write_scene(original);
        Scene again;
        try {
            again = parse_scene(text, "written.zs", entry.path().parent_path());
        } catch (const SceneError& e) {
            ADD_FAILURE() << entry.path() << ": " << e.what() << "\n" << text.substr(0, 2000);
            continue;
        }
        EXPECT_EQ(pixels(original), pixels(again)) << entry.path();
        ++count;
    }
    EXPECT_GE(count, 20);
}

TEST(SceneWriter, WritesEachKindOfNode) {
    const Scene s = parse("camera { from (1, 2, -5) at (0, 0.5, 0) fov 35 shift_up 0.125 }\n"
                          "light { direction (1, -1, 1) color (0.5, 0.5, 0.5) shadows off }\n"
                          "object \"o\" { surface x^2 + (-y)^2 + z^2 - 1 bounds sphere((0, 0, 0), 2) method interval open on "
                          "clip x - 0.5 gate box((-1, -1, -1), (1, 1, 0.5)) material { color (x, 0, 1) } translate (1, 0, 0) }\n"
                          "blob { kernel blinn threshold 0.5 component { center (1, 0, 0) radius 2 blobbiness -2 scale (1, 2, 1) } "
                          "component { from (0, 0, 0) to (0, 1, 0) radius 0.5 } }\n"
                          "sweep { curve catmull_rom closed on radius 0.2 point (0, 0, 0) point (1, 0, 0) point (0, 1, 0) }\n"
                          "fractal { kind mandelbulb power 6 iterations 5 }\n"
                          "difference \"d\" { object { surface x bounds box((-1, -1, -1), (1, 1, 1)) cut on } "
                          "object { surface y bounds none } rotate (0, 30, 0) }\n");
    const std::string text = write_scene(s, "a header");
    EXPECT_EQ(text.rfind("# a header\n", 0), 0U) << text;
    const Scene t = parse(text);
    EXPECT_EQ(write_scene(t, "a header"), text);  // a fixed point: nothing lost or changed
    EXPECT_EQ(t.camera.shift_up, 0.125);
    EXPECT_EQ(t.camera.shift_right, 0.0);
    const auto objects = placed_objects(t);
    ASSERT_EQ(objects.size(), 8U);  // the sweep's 3 pieces are 3 sweeps in a group, the difference has 2
    EXPECT_TRUE(objects[0].object().open);
    EXPECT_EQ(objects[0].object().bounds.kind, Bounds::Kind::Sphere);
    EXPECT_EQ(objects[0].object().method, Method::Interval);
    ASSERT_TRUE(objects[0].object().gate);
    EXPECT_EQ(objects[0].object().gate->box.hi.z, 0.5);
    EXPECT_EQ(objects[1].object().blob->components().size(), 2U);
    EXPECT_TRUE(objects[5].object().fractal);
}

/// f and g agree at points spread over [−2, 2]³.
void expect_same_function(const Expr& f, const Expr& g) {
    const Tape tf(f), tg(g);
    Evaluator<double> ef(tf), eg(tg);
    for (int i = 0; i < 64; ++i) {
        const double x = -2.0 + 0.0625 * i, y = 1.5 - 0.05 * i, z = 0.03 * i - 1.0;
        EXPECT_EQ(ef(x, y, z), eg(x, y, z)) << "at (" << x << ", " << y << ", " << z << ")";
    }
}

TEST(SceneWriter, DeepAndSharedExpressionsReadBackThroughLets) {
    // A chain far deeper than the parser's nesting limit, the same chain
    // with each level's part used twice, and a DAG whose levels each use
    // the one below twice (2^40 nodes unfolded).
    const Expr X = var_x(), Y = var_y(), Z = var_z();
    const Expr ball = square(X) + square(Y) + square(Z) - 1.0;
    Expr chain = ball, deep = ball, shared = ball;
    for (int i = 0; i < 5000; ++i) chain = sin(chain);
    for (int i = 0; i < 5000; ++i) deep = sin(deep) + 0.5 * deep;
    for (int i = 0; i < 40; ++i) shared = shared + 0.001 * sin(shared);
    for (const Expr& f : {chain, deep, shared}) {
        Scene s = parse("object { surface x bounds box((-2, -2, -2), (2, 2, 2)) }");
        std::const_pointer_cast<SceneNode>(s.nodes.front())->object.surface = f;
        const std::string text = write_scene(s);
        EXPECT_LT(text.size(), 2'000'000U);
        EXPECT_NE(text.find("\nlet part_1 = "), std::string::npos);
        const Scene t = parse(text);
        expect_same_function(f, placed_objects(t).front().object().surface);
    }
}

TEST(SceneWriter, LogSumExpReadsBack) {
    // ln of a sum of exps becomes the log-sum-exp op, whose .vm name is no
    // scene function: it is written as log_sum_exp.
    const Scene s = parse("object { surface ln(exp(x) + exp(y)) - z bounds box((-2, -2, -2), (2, 2, 2)) }");
    const Expr f = placed_objects(s).front().object().surface;
    ASSERT_EQ(f.operand(0).op(), Op::LogSumExp);
    const Scene t = parse(write_scene(s));
    expect_same_function(f, placed_objects(t).front().object().surface);
}

TEST(SceneWriter, InfiniteConstantsReadBack) {
    const Scene s = parse("object { surface max(x^2 + y^2 + z^2 - 1, -1e308 * 10) bounds box((-2, -2, -2), (2, 2, 2)) }");
    const Scene t = parse(write_scene(s));
    expect_same_function(placed_objects(s).front().object().surface, placed_objects(t).front().object().surface);
}

TEST(SceneWriter, SmallSharedPartsAreWrittenInPlace) {
    const Scene s = parse("object { surface (x*x + 1)^2 + sin(x*x + 1) bounds box((-2, -2, -2), (2, 2, 2)) }");
    const std::string text = write_scene(s);
    EXPECT_EQ(text.find("let "), std::string::npos) << text;
}

}  // namespace
}  // namespace zeroset::test
