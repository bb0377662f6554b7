// find_bounds_cut: bounds that cut through the solid are found, with a point
// of the boundary where f < 0; bounds that enclose the solid are not.
#include "zeroset/trace/bounds_cut.hpp"

#include <gtest/gtest.h>

#include "zeroset/expr/evaluator.hpp"

namespace zeroset {
namespace {

const Expr x = var_x(), y = var_y(), z = var_z();
const Expr ball = square(x) + square(y) + square(z) - 1.0;

double f_at(const Expr& f, const Vec3d& p) {
    const Tape tape(f);
    Evaluator<double> eval(tape);
    return eval(p.x, p.y, p.z);
}

TEST(BoundsCut, EnclosingBoundsAreFine) {
    const Tape tape(ball);
    EXPECT_FALSE(find_bounds_cut(tape, Bounds::make_box({{-1.1, -1.1, -1.1}, {1.1, 1.1, 1.1}})));
    EXPECT_FALSE(find_bounds_cut(tape, Bounds::make_sphere({0, 0, 0}, 1.05)));
    EXPECT_FALSE(find_bounds_cut(tape, Bounds::none()));
}

TEST(BoundsCut, ABoxThroughTheBallIsFoundOnItsFace) {
    const Tape tape(ball);
    const auto cut = find_bounds_cut(tape, Bounds::make_box({{-1.1, -1.1, -1.1}, {1.1, 1.1, 0.5}}));
    ASSERT_TRUE(cut);
    EXPECT_EQ(cut->where, "the face z = 0.5");
    EXPECT_EQ(cut->point.z, 0.5);
    EXPECT_LT(f_at(ball, cut->point), 0.0);
}

TEST(BoundsCut, ASmallNickIsFoundToo) {
    // The box grazes the ball's side: f < 0 only on a disc of radius 0.2 in
    // the middle of the face x = 0.98 (1/5 of the face's width).
    const Tape tape(ball);
    const auto cut = find_bounds_cut(tape, Bounds::make_box({{-1.1, -1.1, -1.1}, {0.98, 1.1, 1.1}}));
    ASSERT_TRUE(cut);
    EXPECT_EQ(cut->point.x, 0.98);
    EXPECT_LT(f_at(ball, cut->point), 0.0);
}

TEST(BoundsCut, ASphereThroughTheSolidIsFound) {
    const Expr slab = abs(y) - 0.3;  // a slab: any sphere of bounds cuts it
    const Tape tape(slab);
    const auto cut = find_bounds_cut(tape, Bounds::make_sphere({0, 0, 0}, 2));
    ASSERT_TRUE(cut);
    EXPECT_EQ(cut->where, "the bounding sphere");
    EXPECT_NEAR(length(cut->point), 2.0, 1e-8);  // a hair outside, by design
    EXPECT_LT(f_at(slab, cut->point), 0.0);
}

}  // namespace
}  // namespace zeroset

namespace zeroset {
namespace {

TEST(BoundsCut, BoundsThatOnlyTouchTheSurfaceAreFine) {
    EXPECT_FALSE(find_bounds_cut(Tape(ball), Bounds::make_sphere({0, 0, 0}, 1.0)));
    EXPECT_FALSE(find_bounds_cut(Tape(ball), Bounds::make_box({{-1, -1, -1}, {1, 1, 1}})));
}

}  // namespace
}  // namespace zeroset
