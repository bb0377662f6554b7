// polygonize, by both methods: closed, consistently oriented meshes of the
// right topology (Euler characteristic) whose vertices each have one fan of
// triangles, vertices where each method says they are, sharp corners kept
// by dual contouring, the same mesh for any number of threads, and the
// shared bear.
#include "zeroset/mesh/polygonize.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "support/models.hpp"
#include "zeroset/expr/deform.hpp"
#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/shapes.hpp"
#include "zeroset/expr/substitute.hpp"
#include "zeroset/expr/vm_import.hpp"
#include "zeroset/mesh/dual_contouring.hpp"

namespace zeroset {
namespace {

const Expr x = var_x(), y = var_y(), z = var_z();
const Expr ball = square(x) + square(y) + square(z) - 1.0;
const Box3 cube{{-1.5, -1.5, -1.5}, {1.5, 1.5, 1.5}};

using DirectedEdges = std::map<std::pair<std::uint32_t, std::uint32_t>, int>;

DirectedEdges directed_edges(const Mesh& mesh) {
    DirectedEdges directed;
    for (const auto& t : mesh.triangles)
        for (std::size_t e = 0; e < 3; ++e) ++directed[{t[e], t[(e + 1) % 3]}];
    return directed;
}

/// Checks the mesh is closed and consistently oriented — every edge is used
/// once in each direction — and that each vertex's triangles make one fan
/// (a manifold), and returns V − E + F.
long euler_characteristic(const Mesh& mesh) {
    const DirectedEdges directed = directed_edges(mesh);
    long edges = 0;
    for (const auto& [edge, count] : directed) {
        EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second << " used " << count << " times one way";
        const auto back = directed.find({edge.second, edge.first});
        EXPECT_TRUE(back != directed.end() && back->second == 1) << "edge " << edge.first << "-" << edge.second << " is a border";
        ++edges;
    }
    // Around a vertex v, each triangle (v, a, b) leads from a to b: one fan
    // is one cycle of those steps through all of them.
    std::vector<std::map<std::uint32_t, std::uint32_t>> next(mesh.vertices.size());
    for (const auto& t : mesh.triangles)
        for (std::size_t c = 0; c < 3; ++c) next[t[c]][t[(c + 1) % 3]] = t[(c + 2) % 3];
    int pinched = 0;
    for (const auto& steps : next) {
        if (steps.empty()) continue;
        std::size_t length = 0;
        std::uint32_t at = steps.begin()->first;
        do {
            const auto step = steps.find(at);
            if (step == steps.end()) break;
            at = step->second;
            ++length;
        } while (at != steps.begin()->first && length <= steps.size());
        pinched += length == steps.size() && at == steps.begin()->first ? 0 : 1;
    }
    EXPECT_EQ(pinched, 0) << "vertices whose triangles make more than one fan";
    return static_cast<long>(mesh.vertices.size()) - edges / 2 + static_cast<long>(mesh.triangles.size());
}

/// Every vertex within `tolerance` (in each coordinate) of a zero of f: f's
/// interval over the box of that half-size around it contains 0.
void expect_vertices_near_surface(const Expr& f, const Mesh& mesh, double tolerance) {
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

/// How far from a zero each method promises its vertices: on a grid edge
/// within the bracket, or — dual contouring — in a box of 1 + 2·reach cells
/// a side around a cell that holds a zero.
double promised_distance(MeshMethod method, const PolygonizeStats& s) {
    return method == MeshMethod::Tetrahedra ? s.vertex_tolerance * 1.01 + 1e-12
                                            : (1 + 2 * DualMesher::vertex_reach) * s.cell_size * 1.0001;
}

class PolygonizeBy : public testing::TestWithParam<MeshMethod> {
protected:
    PolygonizeResult mesh_of(const Expr& f, const Box3& box, int resolution, int threads = 2) const {
        return polygonize(Tape(f), box, {resolution, threads, GetParam()});
    }
};

std::string method_name(const testing::TestParamInfo<MeshMethod>& method) {
    for (const auto& [name, member] : mesh_methods)
        if (member == method.param) return std::string(name);
    return "unnamed";
}

INSTANTIATE_TEST_SUITE_P(Methods, PolygonizeBy, testing::Values(MeshMethod::Dual, MeshMethod::Tetrahedra), method_name);

TEST_P(PolygonizeBy, ABallIsAClosedOutwardSphere) {
    const PolygonizeResult r = mesh_of(ball, cube, 32);
    ASSERT_GT(r.mesh.triangles.size(), 1000u);
    EXPECT_EQ(euler_characteristic(r.mesh), 2);
    EXPECT_GT(r.stats.vertex_tolerance, 0.0);
    EXPECT_LT(r.stats.vertex_tolerance, 1e-5 * r.stats.cell_size);
    // Tetrahedra: on the sphere to the bracket. Dual: where tangent planes
    // a cell or so apart meet, off the unit sphere by about h²/3 for cells
    // of side h (measured 0.34 h² at most here).
    const double h = r.stats.cell_size;
    const double off = GetParam() == MeshMethod::Tetrahedra ? 2 * r.stats.vertex_tolerance + 1e-12 : 0.5 * h * h;
    for (const Vec3d& v : r.mesh.vertices) ASSERT_NEAR(length(v), 1.0, off);
    double volume = 0.0;  // positive when the triangles face outwards
    for (const auto& t : r.mesh.triangles)
        volume += dot(r.mesh.vertices[t[0]], cross(r.mesh.vertices[t[1]], r.mesh.vertices[t[2]])) / 6.0;
    EXPECT_NEAR(volume, 4.0 / 3.0 * 3.14159265358979, 0.02);
}

TEST_P(PolygonizeBy, TopologyComesOutRight) {
    const Expr torus = sd_torus(coordinates(), 1.0, 0.3);
    EXPECT_EQ(euler_characteristic(mesh_of(torus, cube, 64).mesh), 0);  // genus 1
    const Expr two = min(sd_sphere({x - 0.8, y, z}, 0.5), sd_sphere({x + 0.8, y, z}, 0.5));
    EXPECT_EQ(euler_characteristic(mesh_of(two, cube, 32).mesh), 4);  // two spheres
}

TEST_P(PolygonizeBy, SharpEdgesStayClosedAndNearTheSurface) {
    const Expr box = sd_box(coordinates(), {0.7, 0.5, 0.9});
    const PolygonizeResult r = mesh_of(box, cube, 32);
    EXPECT_EQ(euler_characteristic(r.mesh), 2);
    expect_vertices_near_surface(box, r.mesh, promised_distance(GetParam(), r.stats));
}

TEST_P(PolygonizeBy, TheMeshDoesNotDependOnTheThreads) {
    const Expr torus = sd_torus(coordinates(), 1.0, 0.3);
    const Mesh one = mesh_of(torus, cube, 32, 1).mesh, four = mesh_of(torus, cube, 32, 4).mesh;
    EXPECT_EQ(one.vertices, four.vertices);
    EXPECT_EQ(one.triangles, four.triangles);
}

TEST_P(PolygonizeBy, ASurfaceCutByTheBoxHasABorderAndNothingOutside) {
    const PolygonizeResult r = mesh_of(ball, {{-1.5, -1.5, -1.5}, {1.5, 1.5, 0.25}}, 16);
    const DirectedEdges directed = directed_edges(r.mesh);
    int borders = 0;
    for (const auto& [edge, count] : directed) borders += directed.count({edge.second, edge.first}) ? 0 : 1;
    EXPECT_GT(borders, 0);  // open where the box cuts it
    for (const Vec3d& v : r.mesh.vertices) EXPECT_LE(v.z, 0.25 + 1e-12);
    // An octahedron's tip just beyond the box: its dual vertex would go
    // there, but stays in the box; and every vertex is used.
    const Box3 cut{{-1.1, -1.1, -1.1}, {1.1, 1.1, 0.95}};
    const Mesh tip = mesh_of(abs(x) + abs(y) + abs(z) - 1.0, cut, 16).mesh;
    std::vector<bool> used(tip.vertices.size(), false);
    for (const auto& t : tip.triangles)
        for (const std::uint32_t v : t) used[v] = true;
    EXPECT_EQ(std::count(used.begin(), used.end(), false), 0);
    for (const Vec3d& v : tip.vertices) EXPECT_LE(v.z, 0.95);
}

TEST_P(PolygonizeBy, BadSettingsAreRefused) {
    const Tape tape(ball);
    EXPECT_THROW(polygonize(tape, cube, {100, 1, GetParam()}), std::invalid_argument);
    EXPECT_THROW(polygonize(tape, cube, {8192, 1, GetParam()}), std::invalid_argument);
    EXPECT_THROW(polygonize(tape, {{0, 0, 0}, {0, 1, 1}}, {16, 1, GetParam()}), std::invalid_argument);
}

TEST_P(PolygonizeBy, TheBearIsClosedAndNearItsSurface) {
    ZEROSET_SKIP_WITHOUT_MODEL("bear.vm");
    std::ifstream in(ZEROSET_MODELS_DIR "/bear.vm");
    const Expr bear = import_vm(in);
    const PolygonizeResult r = mesh_of(bear, {{-0.7, -0.65, -0.75}, {1.05, 0.9, 0.7}}, 64);
    EXPECT_GT(r.mesh.triangles.size(), 5000u);
    euler_characteristic(r.mesh);  // closed, oriented and manifold (its checks); the bear's genus is its own business
    expect_vertices_near_surface(bear, r.mesh, promised_distance(GetParam(), r.stats));
}

TEST_P(PolygonizeBy, ZerosOnGridPointsKeepTheMeshClosedAndOriented) {
    // ±1 at resolution 64: the grid has points at ±0.5, where these are 0.
    const Box3 unit{{-1, -1, -1}, {1, 1, 1}};
    EXPECT_EQ(euler_characteristic(mesh_of(sd_box(coordinates(), {0.5, 0.5, 0.5}), unit, 64).mesh), 2);
    EXPECT_EQ(euler_characteristic(mesh_of(square(x) + square(y) + square(z) - 0.25, unit, 64).mesh), 2);
    EXPECT_EQ(euler_characteristic(mesh_of(sd_torus(coordinates(), 0.5, 0.25), unit, 64).mesh), 0);
    const PolygonizeResult plane = mesh_of(x - 0.25, unit, 16);
    EXPECT_EQ(plane.stats.vertex_tolerance, 0.0);  // every crossing exactly on the plane, so every vertex too
    for (const Vec3d& v : plane.mesh.vertices) EXPECT_EQ(v.x, 0.25);
}

TEST_P(PolygonizeBy, AnUndefinedSurfaceIsAnErrorNotAHole) {
    EXPECT_THROW(mesh_of(sqrt(x) + square(y) + square(z) - 0.5, cube, 32), std::domain_error);
}

TEST(Polygonize, NaNBeyondAPrunedBranchIsAnErrorForDualContouring) {
    // The min's second branch is NaN on the plane x = −1/16 (a grid plane
    // at 32 cells over ±1) and always loses where it is defined: a block's
    // pruned tape drops it, but the full tape, which dual contouring
    // evaluates just beyond a block, says NaN.
    const double k = 40.0;
    const Expr gyroid = sin(x * k) * cos(y * k) + sin(y * k) * cos(z * k) + sin(z * k) * cos(x * k);
    const Expr shape = max(gyroid, sd_sphere(coordinates(), 0.9));
    const Expr f = min(shape, sqrt((x + 0.1) * (x + 0.05)) + 100.0);
    EXPECT_THROW(polygonize(Tape(f), {{-1, -1, -1}, {1, 1, 1}}, {32, 2, MeshMethod::Dual}), std::domain_error);
}

TEST_P(PolygonizeBy, TheCoarsestResolutionsMeshToo) {
    // Two cells a side, only the centre inside: an octahedron's worth of surface, closed.
    EXPECT_EQ(euler_characteristic(mesh_of(square(x) + square(y) + square(z) - 0.5, {{-1, -1, -1}, {1, 1, 1}}, 2).mesh), 2);
    EXPECT_EQ(euler_characteristic(mesh_of(ball, cube, 4).mesh), 2);
}

/// The distance from `point` to the nearest vertex.
double nearest_vertex(const Mesh& mesh, const Vec3d& point) {
    double best = 1e300;
    for (const Vec3d& v : mesh.vertices) best = std::min(best, length(v - point));
    return best;
}

TEST(DualContouring, KeepsTheCornersAndEdgesOfABox) {
    // A box turned so that no face lies along the grid: each corner is a
    // vertex, and every vertex lies on a face (to rounding), where the
    // tetrahedra's cut corners miss by a good part of a cell.
    const Vec3d half{0.7, 0.5, 0.9};
    const Vec3d turn{30, 20, 10};
    const Expr box = rotate_degrees(sd_box(coordinates(), half), turn);
    const Mat4 to_scene = Mat4::rotate_xyz_degrees(turn);
    for (const MeshMethod method : {MeshMethod::Dual, MeshMethod::Tetrahedra}) {
        const PolygonizeResult r = polygonize(Tape(box), cube, {32, 2, method});
        double worst_corner = 0.0;
        for (int c = 0; c < 8; ++c) {
            const Vec3d corner{c & 1 ? half.x : -half.x, c & 2 ? half.y : -half.y, c & 4 ? half.z : -half.z};
            worst_corner = std::max(worst_corner, nearest_vertex(r.mesh, to_scene.transform_point(corner)));
        }
        if (method == MeshMethod::Dual) {
            EXPECT_LT(worst_corner, 1e-9);
            const Tape tape(box);
            Evaluator<double> f(tape);
            for (const Vec3d& v : r.mesh.vertices) ASSERT_NEAR(f(v.x, v.y, v.z), 0.0, 1e-9);  // an exact distance
            // No triangle cuts across a crease: each lies in a face, so its
            // centroid too is on the surface.
            for (const auto& t : r.mesh.triangles) {
                const Vec3d c = (r.mesh.vertices[t[0]] + r.mesh.vertices[t[1]] + r.mesh.vertices[t[2]]) / 3.0;
                ASSERT_NEAR(f(c.x, c.y, c.z), 0.0, 1e-9);
            }
        } else {
            EXPECT_GT(worst_corner, 0.1 * r.stats.cell_size);
        }
    }
}

}  // namespace
}  // namespace zeroset

namespace zeroset {
namespace {

TEST_P(PolygonizeBy, DetailAboutACellThickStaysManifold) {
    // A gyroid of period 0.16 inside a ball, at cells of 1/16: surface that
    // wraps round cell faces everywhere, the case where dual contouring
    // flips faces; both methods must still close up with one fan a vertex.
    const double k = 40.0;
    const Expr gyroid = sin(x * k) * cos(y * k) + sin(y * k) * cos(z * k) + sin(z * k) * cos(x * k);
    const PolygonizeResult r = mesh_of(max(gyroid, sd_sphere(coordinates(), 0.9)), {{-1, -1, -1}, {1, 1, 1}}, 32);
    EXPECT_GT(r.mesh.triangles.size(), 10000u);
    euler_characteristic(r.mesh);
}

}  // namespace
}  // namespace zeroset

namespace zeroset {
namespace {

TEST_P(PolygonizeBy, ATinySurfaceIsClosedAndOrientedToo) {
    // A ball of radius 10⁻¹⁵⁰: products of its coordinates underflow, so no
    // triangle may take its winding from a cross product.
    const double r = 1e-150;
    const PolygonizeResult t = mesh_of(square(x) + square(y) + square(z) - r * r, {{-2 * r, -2 * r, -2 * r}, {2 * r, 2 * r, 2 * r}}, 16);
    EXPECT_EQ(euler_characteristic(t.mesh), 2);
}

}  // namespace
}  // namespace zeroset
