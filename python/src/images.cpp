// Rendering, slicing and probing from Python. Images come back as numpy
// arrays — linear RGB float32 of shape (height, width, 3), row 0 at the top
// — and the GIL is released while the library works, so other Python
// threads run meanwhile.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstring>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "values.hpp"
#include "vec3_caster.hpp"
#include "zeroset/io/image_writer.hpp"
#include "zeroset/render/ray_probe.hpp"
#include "zeroset/render/ray_report.hpp"
#include "zeroset/render/renderer.hpp"
#include "zeroset/render/slice.hpp"
#include "zeroset/scene/default_scene.hpp"

namespace zeroset::python {

namespace {

static_assert(sizeof(Vec3f) == 3 * sizeof(float), "Vec3f must be three packed floats to copy it as an array");

/// Three floats a pixel from a C-contiguous array.
void copy_triples(const float* from, std::span<Vec3f> to) {
    for (Vec3f& v : to) {
        v = {from[0], from[1], from[2]};
        from += 3;
    }
}

py::array_t<float> rgb_array(std::span<const Vec3f> pixels, int width, int height) {
    py::array_t<float> out({height, width, 3});
    std::memcpy(out.mutable_data(), pixels.data(), pixels.size() * sizeof(Vec3f));
    return out;
}

py::array_t<float> plane_array(std::span<const float> values, int width, int height) {
    py::array_t<float> out({height, width});
    std::memcpy(out.mutable_data(), values.data(), values.size() * sizeof(float));
    return out;
}

py::object render_scene(const Scene& scene, std::optional<int> width, std::optional<int> height,
                        std::optional<int> spp, int threads, const std::optional<std::string>& method, bool layers,
                        const std::optional<std::string>& antialias) {
    RenderSettings settings;
    settings.width = width.value_or(scene.image.width);
    settings.height = height.value_or(scene.image.height);
    settings.samples_per_pixel = spp.value_or(scene.image.samples_per_pixel);
    settings.threads = threads;
    settings.layers = layers;
    settings.cone_antialiasing = scene.image.cone_antialiasing;
    if (antialias) settings.cone_antialiasing = cone_antialiasing_named(*antialias);
    if (method) settings.method = named(*method, "method", all_methods(), method_name);
    // A copy (shallow: the nodes are shared and immutable), since another
    // Python thread may change the scene while this one renders.
    const Scene copy = scene;
    RenderResult result;
    {
        const py::gil_scoped_release unlocked;
        result = render(copy, settings);
    }
    for (const std::string& warning : result.stats.warnings)
        if (PyErr_WarnEx(PyExc_UserWarning, warning.c_str(), 1) != 0) throw py::error_already_set();
    const Image& image = result.image;
    py::array_t<float> rgb = rgb_array(image.pixels, image.width, image.height);
    if (!layers) return rgb;
    return py::make_tuple(rgb, plane_array(image.depth, image.width, image.height),
                          rgb_array(image.normals, image.width, image.height));
}

int axis_from(const std::string& name) {
    if (name == "x") return 0;
    if (name == "y") return 1;
    if (name == "z") return 2;
    throw py::value_error("unknown axis '" + name + "' (give 'x', 'y' or 'z')");
}

py::array_t<float> slice_expression(const Expr& f, int size, const std::string& axis, double at,
                                    std::pair<double, double> region, bool values, int threads) {
    SliceSettings settings;
    settings.plane = {axis_from(axis), at, region.first, region.second};
    settings.size = size;
    settings.every_pixel = values;
    settings.threads = threads;
    SliceField field;
    {
        const py::gil_scoped_release unlocked;
        const Tape tape(f);
        field = slice(tape, settings);
    }
    return plane_array(field.values, field.size, field.size);
}

py::object probe(const std::optional<Scene>& given, std::optional<Vec3d> origin, std::optional<Vec3d> dir,
                 const std::optional<std::string>& object, const std::string& method,
                 std::optional<double> newton_from) {
    if (given && (!origin || !dir)) throw py::value_error("with a scene, give the ray's origin and dir");
    const Scene scene = given ? *given : default_scene();
    const Ray ray{origin.value_or(survey_origin), dir.value_or(survey_dir)};
    if (ray.dir == Vec3d{}) throw py::value_error("dir must not be zero");
    std::vector<Method> methods;
    if (method == "all") {
        methods.assign(all_methods().begin(), all_methods().end());
    } else {
        methods.push_back(named(method, "method", all_methods(), method_name));
    }
    const PlacedObject placed = find_placed_object(scene, object);
    std::string json;
    {
        const py::gil_scoped_release unlocked;
        const ObjectProbe probe_object(placed, newton_from);
        json = ray_report_json({given ? "<python>" : "<default>", placed.name(), newton_from},
                               probe_object.probe(ray, methods));
    }
    return py::module_::import("json").attr("loads")(json);
}

/// An Image from arrays: rgb (H, W, 3), and depth (H, W) with normals
/// (H, W, 3) together or not at all.
Image image_from(const py::array_t<float, py::array::c_style | py::array::forcecast>& rgb,
                 const std::optional<py::array_t<float, py::array::c_style | py::array::forcecast>>& depth,
                 const std::optional<py::array_t<float, py::array::c_style | py::array::forcecast>>& normals) {
    if (rgb.ndim() != 3 || rgb.shape(2) != 3 || rgb.shape(0) == 0 || rgb.shape(1) == 0)
        throw py::value_error("rgb must have the shape (height, width, 3), both sides at least 1");
    const auto height = static_cast<int>(rgb.shape(0)), width = static_cast<int>(rgb.shape(1));
    Image image(width, height);
    copy_triples(rgb.data(), image.pixels);
    if (depth.has_value() != normals.has_value()) throw py::value_error("give depth and normals together");
    if (!depth) return image;
    if (depth->ndim() != 2 || depth->shape(0) != height || depth->shape(1) != width)
        throw py::value_error("depth must have the shape (height, width) of rgb");
    if (normals->ndim() != 3 || normals->shape(0) != height || normals->shape(1) != width || normals->shape(2) != 3)
        throw py::value_error("normals must have the shape (height, width, 3) of rgb");
    image.add_layers();
    std::memcpy(image.depth.data(), depth->data(), image.depth.size() * sizeof(float));
    copy_triples(normals->data(), image.normals);
    return image;
}

}  // namespace

void bind_images(py::module_& m) {
    m.def("render", &render_scene, py::arg("scene"), py::arg("width") = py::none(), py::arg("height") = py::none(),
          py::arg("spp") = py::none(), py::arg("threads") = 0, py::arg("method") = py::none(),
          py::arg("layers") = false, py::arg("antialias") = py::none(),
          "Renders the scene: linear RGB float32, shape (height, width, 3). Size, samples and antialias "
          "('samples' or 'cone', docs/antialiasing.md) default to the scene's; threads=0 uses every core; method "
          "overrides every object's. With layers=True, returns "
          "(rgb, depth, normals): depth (height, width) is the distance to the nearest hit along the pixel's ray "
          "(inf where none), normals (height, width, 3) the unit normal there (0 where none).");
    m.def("slice", &slice_expression, py::arg("f"), py::arg("size") = 512, py::arg("axis") = "z",
          py::arg("at") = 0.0, py::arg("region") = std::pair{-1.0, 1.0}, py::arg("values") = true,
          py::arg("threads") = 0,
          "f on the square region×region of the plane normal to axis at `at`: float32 (size, size), row 0 at the "
          "top (docs/slicing.md). With values=False, tiles whose sign intervals decide hold a bound nearest 0.");
    m.def("ray", &probe, py::arg("scene") = py::none(), py::arg("origin") = py::none(), py::arg("dir") = py::none(),
          py::arg("object") = py::none(), py::arg("method") = "all", py::arg("newton_from") = py::none(),
          "Every intersection method on one ray: the data of `zeroset ray --json` (docs/ray-command.md) as a "
          "dict. Without a scene, the default scene and the survey's ray.");
    m.def(
        "write_image",
        [](const std::string& path, const py::array_t<float, py::array::c_style | py::array::forcecast>& rgb,
           const std::optional<py::array_t<float, py::array::c_style | py::array::forcecast>>& depth,
           const std::optional<py::array_t<float, py::array::c_style | py::array::forcecast>>& normals) {
            write_image(image_from(rgb, depth, normals), path);
        },
        py::arg("path"), py::arg("rgb"), py::arg("depth") = py::none(), py::arg("normals") = py::none(),
        "Writes linear RGB (and, for .exr, depth and normals) by the file's extension: .png, .ppm, .pfm, .exr.");
}

}  // namespace zeroset::python
