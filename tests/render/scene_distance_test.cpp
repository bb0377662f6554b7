// The scene's distance bound must never claim more room than there is: at
// random points, no point of any solid lies nearer than the bound (checked
// by point membership, apart from the bound's own reasoning), and for
// spheres the bound comes close to the true distance.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "zeroset/render/render_settings.hpp"
#include "zeroset/render/scene_distance.hpp"

namespace zeroset {
namespace {

Expr ball(const Vec3d& c, double r) {
    return square(var_x() - c.x) + square(var_y() - c.y) + square(var_z() - c.z) - r * r;
}

SceneNodePtr object_node(const Expr& f, const Box3& box, const Mat4& transform = Mat4::identity()) {
    Object o;
    o.surface = f;
    o.bounds = Bounds::make_box(box);
    auto node = std::make_shared<SceneNode>(*make_object_node(o));
    node->transform = transform;
    return node;
}

SceneNodePtr combine(SceneNode::Kind kind, std::vector<SceneNodePtr> children) {
    auto node = std::make_shared<SceneNode>();
    node->kind = kind;
    node->children = std::move(children);
    return node;
}

using Membership = std::function<bool(const Vec3d&)>;

/// A random point within the ball of the given radius around p (spread
/// over the ball's volume), or p itself for a radius 0.
Vec3d point_in_ball(std::mt19937& random, const Vec3d& p, double radius) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (;;) {
        const Vec3d v{unit(random), unit(random), unit(random)};
        if (length(v) > 1e-3 && length(v) <= 1.0) return p + v * radius;
    }
}

/// Random points around the scene: at each, no point sampled in the ball of
/// the bound's radius is inside a solid. Returns how many points had a bound > 0.
int check_bound_is_clear(const Scene& scene, const Membership& inside, double reach) {
    const SceneDistance distance(scene);
    DistanceProbe probe(distance);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-4.0, 4.0);
    int positive = 0;
    for (int i = 0; i < 400; ++i) {
        const Vec3d p{coordinate(random), coordinate(random), coordinate(random)};
        const DistanceBound bound = probe.outside_at(p, reach);
        EXPECT_GE(bound.distance, 0.0);
        EXPECT_LE(bound.distance, reach + 1e-12);
        if (inside(p)) {
            EXPECT_EQ(bound.distance, 0.0) << "inside at " << p.x << ", " << p.y << ", " << p.z;
            continue;
        }
        if (bound.distance > 0.0) ++positive;
        for (int j = 0; j < 200; ++j) {
            const Vec3d q = point_in_ball(random, p, 0.999 * bound.distance);
            if (inside(q)) {
                ADD_FAILURE() << "a solid point at distance " << length(q - p) << " < bound " << bound.distance;
                return -1;
            }
        }
    }
    return positive;
}

const Box3 wide{{-3, -3, -3}, {3, 3, 3}};

bool in_ball(const Vec3d& p, const Vec3d& c, double r) { return length(p - c) < r; }

TEST(SceneDistance, SphereBoundIsClearAndNearlyTight) {
    Scene scene;
    scene.nodes.push_back(object_node(ball({0, 0, 0}, 1), wide));
    const SceneDistance distance(scene);
    DistanceProbe probe(distance);
    // Close to the surface the interval gradient is nearly |∇f| = 2|p|.
    for (const double r : {1.01, 1.1, 1.5}) {
        const double d = probe.outside_at({r, 0, 0}, 2.0 * (r - 1.0)).distance;
        EXPECT_LE(d, r - 1.0);
        EXPECT_GE(d, 0.3 * (r - 1.0)) << r;
    }
    EXPECT_GT(check_bound_is_clear(scene, [](const Vec3d& p) { return in_ball(p, {0, 0, 0}, 1); }, 1.0), 100);
}

