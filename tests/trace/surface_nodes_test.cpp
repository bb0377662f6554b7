// The singular-point finder of the algebraic accuracy study
// (support/surface_nodes.hpp) on scenes whose singular points are known:
// Kummer's 16 nodes, the cone's apex, none on the sphere, and Steiner's
// double lines (not isolated: capped, every point on an axis).
#include "support/surface_nodes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace zeroset::test {
namespace {

Object algebraic_object(const std::string& name) {
    return placed_objects(load_scene(ZEROSET_SOURCE_DIR "/scenes/algebraic/" + name + ".zs")).at(0).object();
}

/// The nodes of the scene's object, each checked to be a singular point to
/// within `tolerance` (on |f| and |∇f|), distinct and inside the bounds.
std::vector<Vec3d> checked_nodes(const Object& object, double tolerance, int max_count = 64) {
    const std::vector<Vec3d> nodes = surface_nodes(object.surface, object.bounds, max_count);
    const Tape tape(object.surface);
    Evaluator<Dual<double>> gradient(tape);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const Dual<double> d = evaluate_gradient(gradient, nodes[i]);
        EXPECT_LE(std::abs(d.v), tolerance) << " node " << i;
        EXPECT_LE(length(d.g), tolerance) << " node " << i;
        EXPECT_TRUE(object.bounds.enclosing_box().contains(nodes[i]));
        for (std::size_t j = 0; j < i; ++j) EXPECT_GT(length(nodes[i] - nodes[j]), 1e-3) << i << ", " << j;
    }
    return nodes;
}

TEST(SurfaceNodes, FindsKummersSixteenNodes) {
    EXPECT_EQ(checked_nodes(algebraic_object("kummer"), 1e-10).size(), 16u);
}

TEST(SurfaceNodes, FindsTheConesApex) {
    const auto nodes = checked_nodes(algebraic_object("cone"), 1e-12);
    ASSERT_EQ(nodes.size(), 1u);
    EXPECT_LE(length(nodes[0]), 1e-12);
}

TEST(SurfaceNodes, FindsNoneOnTheSphere) { EXPECT_TRUE(checked_nodes(algebraic_object("sphere"), 0.0).empty()); }

TEST(SurfaceNodes, CapsSteinersDoubleLinesAndKeepsThemOnTheAxes) {
    const auto nodes = checked_nodes(algebraic_object("steiner"), 1e-10, 24);
    ASSERT_EQ(nodes.size(), 24u);
    for (const Vec3d& p : nodes) {
        const int off_axis = (std::abs(p.x) > 1e-6) + (std::abs(p.y) > 1e-6) + (std::abs(p.z) > 1e-6);
        EXPECT_LE(off_axis, 1) << p.x << " " << p.y << " " << p.z;
    }
}

}  // namespace
}  // namespace zeroset::test
