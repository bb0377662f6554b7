// Implicit leaves, instances, groups and CSG nodes (accel/) against the
// same shapes written as single expressions and traced as one leaf: the
// first hits, spans and normals must agree.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "support/camera_tiles.hpp"
#include "zeroset/accel/csg.hpp"
#include "zeroset/accel/group.hpp"
#include "zeroset/accel/half_space.hpp"
#include "zeroset/accel/implicit_leaf.hpp"
#include "zeroset/accel/instance.hpp"
#include "zeroset/accel/trace_scratch.hpp"

namespace zeroset {
namespace {

const Expr x = var_x(), y = var_y(), z = var_z();

Expr ball(const Vec3d& c, double r) { return square(x - c.x) + square(y - c.y) + square(z - c.z) - r * r; }
Expr cube(double h) { return max(max(abs(x), abs(y)), abs(z)) - h; }

class Leaves {
public:
    std::shared_ptr<const ImplicitLeaf> add(const Expr& f, const Box3& box, Method method = Method::Auto,
                                            MaterialId material = no_material) {
        LeafDescription d;
        d.name = "leaf " + std::to_string(count_);
        d.surface = f;
        d.bounds = Bounds::make_box(box);
        d.method = method;
        d.material = material;
        return std::make_shared<const ImplicitLeaf>(count_++, d);
    }
    [[nodiscard]] std::size_t count() const { return count_; }

private:
    std::size_t count_ = 0;
};

Box3 around(const Vec3d& c, double r) { return {c - Vec3d{r, r, r}, c + Vec3d{r, r, r}}; }

Ray random_ray(std::mt19937& random, double reach) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const Vec3d target{u(random), u(random), u(random)};
    Vec3d d{u(random), u(random), u(random)};
    d = normalize(d);
    return {target * 1.2 - d * reach, d};
}

/// The outward unit normal of a hit, in the query's space.
Vec3d normal_of(const Hit& hit, TraceScratch& scratch) {
    const SurfaceRef& s = hit.surface;
    Vec3d n = s.to_local.transpose_transform_vector(s.leaf->local_normal(s, scratch));
    if (s.flipped) n = -n;
    return normalize(n);
}

TEST(Primitives, AnInstanceTracesLikeTheTransformedExpression) {
    Leaves leaves;
    const auto unit = leaves.add(ball({0, 0, 0}, 1.0), around({0, 0, 0}, 1.01));
    // An ellipsoid: the unit ball scaled by (2, 0.5, 1), rotated and moved.
    const Mat4 m = Mat4::translate({0.3, -0.2, 0.1}) * Mat4::rotate({1, 1, 0}, 0.7) * Mat4::scale({0.8, 0.4, 0.6});
    const Instance placed(unit, m, 4);
    const Mat4 inverse = *m.inverse();
    const auto at = [&](int row) {
        return inverse.m[row][0] * x + inverse.m[row][1] * y + inverse.m[row][2] * z + inverse.m[row][3];
    };
    const Expr moved = square(at(0)) + square(at(1)) + square(at(2)) - 1.0;
    const auto reference = leaves.add(moved, around({0, 0, 0}, 1.5), Method::Interval);
    TraceScratch scratch(leaves.count());
    std::mt19937 random(11);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Ray ray = random_ray(random, 4.0);
        const auto a = placed.first_hit(ray, 0.0, INFINITY, scratch);
        const auto b = reference->first_hit(ray, 0.0, INFINITY, scratch);
        ASSERT_EQ(a.has_value(), b.has_value()) << i;
        if (!a) continue;
        ++hits;
        EXPECT_NEAR(a->t, b->t, 1e-9);
        EXPECT_EQ(a->surface.material, 4);
        EXPECT_NEAR(length(normal_of(*a, scratch) - normal_of(*b, scratch)), 0.0, 1e-6);
        // Spans: enter and leave where the expression does.
        SpanList sa, sb;
        placed.spans(ray, 0.0, INFINITY, scratch, sa);
        reference->spans(ray, 0.0, INFINITY, scratch, sb);
        ASSERT_EQ(sa.size(), sb.size());
        for (std::size_t k = 0; k < sa.size(); ++k) {
            EXPECT_NEAR(sa[k].enter.t, sb[k].enter.t, 1e-9);
            EXPECT_NEAR(sa[k].exit.t, sb[k].exit.t, 1e-9);
        }
    }
    EXPECT_GT(hits, 300);
}

