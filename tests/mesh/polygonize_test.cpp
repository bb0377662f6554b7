// polygonize: closed, consistently oriented meshes of the right topology
// (Euler characteristic), vertices within the reported tolerance of the
// surface, the same mesh for any number of threads, and the shared bear.
#include "zeroset/mesh/polygonize.hpp"

#include <gtest/gtest.h>

#include <map>
#include <stdexcept>
#include <utility>

#include "support/models.hpp"
#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/shapes.hpp"
#include "zeroset/expr/substitute.hpp"
#include "zeroset/expr/vm_import.hpp"

#include <fstream>

namespace zeroset {
namespace {

const Expr x = var_x(), y = var_y(), z = var_z();
const Expr ball = square(x) + square(y) + square(z) - 1.0;
const Box3 cube{{-1.5, -1.5, -1.5}, {1.5, 1.5, 1.5}};

PolygonizeResult mesh_of(const Expr& f, const Box3& box, int resolution, int threads = 2) {
    return polygonize(Tape(f), box, {resolution, threads});
}

/// Checks the mesh is closed and consistently oriented — every edge is used
/// once in each direction — and returns V − E + F.
long euler_characteristic(const Mesh& mesh) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (const auto& t : mesh.triangles)
        for (int e = 0; e < 3; ++e) ++directed[{t[static_cast<std::size_t>(e)], t[static_cast<std::size_t>((e + 1) % 3)]}];
    long edges = 0;
    for (const auto& [edge, count] : directed) {
        EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second << " used " << count << " times one way";
        const auto back = directed.find({edge.second, edge.first});
        EXPECT_TRUE(back != directed.end() && back->second == 1) << "edge " << edge.first << "-" << edge.second << " is a border";
        ++edges;
    }
    return static_cast<long>(mesh.vertices.size()) - edges / 2 + static_cast<long>(mesh.triangles.size());
}

/// Every vertex within `tolerance` of a zero of f: f's interval over the box
/// of that half-size around it contains 0.
void expect_vertices_on_surface(const Expr& f, const Mesh& mesh, double tolerance) {
    const Tape tape(f);
    Evaluator<Interval> eval(tape);
    const Vec3d d{tolerance, tolerance, tolerance};
    int off = 0;
    for (const Vec3d& v : mesh.vertices) {
        const Interval range = evaluate_box(eval, v - d, v + d);
        off += range.lo <= 0.0 && range.hi >= 0.0 ? 0 : 1;
    }
    EXPECT_EQ(off, 0) << "of " << mesh.vertices.size() << " vertices";
}

TEST(Polygonize, ABallIsAClosedOutwardSphere) {
    const PolygonizeResult r = mesh_of(ball, cube, 32);
    ASSERT_GT(r.mesh.triangles.size(), 1000u);
    EXPECT_EQ(euler_characteristic(r.mesh), 2);
    EXPECT_GT(r.stats.vertex_tolerance, 0.0);
    EXPECT_LT(r.stats.vertex_tolerance, 1e-5 * r.stats.cell_size);
    for (const Vec3d& v : r.mesh.vertices) ASSERT_NEAR(length(v), 1.0, 2 * r.stats.vertex_tolerance + 1e-12);
    double volume = 0.0;  // positive when the triangles face outwards
    for (const auto& t : r.mesh.triangles)
        volume += dot(r.mesh.vertices[t[0]], cross(r.mesh.vertices[t[1]], r.mesh.vertices[t[2]])) / 6.0;
    EXPECT_NEAR(volume, 4.0 / 3.0 * 3.14159265358979, 0.02);
}

TEST(Polygonize, TopologyComesOutRight) {
    const Expr torus = sd_torus(coordinates(), 1.0, 0.3);
    EXPECT_EQ(euler_characteristic(mesh_of(torus, cube, 64).mesh), 0);  // genus 1
    const Expr two = min(sd_sphere({x - 0.8, y, z}, 0.5), sd_sphere({x + 0.8, y, z}, 0.5));
    EXPECT_EQ(euler_characteristic(mesh_of(two, cube, 32).mesh), 4);  // two spheres
}

TEST(Polygonize, SharpEdgesStayClosedAndNearTheSurface) {
    const Expr box = sd_box(coordinates(), {0.7, 0.5, 0.9});
    const PolygonizeResult r = mesh_of(box, cube, 32);
    EXPECT_EQ(euler_characteristic(r.mesh), 2);
    expect_vertices_on_surface(box, r.mesh, r.stats.vertex_tolerance * 1.01 + 1e-12);
}

TEST(Polygonize, TheMeshDoesNotDependOnTheThreads) {
    const Expr torus = sd_torus(coordinates(), 1.0, 0.3);
    const Mesh one = mesh_of(torus, cube, 32, 1).mesh, four = mesh_of(torus, cube, 32, 4).mesh;
    EXPECT_EQ(one.vertices, four.vertices);
    EXPECT_EQ(one.triangles, four.triangles);
}

TEST(Polygonize, ASurfaceCutByTheBoxHasABorderAndNothingOutside) {
    const PolygonizeResult r = mesh_of(ball, {{-1.5, -1.5, -1.5}, {1.5, 1.5, 0.25}}, 16);
    int borders = 0;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (const auto& t : r.mesh.triangles)
        for (int e = 0; e < 3; ++e) ++directed[{t[static_cast<std::size_t>(e)], t[static_cast<std::size_t>((e + 1) % 3)]}];
    for (const auto& [edge, count] : directed) borders += directed.count({edge.second, edge.first}) ? 0 : 1;
    EXPECT_GT(borders, 0);  // open where the box cuts it
    for (const Vec3d& v : r.mesh.vertices) EXPECT_LE(v.z, 0.25 + 1e-12);
}

TEST(Polygonize, BadSettingsAreRefused) {
    const Tape tape(ball);
    EXPECT_THROW(polygonize(tape, cube, {100, 1}), std::invalid_argument);
    EXPECT_THROW(polygonize(tape, cube, {8192, 1}), std::invalid_argument);
    EXPECT_THROW(polygonize(tape, {{0, 0, 0}, {0, 1, 1}}, {16, 1}), std::invalid_argument);
}

TEST(Polygonize, TheBearIsClosedAndOnItsSurface) {
    ZEROSET_SKIP_WITHOUT_MODEL("bear.vm");
    std::ifstream in(ZEROSET_MODELS_DIR "/bear.vm");
    const Expr bear = import_vm(in);
    const PolygonizeResult r = mesh_of(bear, {{-0.7, -0.65, -0.75}, {1.05, 0.9, 0.7}}, 64);
    EXPECT_GT(r.mesh.triangles.size(), 10000u);
    euler_characteristic(r.mesh);  // closed and oriented (its checks); the bear's genus is its own business
    expect_vertices_on_surface(bear, r.mesh, r.stats.vertex_tolerance * 1.01 + 1e-12);
}

}  // namespace
}  // namespace zeroset

