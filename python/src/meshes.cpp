// mesh() from Python: the surface of an Expr (within a box) or of a scene's
// object (within its bounds, placed as the scene places it) as numpy arrays
// of vertices and triangles — docs/meshes.md tells how and what is certain.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <utility>

#include "bindings.hpp"
#include "values.hpp"
#include "vec3_caster.hpp"
#include "zeroset/mesh/polygonize.hpp"
#include "zeroset/scene/scene.hpp"

namespace zeroset::python {

namespace {

py::tuple mesh_arrays(const Mesh& mesh) {
    py::array_t<double> vertices({static_cast<py::ssize_t>(mesh.vertices.size()), py::ssize_t{3}});
    py::array_t<std::uint32_t> triangles({static_cast<py::ssize_t>(mesh.triangles.size()), py::ssize_t{3}});
    auto v = vertices.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < v.shape(0); ++i)
        for (int c = 0; c < 3; ++c) v(i, c) = mesh.vertices[static_cast<std::size_t>(i)][c];
    auto t = triangles.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < t.shape(0); ++i)
        for (int c = 0; c < 3; ++c) t(i, c) = mesh.triangles[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)];
    return py::make_tuple(vertices, triangles);
}

Mesh polygonized(const Expr& f, const Box3& box, const PolygonizeSettings& settings) {
    const py::gil_scoped_release unlocked;
    try {
        return polygonize(Tape(f), box, settings).mesh;
    } catch (const std::invalid_argument& e) {
        throw py::value_error(e.what());  // raised once the GIL is back
    }
}

}  // namespace

void bind_meshes(py::module_& m) {
    m.def(
        "mesh",
        [](const py::object& what, int resolution, std::optional<std::pair<Vec3d, Vec3d>> box,
           const std::optional<std::string>& object, int threads, const std::string& method) {
            const PolygonizeSettings settings{resolution, threads,
                                              named(method, "mesh method", std::span<const NamedMeshMethod>(mesh_methods),
                                                    [](const NamedMeshMethod& n) { return n.first; }).second};
            if (py::isinstance<Scene>(what)) {
                if (box) throw py::value_error("a scene's object is meshed within its bounds: give no box");
                const PlacedObject placed = find_placed_object(what.cast<const Scene&>(), object);
                if (placed.object().bounds.kind == Bounds::Kind::None)
                    throw py::value_error("the object has no bounds (a plane, say): a mesh needs a finite region");
                Mesh mesh = polygonized(surface_of(placed.object()), placed.object().bounds.enclosing_box(), settings);
                transform_mesh(mesh, placed.to_scene);
                return mesh_arrays(mesh);
            }
            if (object) throw py::value_error("object= names an object of a scene, not of an Expr");
            const auto corners = box.value_or(std::pair{Vec3d{-1, -1, -1}, Vec3d{1, 1, 1}});
            return mesh_arrays(polygonized(what.cast<Expr>(), {corners.first, corners.second}, settings));
        },
        py::arg("surface"), py::arg("resolution") = 128, py::arg("box") = py::none(), py::arg("object") = py::none(),
        py::arg("threads") = 0, py::arg("method") = "dual",
        "A triangle mesh of f = 0: (vertices float64 (n, 3), triangles uint32 (m, 3)), counter-clockwise seen from "
        "outside. `surface` is an Expr (meshed within box=(lo, hi), default the cube ±1) or a Scene (its object, "
        "within its bounds, in scene coordinates). resolution: cells a side, a power of two; method: 'dual' (dual contouring, keeps sharp edges) or 'tetrahedra' (vertices on the surface) — docs/meshes.md.");
}

}  // namespace zeroset::python