TEST(Primitives, AGroupFindsTheNearestOfItsChildren) {
    Leaves leaves;
    std::vector<std::shared_ptr<const Primitive>> children;
    std::vector<std::shared_ptr<const ImplicitLeaf>> all;
    std::mt19937 random(13);
    std::uniform_real_distribution<double> u(-1.0, 1.0), r(0.02, 0.15);
    for (int i = 0; i < 200; ++i) {
        const Vec3d c{u(random), u(random), u(random)};
        const double radius = r(random);
        all.push_back(leaves.add(ball(c, radius), around(c, radius * 1.01), Method::Auto, i));
        children.push_back(all.back());
    }
    const Group group(children, 2);
    TraceScratch scratch(leaves.count());
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        const Ray ray = random_ray(random, 3.0);
        std::optional<Hit> nearest;
        for (const auto& leaf : all) {
            const auto h = leaf->first_hit(ray, 0.0, INFINITY, scratch);
            if (h && (!nearest || h->t < nearest->t)) nearest = h;
        }
        const auto found = group.first_hit(ray, 0.0, INFINITY, scratch);
        ASSERT_EQ(found.has_value(), nearest.has_value());
        EXPECT_EQ(group.occluded(ray, 0.0, INFINITY, scratch), nearest.has_value());
        if (!found) continue;
        ++hits;
        EXPECT_NEAR(found->t, nearest->t, 1e-12 * nearest->t);  // a shorter span rounds differently
        EXPECT_EQ(found->surface.material, nearest->surface.material);
        EXPECT_FALSE(group.occluded(ray, 0.0, 0.999 * nearest->t, scratch));
    }
    EXPECT_GT(hits, 500);
}

TEST(Primitives, RothCsgAgreesWithMinAndMaxOfOneExpression) {
    // (cube ∩ ball) − (three rods), as span lists of four leaves, each with
    // its own method, and as one expression traced by the interval method.
    Leaves leaves;
    const Expr rods_x = square(y) + square(z) - 0.3, rods_y = square(x) + square(z) - 0.3,
               rods_z = square(x) + square(y) - 0.3;
    const auto c = leaves.add(cube(1.0), around({0, 0, 0}, 1.1), Method::Interval);
    const auto b = leaves.add(ball({0, 0, 0}, 1.35), around({0, 0, 0}, 1.4), Method::Polynomial);
    const Box3 rod_box{{-2, -0.6, -0.6}, {2, 0.6, 0.6}};
    const auto rx = leaves.add(rods_x, rod_box, Method::Sphere);
    const auto ry = leaves.add(rods_y, {{-0.6, -2, -0.6}, {0.6, 2, 0.6}}, Method::Lg);
    const auto rz = leaves.add(rods_z, {{-0.6, -0.6, -2}, {0.6, 0.6, 2}}, Method::Polynomial);
    const auto body = std::make_shared<CsgNode>(CsgNode::Operation::Intersection,
                                                std::vector<std::shared_ptr<const Primitive>>{c, b});
    const CsgNode part(CsgNode::Operation::Difference, {body, rx, ry, rz});
    const Expr one = max(max(cube(1.0), ball({0, 0, 0}, 1.35)), -min(min(rods_x, rods_y), rods_z));
    const auto reference = leaves.add(one, around({0, 0, 0}, 1.1), Method::Interval);
    TraceScratch scratch(leaves.count());
    std::mt19937 random(17);
    int agree = 0, hits = 0;
    const int rays = 4000;
    for (int i = 0; i < rays; ++i) {
        const Ray ray = random_ray(random, 4.0);
        const auto a = part.first_hit(ray, 0.0, INFINITY, scratch);
        const auto r = reference->first_hit(ray, 0.0, INFINITY, scratch);
        if (a.has_value() != r.has_value()) continue;
        if (a && std::abs(a->t - r->t) > 1e-7) continue;
        ++agree;
        if (!a) continue;
        ++hits;
        // The normal comes from the leaf that owns the boundary.
        EXPECT_GT(dot(normal_of(*a, scratch), normal_of(*r, scratch)), 0.999) << i;
    }
    EXPECT_GE(agree, rays - 2);  // rays through an edge may differ by rounding
    EXPECT_GT(hits, 1000);
}

