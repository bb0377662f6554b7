// Scenes from Python: load or parse scene files, or build one — camera,
// lights, materials and objects with their bounds, method and placement —
// with the same defaults as the scene language.
#include <pybind11/stl.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>

#include "bindings.hpp"
#include "values.hpp"
#include "vec3_caster.hpp"
#include "zeroset/pov/pov_import.hpp"
#include "zeroset/scene/load_scene.hpp"
#include "zeroset/scene/wording.hpp"

namespace zeroset::python {

namespace {

/// scale, then rotate (degrees about x, then y, then z), then translate —
/// the order a placement is usually thought of in.
Mat4 placement(const std::optional<py::object>& scale, const std::optional<Vec3d>& rotate,
               const std::optional<Vec3d>& translate) {
    Mat4 m = Mat4::identity();
    if (scale) {
        const Vec3d s = py::isinstance<py::sequence>(*scale) ? scale->cast<Vec3d>()
                                                              : Vec3d{1, 1, 1} * scale->cast<double>();
        if (s.x == 0.0 || s.y == 0.0 || s.z == 0.0) throw py::value_error("a scale of 0 would flatten the object");
        m = Mat4::scale(s) * m;
    }
    if (rotate) m = Mat4::rotate_xyz_degrees(*rotate) * m;
    if (translate) m = Mat4::translate(*translate) * m;
    if (!m.is_finite() || !m.inverse()) throw py::value_error("the placement must be finite and invertible");
    return m;
}

/// `value` when lo ≤ value ≤ hi (the scene language's rules); ValueError otherwise.
double checked(double value, double lo, double hi, const char* what) {
    if (!(value >= lo && value <= hi))
        throw py::value_error(std::string(what) + " must be between " + format_number(lo) + " and " + format_number(hi) +
                              ", not " + format_number(value));
    return value;
}

/// A member of a material that must be in [lo, hi], read and written from Python.
template <double Material::*member>
void material_number(py::class_<Material>& c, const char* name, double lo, double hi) {
    c.def_property(
        name, [](const Material& m) { return m.*member; },
        [name, lo, hi](Material& m, double v) { m.*member = checked(v, lo, hi, name); });
}

/// A constant colour, or — when a component depends on x, y or z — a pattern.
void set_color(Material& material, const py::object& color) {
    const Value v = to_value(color, "the material color");
    if (!v.is_vector()) throw py::type_error("the material color must be three numbers or Exprs");
    if (variables_of(v.vector()).empty()) {
        const Vec3d c{v.vector()[0].value(), v.vector()[1].value(), v.vector()[2].value()};
        if (!(c.x >= 0.0 && c.y >= 0.0 && c.z >= 0.0 && c.x <= HUGE_VAL && c.y <= HUGE_VAL && c.z <= HUGE_VAL))
            throw py::value_error("the material color must not be negative or NaN");
        material.color = c;
        material.color_pattern.reset();
    } else {
        material.color_pattern = v.vector();
    }
}

Bounds bounds_from(const py::object& given) {
    if (given.is_none()) return default_object_bounds();
    if (py::isinstance<Bounds>(given)) return given.cast<Bounds>();
    const auto corners = given.cast<std::pair<Vec3d, Vec3d>>();  // (lo, hi)
    const Box3 box{corners.first, corners.second};
    if (!(box.lo.x < box.hi.x && box.lo.y < box.hi.y && box.lo.z < box.hi.z))
        throw py::value_error("bounds (lo, hi) need lo < hi in every coordinate");
    return Bounds::make_box(box);
}

void add_object(Scene& scene, const Expr& surface, const std::string& name, const py::object& bounds,
                const std::optional<Material>& material, const std::string& method, const std::string& normals,
                const std::optional<py::object>& scale, const std::optional<Vec3d>& rotate,
                const std::optional<Vec3d>& translate) {
    Object object;
    object.surface = surface;
    object.bounds = bounds_from(bounds);
    object.method = named(method, "method", all_methods(), method_name);
    object.normals = named(normals, "normal mode", all_normal_modes(), normal_mode_name);
    auto node = std::make_shared<SceneNode>(*make_object_node(object, name, material));
    node->transform = placement(scale, rotate, translate);
    scene.nodes.push_back(std::move(node));
}

/// A lens shift as the scene language takes it (−1000 to 1000 image heights).
double checked_shift(double shift, const char* name) {
    if (!(std::abs(shift) <= 1e3))
        throw py::value_error(std::string(name) + " must be between -1000 and 1000 image heights");
    return shift;
}

}  // namespace

void bind_scenes(py::module_& m) {
    py::class_<Camera>(m, "Camera",
                       "A pinhole camera; fov is the vertical field of view in degrees, shift_right and shift_up a "
                       "shifted lens (the image's centre moved off the view axis, in image heights).")
        .def(py::init([](Vec3d from, Vec3d at, Vec3d up, double fov, double shift_right, double shift_up) {
                 return Camera{from, at, up, fov, checked_shift(shift_right, "shift_right"), checked_shift(shift_up, "shift_up")};
             }),
             py::arg("from_") = Camera{}.from, py::arg("at") = Camera{}.at, py::arg("up") = Camera{}.up,
             py::arg("fov") = Camera{}.fov_degrees, py::arg("shift_right") = 0.0, py::arg("shift_up") = 0.0)
        .def_readwrite("from_", &Camera::from)
        .def_readwrite("at", &Camera::at)
        .def_readwrite("up", &Camera::up)
        .def_readwrite("fov", &Camera::fov_degrees)
        .def_property(
            "shift_right", [](const Camera& c) { return c.shift_right; },
            [](Camera& c, double v) { c.shift_right = checked_shift(v, "shift_right"); })
        .def_property(
            "shift_up", [](const Camera& c) { return c.shift_up; },
            [](Camera& c, double v) { c.shift_up = checked_shift(v, "shift_up"); });

    py::class_<Light>(m, "Light", "A point light (not attenuated) or a directional one.")
        .def_static(
            "point",
            [](Vec3d position, Vec3d color, bool shadows) {
                return Light{Light::Kind::Point, position, {}, color, shadows};
            },
            py::arg("position"), py::arg("color") = Vec3d{1, 1, 1}, py::arg("shadows") = true)
        .def_static(
            "directional",
            [](Vec3d direction, Vec3d color, bool shadows) {
                return Light{Light::Kind::Directional, {}, direction, color, shadows};
            },
            py::arg("direction"), py::arg("color") = Vec3d{1, 1, 1}, py::arg("shadows") = true)
        .def_property_readonly("is_point", [](const Light& l) { return l.kind == Light::Kind::Point; })
        .def_readwrite("position", &Light::position)
        .def_readwrite("direction", &Light::direction)
        .def_readwrite("color", &Light::color)
        .def_readwrite("shadows", &Light::casts_shadows);

    const Material plain;
    py::class_<Material> material_class(m, "Material",
                         "Blinn–Phong with a mirror share: color (linear RGB, or three Exprs of the object's own "
                         "coordinates for a pattern), ambient, diffuse, specular, shininess, reflection.");
    material_class.def(py::init([](const py::object& color, double ambient, double diffuse, double specular, double shininess,
                         double reflection) {
                 Material material;
                 set_color(material, color);
                 material.ambient = checked(ambient, 0.0, HUGE_VAL, "ambient");
                 material.diffuse = checked(diffuse, 0.0, HUGE_VAL, "diffuse");
                 material.specular = checked(specular, 0.0, HUGE_VAL, "specular");
                 material.shininess = checked(shininess, 0.0, HUGE_VAL, "shininess");
                 material.reflection = checked(reflection, 0.0, 1.0, "reflection");
                 return material;
             }),
             py::arg("color") = plain.color, py::arg("ambient") = plain.ambient, py::arg("diffuse") = plain.diffuse,
             py::arg("specular") = plain.specular, py::arg("shininess") = plain.shininess,
             py::arg("reflection") = plain.reflection)
        .def_property(
            "color",
            [](const Material& material) -> py::object {
                if (!material.color_pattern) return py::cast(material.color);
                const auto& p = *material.color_pattern;
                return py::make_tuple(p[0], p[1], p[2]);
            },
            &set_color);
    material_number<&Material::ambient>(material_class, "ambient", 0.0, HUGE_VAL);
    material_number<&Material::diffuse>(material_class, "diffuse", 0.0, HUGE_VAL);
    material_number<&Material::specular>(material_class, "specular", 0.0, HUGE_VAL);
    material_number<&Material::shininess>(material_class, "shininess", 0.0, HUGE_VAL);
    material_number<&Material::reflection>(material_class, "reflection", 0.0, 1.0);

    py::class_<Bounds>(m, "Bounds", "Where an object's surface lies: a box, a sphere, or none (a half-space, say).")
        .def_static("box", [](Vec3d lo, Vec3d hi) { return bounds_from(py::make_tuple(lo, hi)); }, py::arg("lo"),
                    py::arg("hi"))
        .def_static(
            "sphere",
            [](Vec3d center, double radius) {
                if (!(radius > 0.0)) throw py::value_error("a bounding sphere needs a positive radius");
                return Bounds::make_sphere(center, radius);
            },
            py::arg("center"), py::arg("radius"))
        .def_static("none", &Bounds::none);

    py::class_<Scene>(m, "Scene",
                      "What to render: camera, lights, background, image size and objects. Scene() is empty "
                      "(a render adds a headlight when it has no lights).")
        .def(py::init<>())
        .def_readwrite("camera", &Scene::camera)
        .def_readwrite("background", &Scene::background)
        .def_readwrite("ambient", &Scene::ambient)
        .def_property(
            "width", [](const Scene& s) { return s.image.width; }, [](Scene& s, int w) { s.image.width = w; })
        .def_property(
            "height", [](const Scene& s) { return s.image.height; }, [](Scene& s, int h) { s.image.height = h; })
        .def_property(
            "reflection_depth", [](const Scene& s) { return s.image.reflection_depth; },
            [](Scene& s, int n) {
                s.image.reflection_depth = static_cast<int>(checked(n, 0, max_reflection_depth, "reflection_depth"));
            })
        .def_property(
            "spp", [](const Scene& s) { return s.image.samples_per_pixel; },
            [](Scene& s, int n) { s.image.samples_per_pixel = n; })
        .def_property_readonly("lights", [](const Scene& s) { return s.lights; }, "A copy; add with add_light().")
        .def("add_light", [](Scene& s, const Light& light) { s.lights.push_back(light); }, py::arg("light"))
        .def("add_object", &add_object, py::arg("surface"), py::kw_only(), py::arg("name") = "",
             py::arg("bounds") = py::none(), py::arg("material") = py::none(), py::arg("method") = "auto",
             py::arg("normals") = "analytic", py::arg("scale") = py::none(), py::arg("rotate") = py::none(),
             py::arg("translate") = py::none(),
             "Adds an object: f within bounds (a Bounds, or (lo, hi) corners; default the box ±10), placed by "
             "scale, then rotate (degrees about x, y, z), then translate.")
        .def_property_readonly(
            "objects",
            [](const Scene& s) {
                py::list names;
                for (const PlacedObject& placed : placed_objects(s)) names.append(placed.name());
                return names;
            },
            "The names of the scene's objects, one per placement, in order.")
        .def("surface", [](const Scene& s, const std::optional<std::string>& name) {
            return surface_of(find_placed_object(s, name).object());
        }, py::arg("name") = py::none(), "The f of an object (the first when no name is given), in its own space.");

    m.def(
        "load_scene",
        [](const std::string& path, double clock, int width, int height) {
            if (!pov::is_pov_file(path)) return load_scene(path, {}, clock);
            pov::PovOptions options;
            options.clock = clock;
            options.width = width;
            options.height = height;
            return pov::read_pov_scene(path, options).scene;
        },
        py::arg("path"), py::arg("clock") = 0.0, py::arg("width") = 640, py::arg("height") = 480,
        "Reads a .zs scene file, or a POV-Ray scene (.pov, docs/povray.md: its warnings are the scene's); includes "
        "and models are found relative to it; `clock` is what the scene's clock reads (an animation's time); "
        "`width` and `height` are the image size a POV-Ray scene is read for.");
    m.def(
        "parse_scene",
        [](const std::string& text, const std::string& name, const std::string& base_dir, double clock) {
            return parse_scene(text, name, base_dir, {}, clock);
        },
        py::arg("text"), py::arg("name") = "<string>", py::arg("base_dir") = ".", py::arg("clock") = 0.0,
        "Parses scene text; errors name `name`, and includes and models are relative to base_dir.");
    m.def("default_scene", &default_scene, "The built-in default scene (the survey's Figure 1).");
}

}  // namespace zeroset::python