TEST(SceneDistance, UnionIntersectionAndDifferenceBoundsAreClear) {
    const SceneNodePtr a = object_node(ball({-0.5, 0, 0}, 1), wide), b = object_node(ball({0.6, 0.2, 0}, 0.9), wide);
    const auto in_a = [](const Vec3d& p) { return in_ball(p, {-0.5, 0, 0}, 1); };
    const auto in_b = [](const Vec3d& p) { return in_ball(p, {0.6, 0.2, 0}, 0.9); };
    for (const auto kind : {SceneNode::Kind::Group, SceneNode::Kind::Intersection, SceneNode::Kind::Difference}) {
        Scene scene;
        scene.nodes.push_back(combine(kind, {a, b}));
        const Membership inside = [&](const Vec3d& p) {
            if (kind == SceneNode::Kind::Group) return in_a(p) || in_b(p);
            if (kind == SceneNode::Kind::Intersection) return in_a(p) && in_b(p);
            return in_a(p) && !in_b(p);
        };
        EXPECT_GT(check_bound_is_clear(scene, inside, 1.5), 100) << static_cast<int>(kind);
    }
}

TEST(SceneDistance, TransformsAndBoundsThatCutAreHonoured) {
    // A unit ball stretched by 2 along x and moved; and a ball cut in half by its bounds.
    const Mat4 placed = Mat4::translate({1, 0.5, 0}) * Mat4::scale({2, 0.7, 1});
    const Box3 half{{-3, -4, -3}, {0, 3, 3}};  // it cuts the ball at x = 0 only
    Scene scene;
    scene.nodes.push_back(object_node(ball({0, 0, 0}, 1), wide, placed));
    scene.nodes.push_back(object_node(ball({0, -2, 0}, 1.2), half));
    const Mat4 to_local = placed.inverse().value();
    const Membership inside = [&](const Vec3d& p) {
        const bool in_stretched = in_ball(to_local.transform_point(p), {0, 0, 0}, 1);
        const bool in_half = in_ball(p, {0, -2, 0}, 1.2) && p.x <= 0.0;
        return in_stretched || in_half;
    };
    EXPECT_GT(check_bound_is_clear(scene, inside, 2.0), 100);
}

TEST(SceneDistance, TightBoundsDoNotLengthenTheBoundOutsideThem) {
    // Outside a tight box |∇f| grows past its bound in the box: the slope
    // must be taken over the whole ball then.
    Scene scene;
    scene.nodes.push_back(object_node(ball({0, 0, 0}, 1), {{-1, -1, -1}, {1, 1, 1}}));
    const SceneDistance distance(scene);
    DistanceProbe probe(distance);
    EXPECT_LE(probe.outside_at({3, 0, 0}, 4.0).distance, 2.0);
    EXPECT_LE(probe.outside_at({5, 0, 0}, 10.0).distance, 4.0);
    EXPECT_GT(check_bound_is_clear(scene, [](const Vec3d& p) { return in_ball(p, {0, 0, 0}, 1); }, 6.0), 100);
}

TEST(SceneDistance, DepthBoundStaysInsideTheSolid) {
    // A difference, moved and stretched: no point outside it lies nearer
    // to a point inside it than the depth bound says.
    const Mat4 placed = Mat4::translate({0.3, 0, 0}) * Mat4::scale({1.5, 1, 1});
    auto cut = combine(SceneNode::Kind::Difference, {object_node(ball({0, 0, 0}, 1.5), {{-1.5, -1.5, -1.5}, {1.5, 1.5, 1.5}}),
                                                    object_node(ball({0.8, 0, 0}, 0.7), wide)});
    auto placed_cut = std::make_shared<SceneNode>(*cut);
    placed_cut->transform = placed;
    Scene scene;
    scene.nodes.push_back(placed_cut);
    const Mat4 to_local = placed.inverse().value();
    const auto inside = [&](const Vec3d& p) {
        const Vec3d q = to_local.transform_point(p);
        return in_ball(q, {0, 0, 0}, 1.5) && !in_ball(q, {0.8, 0, 0}, 0.7);
    };
    const SceneDistance distance(scene);
    DistanceProbe probe(distance);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> coordinate(-2.5, 2.5);
    int deep = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3d p{coordinate(random), coordinate(random), coordinate(random)};
        if (!inside(p)) continue;
        const double depth = probe.inside_at(p, 2.0).distance;
        if (depth > 0.0) ++deep;
        for (int j = 0; j < 200; ++j) {
            const Vec3d q = point_in_ball(random, p, 0.999 * depth);
            ASSERT_TRUE(inside(q)) << "a point outside at distance " << length(q - p) << " < depth bound " << depth;
        }
    }
    EXPECT_GT(deep, 100);
}