TEST(Primitives, SpansMarkCutFacesAndRaysStartingInside) {
    Leaves leaves;
    // A ball cut by its bounds at |x| = 0.5.
    const auto cut = leaves.add(ball({0, 0, 0}, 1.0), {{-0.5, -1.1, -1.1}, {0.5, 1.1, 1.1}});
    TraceScratch scratch(leaves.count());
    SpanList spans;
    cut->spans({{-3, 0, 0}, {1, 0, 0}}, 0.0, INFINITY, scratch, spans);
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_NEAR(spans[0].enter.t, 2.5, 1e-12);
    EXPECT_EQ(spans[0].enter.surface.kind, BoundaryKind::Bounds);
    EXPECT_EQ(spans[0].exit.surface.kind, BoundaryKind::Bounds);
    const auto face = cut->first_hit({{-3, 0, 0}, {1, 0, 0}}, 0.0, INFINITY, scratch);
    ASSERT_TRUE(face.has_value());
    EXPECT_EQ(face->surface.kind, BoundaryKind::Bounds);
    EXPECT_EQ(cut->local_normal(face->surface, scratch), (Vec3d{-1, 0, 0}));  // the cut's normal, not ∇f
    // From inside: the span opens at t_min.
    spans.clear();
    cut->spans({{0, 0, 0}, {0, 1, 0}}, 0.0, INFINITY, scratch, spans);
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_EQ(spans[0].enter.surface.kind, BoundaryKind::Open);
    EXPECT_EQ(spans[0].enter.t, 0.0);
    EXPECT_EQ(spans[0].exit.surface.kind, BoundaryKind::Surface);
    EXPECT_NEAR(spans[0].exit.t, 1.0, 1e-12);
}

TEST(Primitives, ATangentRayGivesASpanOfLengthZero) {
    Leaves leaves;
    const auto sphere = leaves.add(ball({0, 0, 0}, 1.0), around({0, 0, 0}, 1.01), Method::Polynomial);
    TraceScratch scratch(leaves.count());
    SpanList spans;
    sphere->spans({{-3, 1, 0}, {1, 0, 0}}, 0.0, INFINITY, scratch, spans);
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_NEAR(spans[0].enter.t, 3.0, 1e-6);
    EXPECT_EQ(spans[0].enter.t, spans[0].exit.t);
}

}  // namespace
}  // namespace zeroset

namespace zeroset {
namespace {

TEST(Primitives, AHalfSpaceIsTracedInClosedForm) {
    const HalfSpace floor("floor", y + 1.0, 2);  // y ≤ −1
    TraceScratch scratch(0);
    const auto hit = floor.first_hit({{0, 2, 0}, normalize(Vec3d{1, -1, 0})}, 0.0, INFINITY, scratch);
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->t, 3.0 * std::sqrt(2.0), 1e-12);
    EXPECT_EQ(hit->surface.material, 2);
    EXPECT_EQ(floor.local_normal(hit->surface, scratch), (Vec3d{0, 1, 0}));
    EXPECT_FALSE(floor.first_hit({{0, 2, 0}, {0, 1, 0}}, 0.0, INFINITY, scratch).has_value());
    EXPECT_FALSE(floor.first_hit({{0, 2, 0}, {0, -1, 0}}, 0.0, 2.5, scratch).has_value());  // beyond t_max
    SpanList spans;
    floor.spans({{0, -3, 0}, {0, 1, 0}}, 0.0, INFINITY, scratch, spans);  // from inside, leaving at y = −1
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_EQ(spans[0].enter.surface.kind, BoundaryKind::Open);
    EXPECT_NEAR(spans[0].exit.t, 2.0, 1e-15);
    EXPECT_FALSE(is_bounded(floor.bounds()));
    EXPECT_THROW(HalfSpace("curved", y * y - 1.0, no_material), std::invalid_argument);
}

TEST(Primitives, AGroupTestsItsUnboundedChildrenOnEveryRay) {
    Leaves leaves;
    const auto ball_leaf = leaves.add(ball({0, 0, 0}, 1.0), around({0, 0, 0}, 1.01));
    const Group group({ball_leaf, std::make_shared<HalfSpace>("floor", y + 1.0, no_material)});
    TraceScratch scratch(leaves.count());
    const auto on_ball = group.first_hit({{0, 0, -5}, {0, 0, 1}}, 0.0, INFINITY, scratch);
    ASSERT_TRUE(on_ball.has_value());
    EXPECT_NEAR(on_ball->t, 4.0, 1e-12);
    const auto on_floor = group.first_hit({{3, 0, -5}, {0, -1, 0}}, 0.0, INFINITY, scratch);
    ASSERT_TRUE(on_floor.has_value());
    EXPECT_NEAR(on_floor->t, 1.0, 1e-12);
}

}  // namespace
}  // namespace zeroset