namespace zeroset {
namespace {

TEST(Polygonize, ZerosOnGridPointsKeepTheMeshClosedAndOriented) {
    // ±1 at resolution 64: the grid has points at ±0.5, where these are 0.
    const Box3 unit{{-1, -1, -1}, {1, 1, 1}};
    EXPECT_EQ(euler_characteristic(mesh_of(sd_box(coordinates(), {0.5, 0.5, 0.5}), unit, 64).mesh), 2);
    EXPECT_EQ(euler_characteristic(mesh_of(square(x) + square(y) + square(z) - 0.25, unit, 64).mesh), 2);
    EXPECT_EQ(euler_characteristic(mesh_of(sd_torus(coordinates(), 0.5, 0.25), unit, 64).mesh), 0);
    const PolygonizeResult plane = mesh_of(x - 0.25, unit, 16);
    EXPECT_EQ(plane.stats.vertex_tolerance, 0.0);  // every vertex exactly on the plane
    for (const Vec3d& v : plane.mesh.vertices) EXPECT_EQ(v.x, 0.25);
}

TEST(Polygonize, AnUndefinedSurfaceIsAnErrorNotAHole) {
    EXPECT_THROW(mesh_of(sqrt(x) + square(y) + square(z) - 0.5, cube, 32), std::domain_error);
}

TEST(Polygonize, TheCoarsestResolutionsMeshToo) {
    EXPECT_GT(mesh_of(square(x) + square(y) + square(z) - 0.5, {{-1, -1, -1}, {1, 1, 1}}, 2).mesh.triangles.size(), 0u);
    EXPECT_EQ(euler_characteristic(mesh_of(ball, cube, 4).mesh), 2);
}

}  // namespace
}  // namespace zeroset
