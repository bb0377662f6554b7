// The top level of a POV-Ray scene: its statements, the camera (POV-Ray's
// horizontal angle, right and up vectors turned into zeroset's vertical
// field of view), light sources, background and global settings; and the
// importer's entry points.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "zeroset/pov/pov_parser.hpp"
#include "zeroset/scene/file_text.hpp"

namespace zeroset::pov {

namespace {

constexpr double radians_per_degree = std::numbers::pi / 180.0;

}  // namespace

bool is_pov_file(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".pov";
}

std::vector<std::filesystem::path> installed_pov_include_dirs() {
    std::vector<std::filesystem::path> dirs;
    for (const char* dir : {"/usr/share/povray-3.7/include", "/usr/share/povray/include", "/usr/local/share/povray-3.7/include"}) {
        std::error_code error;
        if (std::filesystem::is_directory(dir, error)) dirs.emplace_back(dir);
    }
    return dirs;
}

PovImport read_pov_scene(const std::filesystem::path& file, const PovOptions& options) {
    std::string text;
    try {
        text = read_text_file(file);
    } catch (const FileReadError& e) {
        throw SceneError(file.string(), std::string("cannot open the scene file: ") + e.what());
    }
    return parse_pov_scene(text, file.string(), file.parent_path(), options);
}

PovImport parse_pov_scene(std::string_view text, const std::string& file_name, const std::filesystem::path& base_dir,
                          const PovOptions& options) {
    if (options.width < 1 || options.height < 1) throw SceneError(file_name, "the image size must be at least 1×1");
    return PovParser(options).run(std::string(text), file_name, base_dir);
}

PovImport PovParser::run(std::string text, const std::string& file_name, const std::filesystem::path& base_dir) {
    result_.scene.image.width = options_.width;
    result_.scene.image.height = options_.height;
    result_.scene.background = {0.0, 0.0, 0.0};  // POV-Ray's default background is black
    result_.scene.ambient = {1.0, 1.0, 1.0};
    const std::size_t file = add_file(file_name, base_dir, std::move(text));
    frames_.push_back({Frame::Kind::File, file, 0, files_[file]->tokens.size() - 1, 1, 0});
    // POV-Ray's default camera, if the scene has none.
    result_.scene.camera.from = {0.0, 0.0, 0.0};
    result_.scene.camera.at = {0.0, 0.0, 1.0};
    result_.scene.camera.fov_degrees = 2.0 * std::atan(0.5) / radians_per_degree;
    while (peek().kind != PovTokenKind::End) statement();
    if (!blocks_.empty()) fail(peek(), "a #" + std::string(blocks_.back().kind == Block::Kind::If ? "if" : "while") +
                                           " is not closed by an #end");
    if (result_.scene.lights.empty()) warn(peek(), "the scene has no light_source; zeroset lights it from the camera");
    if (!gamma_given_)
        warn(frames_.front().file == 0 ? files_[0]->tokens.front() : peek(),
             "no assumed_gamma: POV-Ray 3.7 then leaves gamma uncorrected, zeroset works in linear light as with "
             "assumed_gamma 1.0, so the image is lighter than POV-Ray's");
    return std::move(result_);
}

void PovParser::statement() {
    const PovToken& t = peek();
    if (starts_object(t)) {
        add_top_level(object_statement());
        return;
    }
    if (t.kind != PovTokenKind::Name) fail_expected("a statement (an object, camera, light_source, …)");
    const PovToken k = next();
    const std::string& w = k.text;
    if (w == "camera") camera_block(k);
    else if (w == "light_source") result_.scene.lights.push_back(light_block(k));
    else if (w == "background") background(k);
    else if (w == "global_settings") global_settings(k);
    else if (w == "sky_sphere" || w == "fog" || w == "rainbow" || w == "media" || w == "photons" || w == "radiosity") {
        skip_block(k, w, nullptr);
        warn(k, w + " is not supported; left out" + std::string(w == "sky_sphere" ? " (the background colour shows instead)" : ""));
    } else {
        fail(k, "unknown statement '" + w + "'");
    }
}

void PovParser::add_top_level(const std::shared_ptr<const PovObject>& object) {
    if (object->inverse) fail(peek(), "an inverted object on its own is not supported (only inside an intersection or difference)");
    auto node = std::make_shared<SceneNode>(*object->node);
    if (!node->material) {  // POV-Ray's default texture: black, the default finish
        PovTexture none;
        node->material = material_of(none, peek());
    }
    result_.scene.nodes.push_back(std::move(node));
}

void PovParser::camera_block(const PovToken& keyword) {
    if (camera_seen_) warn(keyword, "a second camera replaces the first");
    camera_seen_ = true;
    expect_symbol("{", "after camera");
    Vec3d location{0, 0, 0}, direction{0, 0, 1}, up{0, 1, 0}, right{1.33, 0, 0}, sky{0, 1, 0};
    std::optional<Vec3d> look_at;
    std::optional<double> angle;
    Mat4 moved = Mat4::identity();
    if (peek().kind == PovTokenKind::Name) {
        if (const PovValue* v = lookup(peek().text); v && !v->is_numeric()) fail(peek(), "declared cameras are not supported");
    }
    while (!accept_symbol("}")) {
        const PovToken t = next();
        const std::string& w = t.text;
        if (w == "location") location = vector3("the location");
        else if (w == "look_at") look_at = vector3("look_at");
        else if (w == "direction") direction = vector3("the direction");
        else if (w == "up") up = vector3("up");
        else if (w == "right") right = vector3("right");
        else if (w == "sky") sky = vector3("sky");
        else if (w == "angle") {
            angle = number("the angle");
            if (!(*angle > 0.0 && *angle < 180.0)) fail(t, "the camera's angle must be between 0 and 180 degrees");
        } else if (w == "perspective") {
        } else if (w == "orthographic" || w == "fisheye" || w == "ultra_wide_angle" || w == "omnimax" || w == "panoramic" ||
                   w == "spherical" || w == "cylinder") {
            if (w == "cylinder") (void)number("the cylinder type");
            warn(t, "the " + w + " camera is not supported; rendered as a perspective camera");
        } else if (w == "focal_point" || w == "aperture" || w == "blur_samples" || w == "confidence" || w == "variance") {
            if (w == "focal_point") (void)vector3(w);
            else (void)number(w);
            if (accept_symbol(",")) (void)number(w);
            warn(t, "focal blur (" + w + ") is not supported; left out");
        } else if (is_transform(t)) {
            moved = transform_statement(t) * moved;
        } else if (w == "normal") {
            skip_block(t, "a camera normal", nullptr);
            warn(t, "a camera normal (a perturbed view) is not supported; left out");
        } else {
            fail(t, "unknown camera keyword " + describe(t));
        }
    }
    const double right_length = length(right), up_length = length(up);
    if (!(right_length > 0.0 && up_length > 0.0 && length(direction) > 0.0))
        fail(keyword, "the camera's right, up and direction must not be 0");
    // Handedness as written, before look_at turns the vectors (POV-Ray keeps it).
    const bool right_handed = dot(cross(up, direction), right) < 0.0;
    if (angle) direction = normalize(direction) * (0.5 * right_length / std::tan(0.5 * *angle * radians_per_degree));
    if (look_at) {
        const Vec3d d = *look_at - location;
        if (!(length(d) > 0.0)) fail(keyword, "look_at is the camera's location");
        const Vec3d forward = normalize(d);
        Vec3d across = cross(sky, forward);
        if (!(length(across) > 1e-12)) {  // looking along the sky: POV-Ray keeps the right vector
            warn(keyword, "the camera looks along its sky vector; its right vector is kept as it was");
            across = right - forward * dot(right, forward);
            if (!(length(across) > 1e-12)) fail(keyword, "the camera looks along its sky and right vectors: which way is up is not defined");
        }
        right = normalize(across) * right_length;
        up = normalize(cross(forward, right)) * up_length;
        direction = forward * length(direction);
    }
    // The vectors as the camera's transforms leave them (a stretch changes
    // their lengths and angles, so everything below is measured after it).
    const Vec3d d = moved.transform_vector(direction), u = moved.transform_vector(up), r = moved.transform_vector(right);
    if (!(length(d) > 0.0 && length(u) > 0.0 && length(r) > 0.0))
        fail(keyword, "the camera's transforms flatten its right, up or direction to 0");
    // A direction that leans towards up or right, with up and right at right
    // angles, is a shifted lens: the image plane stays at right angles to
    // the part of the direction off both, and its centre moves.
    Vec3d axis = d;
    double shift_right = 0.0, shift_up = 0.0;
    const bool plane_square = std::abs(dot(normalize(u), normalize(r))) <= 1e-9;
    const double skew = std::max(std::abs(dot(normalize(u), normalize(d))), std::abs(dot(normalize(r), normalize(d))));
    if (skew > 1e-9 && plane_square) {
        axis = d - normalize(u) * dot(d, normalize(u)) - normalize(r) * dot(d, normalize(r));
        if (!(length(axis) > 1e-9 * length(d))) fail(keyword, "the camera's direction lies in its image plane");
        // In the basis the renderer builds (its right is up × axis).
        shift_right = dot(d, normalize(cross(u, axis))) / length(u);
        shift_up = dot(d, normalize(u)) / length(u);
        if (!(std::abs(shift_right) <= 1e3 && std::abs(shift_up) <= 1e3))
            fail(keyword, "the camera's direction leans more than 1000 image heights off its image plane's normal");
    } else if (!plane_square) {
        warn(keyword, "a camera whose up and right vectors are not at right angles (a skewed image plane) is not "
                      "supported; rendered with the plane at right angles to the direction");
    }
    if (right_handed)
        warn(keyword, "a right-handed camera (right = -x…) is not supported; rendered left-handed, mirrored");
    const double aspect = length(r) / length(u), image = double(options_.width) / double(options_.height);
    if (std::abs(aspect - image) > 0.01 * image)
        warn(keyword, "the camera's right/up ratio (" + std::to_string(aspect) + ") differs from the image's (" +
                          std::to_string(image) + "); zeroset draws square pixels, so the image is not stretched as POV-Ray's");
    Camera& c = result_.scene.camera;
    c.from = moved.transform_point(location);
    c.at = c.from + axis;
    c.up = u;
    c.fov_degrees = 2.0 * std::atan(0.5 * length(u) / length(axis)) / radians_per_degree;
    c.shift_right = shift_right;
    c.shift_up = shift_up;
}

Light PovParser::light_block(const PovToken& keyword) {
    expect_symbol("{", "after light_source");
    Light light;
    light.position = vector3("the light's position");
    accept_symbol(",");
    const std::array<double, 5> c = color("the light's colour");
    light.color = {c[0], c[1], c[2]};
    bool parallel = false;
    Vec3d point_at{0, 0, 0};
    Mat4 moved = Mat4::identity();
    while (!accept_symbol("}")) {
        const PovToken t = next();
        const std::string& w = t.text;
        if (w == "shadowless") {
            light.casts_shadows = false;
        } else if (w == "parallel") {
            parallel = true;
        } else if (w == "point_at") {
            point_at = vector3("point_at");
        } else if (w == "spotlight" || w == "cylinder") {
            warn(t, "a " + w + " light is not supported; rendered as a point light");
        } else if (w == "radius" || w == "falloff" || w == "tightness" || w == "fade_distance" || w == "fade_power") {
            (void)number(w);
            if (w.starts_with("fade")) warn(t, "light fading (" + w + ") is not supported; left out");
        } else if (w == "area_light") {
            (void)vector3("the area light's first axis");
            expect_symbol(",", "");
            (void)vector3("the area light's second axis");
            expect_symbol(",", "");
            (void)number("the area light's size");
            expect_symbol(",", "");
            (void)number("the area light's size");
            warn(t, "an area light is not supported; rendered as a point light (hard shadows)");
        } else if (w == "adaptive" || w == "jitter" || w == "circular" || w == "orient" || w == "media_interaction" ||
                   w == "media_attenuation") {
            if (w == "adaptive" || starts_optional_switch()) (void)number(w);
        } else if (w == "looks_like" || w == "projected_through" || w == "photons") {
            skip_block(t, "a light's " + w, nullptr);
            warn(t, "a light's " + w + " is not supported; left out");
        } else if (is_transform(t)) {
            moved = transform_statement(t) * moved;
        } else {
            fail(t, "unknown light_source keyword " + describe(t));
        }
    }
    light.position = moved.transform_point(light.position);
    if (parallel) {
        light.kind = Light::Kind::Directional;
        const Vec3d d = moved.transform_point(point_at) - light.position;
        if (!(length(d) > 0.0)) fail(keyword, "a parallel light's point_at is its position");
        light.direction = normalize(d);
    }
    return light;
}

void PovParser::background(const PovToken& keyword) {
    (void)keyword;
    expect_symbol("{", "after background");
    const std::array<double, 5> c = color("the background colour");
    expect_symbol("}", "after the background colour");
    result_.scene.background = {std::max(c[0], 0.0), std::max(c[1], 0.0), std::max(c[2], 0.0)};
}

void PovParser::global_settings(const PovToken& keyword) {
    (void)keyword;
    expect_symbol("{", "after global_settings");
    while (!accept_symbol("}")) {
        const PovToken t = next();
        const std::string& w = t.text;
        if (w == "assumed_gamma") {
            gamma_given_ = true;
            const double g = number("assumed_gamma");
            if (g != 1.0)
                warn(t, "assumed_gamma " + std::to_string(g) + " is not supported; rendered as 1.0 (zeroset works in linear light)");
        } else if (w == "ambient_light") {
            const std::array<double, 5> c = color("the ambient light");
            result_.scene.ambient = {std::max(c[0], 0.0), std::max(c[1], 0.0), std::max(c[2], 0.0)};
        } else if (w == "max_trace_level") {
            result_.scene.image.reflection_depth = std::clamp(static_cast<int>(number(w)), 0, max_reflection_depth);
        } else if (w == "adc_bailout" || w == "number_of_waves" || w == "irid_wavelength" || w == "noise_generator" ||
                   w == "hf_gray_16" || w == "mm_per_unit" || w == "max_intersections") {
            if (w == "irid_wavelength") (void)color(w);
            else if (w != "hf_gray_16" || peek().kind == PovTokenKind::Number) (void)number(w);
            note(t, w + " is not needed");
        } else if (w == "charset") {
            next();
        } else if (w == "radiosity" || w == "photons" || w == "subsurface") {
            skip_block(t, w, nullptr);
            warn(t, w + " is not supported; left out");
        } else {
            fail(t, "unknown global setting " + describe(t));
        }
    }
}

}  // namespace zeroset::pov