namespace zeroset {
namespace {

TEST(Primitives, CsgHandlesRaysStartingInsideAndSharedFaces) {
    Leaves leaves;
    // A = the cube [−1, 1]³; B = the unit cube scaled by 0.7 and moved by 0.3
    // along x, [−0.4, 1] × [−0.7, 0.7]²: the two share the face x = 1, whose
    // roots their arithmetic places an ulp or two apart.
    const auto a = leaves.add(cube(1.0), around({0, 0, 0}, 1.1), Method::Interval, 1);
    const auto unit = leaves.add(cube(1.0), around({0, 0, 0}, 1.1), Method::Lg, 2);
    const auto b = std::make_shared<Instance>(unit, Mat4::translate({0.3, 0, 0}) * Mat4::scale({0.7, 0.7, 0.7}),
                                              no_material);
    const CsgNode slab(CsgNode::Operation::Difference, {a, b});
    TraceScratch scratch(leaves.count());
    // From +x through the shared face: the first surface is B's face at
    // x = −0.4, seen from outside B — never a sliver of A at x = 1.
    std::mt19937 random(23);
    std::uniform_real_distribution<double> u(-0.65, 0.65);
    for (int i = 0; i < 400; ++i) {
        const Ray ray{{3 + 0.01 * u(random), u(random), u(random)}, normalize(Vec3d{-1, 0.01 * u(random), 0.0})};
        const auto hit = slab.first_hit(ray, 0.0, INFINITY, scratch);
        ASSERT_TRUE(hit.has_value());
        EXPECT_NEAR(ray.at(hit->t).x, -0.4, 1e-12) << i;
        EXPECT_EQ(hit->surface.material, 2);
        EXPECT_TRUE(hit->surface.flipped);
        EXPECT_NEAR(normal_of(*hit, scratch).x, 1.0, 1e-9);  // B's −x face, flipped: pointing +x
    }
    // From inside the result: the ray starts inside (an open span at t_min).
    const auto inside = slab.first_hit({{-0.7, 0, 0}, {1, 0, 0}}, 0.0, INFINITY, scratch);
    ASSERT_TRUE(inside.has_value());
    EXPECT_EQ(inside->t, 0.0);
    EXPECT_EQ(inside->surface.kind, BoundaryKind::Open);
    SpanList spans;
    slab.spans({{-0.7, 0, 0}, {1, 0, 0}}, 0.0, INFINITY, scratch, spans);
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_NEAR(spans[0].exit.t, 0.3, 1e-12);  // leaving through B's face at x = −0.4
    // From inside B (outside the result), looking back: entering at x = −0.4.
    const auto back = slab.first_hit({{0.5, 0, 0}, {-1, 0, 0}}, 0.0, INFINITY, scratch);
    ASSERT_TRUE(back.has_value());
    EXPECT_NEAR(back->t, 0.9, 1e-12);
}

}  // namespace
}  // namespace zeroset

