// An implicit leaf's gate (LeafDescription::gate, POV-Ray's bounded_by on
// its unbounded surfaces): only rays that pass through it see the object,
// and those see all of it, beyond the gate too.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

#include "zeroset/accel/csg.hpp"
#include "zeroset/accel/implicit_leaf.hpp"
#include "zeroset/accel/trace_scratch.hpp"

namespace zeroset {
namespace {

constexpr double endless = std::numeric_limits<double>::infinity();

/// The open sheet z = 3 (a polynomial of degree one) in a box of side 200,
/// gated by the unit ball about `gate` (the origin), or not gated.
std::shared_ptr<const ImplicitLeaf> sheet(bool gated, const Vec3d& gate = {0, 0, 0}, std::size_t id = 0) {
    LeafDescription d;
    d.name = "sheet";
    d.surface = var_z() - 3.0;
    d.bounds = Bounds::make_box({{-100, -100, -100}, {100, 100, 100}});
    d.open = true;
    if (gated) d.gate = Bounds::make_sphere(gate, 1.0);
    return std::make_shared<const ImplicitLeaf>(id, d);
}

std::optional<double> first_t(const ImplicitLeaf& leaf, const Ray& ray, double t_min, double t_max) {
    TraceScratch scratch(1);
    const auto hit = leaf.first_hit(ray, t_min, t_max, scratch);
    return hit ? std::optional<double>(hit->t) : std::nullopt;
}

TEST(Gate, ARayThroughTheGateSeesTheSurfaceBeyondIt) {
    const auto leaf = sheet(true);
    const auto t = first_t(*leaf, Ray{{0, 0, -5}, {0, 0, 1}}, 0.0, endless);  // through the ball, then z = 3 at t = 8
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, 8.0, 1e-9);
}

TEST(Gate, ARayThatMissesTheGateSeesNothing) {
    const Ray beside{{2, 0, -5}, {0, 0, 1}};  // meets the sheet at t = 8, two units from the ball
    EXPECT_TRUE(first_t(*sheet(false), beside, 0.0, endless));
    EXPECT_FALSE(first_t(*sheet(true), beside, 0.0, endless));
    // A ray that meets the gate only behind its start: as from a point of
    // the surface, leaving it.
    const Ray leaving{{0, 0, 2}, {0, 0, 1}};
    EXPECT_TRUE(first_t(*sheet(false), leaving, 0.0, endless));
    EXPECT_FALSE(first_t(*sheet(true), leaving, 0.0, endless));
}

TEST(Gate, TheGateCountsBeyondTheRaysEnd) {
    // A shadow ray towards a light between the sheet and the gate: it
    // ends before the gate, which POV-Ray's bounding test still counts.
    const auto t = first_t(*sheet(true), Ray{{0, 0, 5}, {0, 0, -1}}, 0.0, 2.5);
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, 2.0, 1e-9);
}

TEST(Gate, TheObjectsSizeIsTheGatesNotItsSearchBox) {
    // Shadow offsets and tolerances follow a hit's scale: the ±100 box's
    // would push a shadow ray's start past a sheet's nearby folds.
    TraceScratch gated_scratch(1), plain_scratch(1);  // one per leaf: both are leaf 0
    const auto gated = sheet(true)->first_hit(Ray{{0, 0, -5}, {0, 0, 1}}, 0.0, endless, gated_scratch);
    const auto plain = sheet(false)->first_hit(Ray{{0, 0, -5}, {0, 0, 1}}, 0.0, endless, plain_scratch);
    ASSERT_TRUE(gated && plain);
    EXPECT_NEAR(gated->surface.scale, 2.0 * std::sqrt(3.0), 1e-9);  // the unit ball's box
    EXPECT_GT(plain->surface.scale, 100.0);
}

TEST(Gate, SpansFollowTheGateToo) {
    const auto leaf = sheet(true);
    TraceScratch scratch(1);
    SpanList through, beside;
    leaf->spans(Ray{{0, 0, -5}, {0, 0, 1}}, 0.0, endless, scratch, through);
    leaf->spans(Ray{{2, 0, -5}, {0, 0, 1}}, 0.0, endless, scratch, beside);
    ASSERT_FALSE(through.empty());  // the solid z ≤ 3, from the box's face to the sheet
    EXPECT_NEAR(through.back().exit.t, 8.0, 1e-9);
    EXPECT_TRUE(beside.empty());
}

TEST(Gate, IsTestedFromTheRaysStartInCsgToo) {
    // An intersection asks its second child only from where its first
    // begins (t = 40 here); the ray crossed the child's gate before that,
    // at t ≈ 20, and POV-Ray's test is on the whole ray.
    LeafDescription box;
    box.name = "box";
    box.surface = max(max(abs(var_x()), abs(var_y())), abs(var_z())) - 10.0;
    box.bounds = Bounds::make_box({{-11, -11, -11}, {11, 11, 11}});
    const auto first = std::make_shared<const ImplicitLeaf>(0, box);
    const CsgNode both(CsgNode::Operation::Intersection, {first, sheet(true, {0, 0, -30}, 1)});
    TraceScratch scratch(2);
    SpanList inside;
    both.spans(Ray{{0, 0, -50}, {0, 0, 1}}, 0.0, endless, scratch, inside);
    ASSERT_EQ(inside.size(), 1U);  // the box's part below the sheet: z from −10 to 3
    EXPECT_NEAR(inside[0].enter.t, 40.0, 1e-6);
    EXPECT_NEAR(inside[0].exit.t, 53.0, 1e-6);
}

}  // namespace
}  // namespace zeroset