TEST(SceneDistance, BoxesSaidToHoldNoSolidHoldNone) {
    // Random boxes over a difference and a union, one of them moved: where
    // interval analysis says a box is empty, no sampled point of it is inside.
    const SceneNodePtr a = object_node(ball({-0.5, 0, 0}, 1), wide), b = object_node(ball({0.6, 0.2, 0}, 0.9), wide);
    auto moved = std::make_shared<SceneNode>(*object_node(ball({0, 0, 0}, 0.5), {{-1, -1, -1}, {1, 1, 1}}));
    moved->transform = Mat4::translate({0, 2.2, 0}) * Mat4::scale({2, 1, 1});
    Scene scene;
    scene.nodes.push_back(combine(SceneNode::Kind::Difference, {a, b}));
    scene.nodes.push_back(moved);
    const Mat4 to_moved = moved->transform.inverse().value();
    const auto inside = [&](const Vec3d& p) {
        return (in_ball(p, {-0.5, 0, 0}, 1) && !in_ball(p, {0.6, 0.2, 0}, 0.9)) ||
               in_ball(to_moved.transform_point(p), {0, 0, 0}, 0.5);
    };
    const SceneDistance distance(scene);
    DistanceProbe probe(distance);
    const std::vector<int> roots{0, 1};
    std::mt19937 random(5);
    std::uniform_real_distribution<double> coordinate(-3.0, 3.0), size(0.01, 0.8), unit(0.0, 1.0);
    int empty = 0, full = 0;
    for (int i = 0; i < 3000; ++i) {
        const Vec3d lo{coordinate(random), coordinate(random), coordinate(random)};
        const Box3 box{lo, lo + Vec3d{size(random), size(random), size(random)}};
        if (!probe.holds_no_solid(box, roots)) {
            ++full;
            continue;
        }
        ++empty;
        for (int j = 0; j < 100; ++j) {
            const Vec3d s = box.hi - box.lo;
            const Vec3d p = box.lo + Vec3d{unit(random) * s.x, unit(random) * s.y, unit(random) * s.z};
            ASSERT_FALSE(inside(p)) << "a solid point in a box said to hold none";
        }
    }
    EXPECT_GT(empty, 500);
    EXPECT_GT(full, 100);
}

TEST(SceneDistance, RefusesFunctionsTooLargeToBoundAtEveryStep) {
    Expr sum = Expr(0.0);
    for (int i = 0; i < 1500; ++i) sum = sum + exp(-ball({0.001 * i, 0, 0}, 1));
    Scene scene;
    scene.nodes.push_back(make_object_node([&] {
        Object o;
        o.surface = Expr(0.5) - sum;
        return o;
    }(), "big"));
    try {
        const SceneDistance distance(scene);
        FAIL() << "a function of more than 4096 operations was taken";
    } catch (const RenderError& e) {
        EXPECT_NE(std::string(e.what()).find("object 'big' has"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("--spp"), std::string::npos) << e.what();
    }
}

TEST(SceneDistance, DirectionPointsAtTheNearestSurface) {
    Scene scene;
    scene.nodes.push_back(object_node(ball({1, 0, 0}, 1), wide));
    const SceneDistance distance(scene);
    DistanceProbe probe(distance);
    const Vec3d p{1, 2.5, 0};
    const DistanceBound bound = probe.outside_at(p, 3.0);
    ASSERT_GE(bound.leaf, 0);
    const Vec3d toward = probe.toward_surface(p, bound);
    EXPECT_NEAR(toward.x, 0.0, 1e-12);
    EXPECT_NEAR(toward.y, -1.0, 1e-12);
    EXPECT_NEAR(toward.z, 0.0, 1e-12);
}

}  // namespace
}  // namespace zeroset