namespace zeroset {
namespace {

TEST(Primitives, APlaneTakesPartInCsg) {
    // A floor y ≤ 0 with a pit dug by a ball: spans that run on to t = ∞.
    Leaves leaves;
    const auto pit = leaves.add(ball({0, 0, 0}, 1.0), around({0, 0, 0}, 1.01));
    const CsgNode dug(CsgNode::Operation::Difference,
                      {std::make_shared<HalfSpace>("floor", y, 1), pit});
    TraceScratch scratch(leaves.count());
    const auto away = dug.first_hit({{3, 2, 0}, {0, -1, 0}}, 0.0, INFINITY, scratch);
    ASSERT_TRUE(away.has_value());
    EXPECT_NEAR(away->t, 2.0, 1e-12);  // the floor itself
    const auto in_pit = dug.first_hit({{0, 2, 0}, {0, -1, 0}}, 0.0, INFINITY, scratch);
    ASSERT_TRUE(in_pit.has_value());
    EXPECT_NEAR(in_pit->t, 3.0, 1e-12);  // the bottom of the pit, at y = −1
    EXPECT_TRUE(dug.occluded({{3, 2, 0}, {0, -1, 0}}, 0.0, INFINITY, scratch));
    const CsgNode wedge(CsgNode::Operation::Intersection,
                        {std::make_shared<HalfSpace>("a", y, 1), std::make_shared<HalfSpace>("b", x, 2)});
    const auto corner = wedge.first_hit({{-1, 3, 0}, {0, -1, 0}}, 0.0, INFINITY, scratch);
    ASSERT_TRUE(corner.has_value());
    EXPECT_NEAR(corner->t, 3.0, 1e-12);
}

// An instance asks its child whether a camera tile misses it with the tile
// carried into the child's space, where the child's own box is tighter
// than the instance's box around it — unless its map is far from a
// similarity (flattened across a turned axis): the tile's planes, carried
// there, would be off by more than the box test's margin, so only its own
// box is asked.
TEST(Primitives, AnInstanceAsksItsChildOfATileOnlyThroughAWellConditionedMap) {
    Leaves leaves;
    const auto cube_leaf = leaves.add(cube(1.0), around({0, 0, 0}, 1.0), Method::Interval);
    std::mt19937 random(4);
    std::uniform_real_distribution<double> u(-0.5, 0.5);
    for (const double flat : {0.5, 1e-6}) {
        SCOPED_TRACE(flat);
        const Mat4 turn = Mat4::rotate_xyz_degrees({35, 50, 20});
        const Instance placed(cube_leaf, Mat4::scale({1.0, 1.0, flat}) * turn, no_material);
        TraceScratch scratch(leaves.count());
        int child_proved = 0;
        for (int i = 0; i < 400; ++i) {
            const double u0 = u(random), v0 = u(random);  // in this order, whatever the compiler
            const CameraFrustum f = test::square_tile({0.0, 0.0, -6.0}, {0.0, 0.0, 1.0}, 4, 0.01, u0, v0);
            const bool by_box = f.misses(placed.bounds());
            const bool missed = placed.misses_tile(f, scratch);
            EXPECT_TRUE(missed || !by_box);
            if (missed && !by_box) ++child_proved;
        }
        if (flat == 0.5) {
            EXPECT_GT(child_proved, 10);  // the turned cube's corners leave room beside it
        } else {
            EXPECT_EQ(child_proved, 0);
        }
    }
}

// A leaf bounded or gated by a sphere (POV-Ray's bounded_by) passes the
// tiles whose rays all pass beside the sphere, across its box's corners
// too — and no ray of such a tile comes within the sphere.
TEST(Primitives, ALeafPassesTheTilesBesideItsSphereNotOnlyBesideItsBox) {
    std::mt19937 random(8);
    std::uniform_real_distribution<double> u(-0.2, 0.2);
    for (const bool gated : {false, true}) {
        SCOPED_TRACE(gated ? "gate" : "bounds");
        LeafDescription d;
        d.name = "ball";
        d.surface = ball({0, 0, 0}, 2.0);  // solid all through the bounds: no face of them shrinks
        d.method = Method::Interval;
        d.bounds = gated ? Bounds::make_box(around({0, 0, 0}, 1.0)) : Bounds::make_sphere({0, 0, 0}, 1.0);
        if (gated) d.gate = Bounds::make_sphere({0, 0, 0}, 1.0);
        const ImplicitLeaf leaf(0, d);
        TraceScratch scratch(1);
        int beside_box_only = 0;
        for (int i = 0; i < 400; ++i) {
            const double u0 = u(random), v0 = u(random);  // in this order, whatever the compiler
            const CameraFrustum f = test::square_tile({0.0, 0.0, -6.0}, {0.0, 0.0, 1.0}, 4, 0.005, u0, v0);
            if (!leaf.misses_tile(f, scratch)) continue;
            if (!f.misses(around({0, 0, 0}, 1.0))) ++beside_box_only;
            for (double a = 0.0; a <= 1.0; a += 0.125) {
                for (double b = 0.0; b <= 1.0; b += 0.125) {
                    // The rays through the tile's rectangle, edges included.
                    const Ray ray = test::tile_ray(f, a, b);
                    const double along = -dot(ray.origin, ray.dir) / dot(ray.dir, ray.dir);
                    EXPECT_GT(length(ray.at(along)), 1.0);
                }
            }
        }
        EXPECT_GT(beside_box_only, 20);  // tiles across the box's corners, beside the sphere
    }
}

}  // namespace
}  // namespace zeroset
