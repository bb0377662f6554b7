// The statements and blocks of the scene language (docs/scene-language.md).
#include "zeroset/scene/scene_parser.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "zeroset/scene/constant_value.hpp"
#include "zeroset/scene/expression_parser.hpp"
#include "zeroset/scene/file_text.hpp"
#include "zeroset/scene/wording.hpp"

namespace zeroset {

namespace {

constexpr std::array<std::string_view, 18> statement_names{
    "image", "camera", "light",        "background", "ambient",  "let",   "include", "object", "blob", "fractal",
    "sweep", "group",  "union",        "intersection", "difference", "instance", "shape", "for"};
constexpr std::array<std::string_view, 5> image_keys{"width", "height", "spp", "antialias", "reflection_depth"};
constexpr std::array<std::string_view, 6> camera_keys{"from", "at", "up", "fov", "shift_right", "shift_up"};
constexpr std::array<std::string_view, 4> light_keys{"from", "direction", "color", "shadows"};
constexpr std::array<std::string_view, 6> material_keys{"color", "ambient", "diffuse", "specular", "shininess", "reflection"};

constexpr int max_image_size = 65536;
/// Files including files, at most this deep (the reading recurses).
constexpr int max_samples_per_pixel = 1024;

bool contains(std::span<const std::string_view> names, std::string_view name) {
    return std::ranges::find(names, name) != names.end();
}


}  // namespace

SceneParser::SceneParser(const SceneLimits& limits, double clock) : limits_(limits), clock_(clock) {}
SceneParser::~SceneParser() = default;

void SceneParser::parse(std::string file_name, std::string text, const std::filesystem::path& base_dir,
                        const std::filesystem::path& source) {
    TokenStream& in = *streams_.emplace_back(std::make_unique<TokenStream>(std::move(file_name), std::move(text)));
    if (!source.empty()) {
        open_files_.push_back({source, in.file_name()});
        included_.insert(source);
    }
    TokenStream* const outer = in_;
    std::filesystem::path outer_dir = std::exchange(dir_, base_dir);
    in_ = &in;
    while (!in.at(TokenKind::End)) statement();
    in_ = outer;
    dir_ = std::move(outer_dir);
    if (!source.empty()) open_files_.pop_back();
}

void SceneParser::statement() {
    const Token& keyword = in_->peek();
    if (keyword.kind == TokenKind::Name && keyword.text == "for") {
        in_->next();
        loop(keyword, [this] {
            while (!in_->accept(TokenKind::RightBrace)) {
                if (in_->at(TokenKind::End)) in_->fail_expected("'}' to close the for loop");
                statement();
            }
        });
        return;
    }
    if (at_node_statement()) {
        node_statement([this](SceneNodePtr node) { scene_.nodes.push_back(std::move(node)); });
        return;
    }
    if (keyword.kind != TokenKind::Name || !contains(statement_names, keyword.text)) {
        std::string message = "expected a statement (" + join_words(statement_names, "or") + ") but found " +
                              describe(keyword);
        if (keyword.kind == TokenKind::Name && in_->peek(1).kind == TokenKind::Equals)
            message += "; to bind a name, write: let " + std::string(keyword.text) + " = ...";
        in_->fail(keyword.where, message);
    }
    in_->next();
    const std::string_view name = keyword.text;
    if (name == "image") {
        image(keyword);
    } else if (name == "camera") {
        camera(keyword);
    } else if (name == "light") {
        light(keyword);
    } else if (name == "background") {
        once(background_at_, keyword, "a background");
        scene_.background = color("the background color");
    } else if (name == "ambient") {
        once(ambient_at_, keyword, "an ambient light");
        scene_.ambient = color("the ambient light color");
    } else if (name == "let") {
        let();
    } else if (name == "include") {
        include(keyword);
    } else {
        shape();
    }
}

void SceneParser::image(const Token& keyword) {
    once(image_at_, keyword, "an image block");
    ImageSettings& image = scene_.image;
    block(keyword, image_keys, [&](const Token& key) {
        if (key.text == "width") {
            image.width = count("width", max_image_size);
        } else if (key.text == "height") {
            image.height = count("height", max_image_size);
        } else if (key.text == "spp") {
            image.samples_per_pixel = count("spp", max_samples_per_pixel);
        } else if (key.text == "antialias") {
            image.cone_antialiasing = cone_antialiasing_named(choice("antialiasing", antialiasing_names).text);
        } else {
            image.reflection_depth = count("reflection_depth", max_reflection_depth, 0);
        }
    });
}

void SceneParser::camera(const Token& keyword) {
    once(camera_at_, keyword, "a camera block");
    Camera& camera = scene_.camera;
    block(keyword, camera_keys, [&](const Token& key) {
        if (key.text == "from") {
            camera.from = vector("the camera position").value;
        } else if (key.text == "at") {
            camera.at = vector("the camera target").value;
        } else if (key.text == "up") {
            camera.up = vector("the camera up vector").value;
        } else if (key.text == "shift_right" || key.text == "shift_up") {
            const auto [shift, where] = number(key.text);
            if (!(std::abs(shift) <= 1e3))
                in_->fail(where, std::string(key.text) + " must be between -1000 and 1000 image heights, but it is " +
                                     format_number(shift));
            (key.text == "shift_right" ? camera.shift_right : camera.shift_up) = shift;
        } else {
            const auto [fov, where] = number("fov");
            if (!(fov > 0.0 && fov < 180.0))
                in_->fail(where, "fov must be between 0 and 180 degrees, but it is " + format_number(fov));
            camera.fov_degrees = fov;
        }
    });
    const Vec3d view = camera.at - camera.from;
    if (view == Vec3d{}) in_->fail(keyword.where, "the camera position and target must differ");
    if (length(cross(view, camera.up)) <= 1e-9 * length(view) * length(camera.up))
        in_->fail(keyword.where, "the camera up vector must be nonzero and not parallel to the view direction");
}

void SceneParser::light(const Token& keyword) {
    Light light;
    bool point = false;
    bool directional = false;
    block(keyword, light_keys, [&](const Token& key) {
        if (key.text == "from") {
            point = true;
            light.kind = Light::Kind::Point;
            light.position = vector("the light position").value;
        } else if (key.text == "direction") {
            directional = true;
            const auto [direction, where] = vector("the light direction");
            const Vec3d unit = direction / std::hypot(direction.x, direction.y, direction.z);
            if (!(std::isfinite(unit.x) && std::isfinite(unit.y) && std::isfinite(unit.z)))
                in_->fail(where, "the light direction must be a nonzero vector that can be normalised, but it is " +
                                     format_vector(direction));
            light.kind = Light::Kind::Directional;
            light.direction = unit;
        } else if (key.text == "color") {
            light.color = color("the light color");
        } else {
            light.casts_shadows = on_off("shadows");
        }
    });
    if (point && directional)
        in_->fail(keyword.where,
                  "a light has either from (a point light) or direction (a directional light), not both");
    if (!point && !directional)
        in_->fail(keyword.where, "a light needs from (a point light) or direction (a directional light)");
    scene_.lights.push_back(light);
}

void SceneParser::let() {
    const Token& name = in_->expect(TokenKind::Name);
    check_unbound(name);
    in_->expect(TokenKind::Equals);
    scope_.define(std::string(name.text), {value().value, format_location(in_->file_name(), name.where)});
}

void SceneParser::check_unbound(const Token& name) const {
    const std::string text(name.text);
    if (is_builtin_name(text)) in_->fail(name.where, "'" + text + "' is a built-in name; it cannot be bound");
    if (const Binding* earlier = scope_.find(text))
        in_->fail(name.where, "'" + text + "' is already bound (at " + earlier->defined_at +
                                  "); a name can be bound only once");
}

void SceneParser::include(const Token& keyword) {
    const Token& written = in_->expect(TokenKind::String);
    const std::filesystem::path path = resolve_path(dir_, written.text);
    const std::filesystem::path canonical = canonical_path(path);
    const auto open = std::ranges::find(open_files_, canonical, &OpenFile::canonical);
    if (open != open_files_.end()) {
        std::string chain;
        for (auto it = open; it != open_files_.end(); ++it) chain += it->name + " -> ";
        in_->fail(keyword.where, "include cycle: " + chain + path.string());
    }
    if (included_.contains(canonical)) return;  // each file is read once per scene
    if (open_files_.size() >= limits_.include_depth)
        in_->fail(keyword.where, "includes nested too deeply (more than " + std::to_string(limits_.include_depth) +
                                     " files, each including the next)");
    std::string text;
    try {
        text = read_text_file(path);
    } catch (const FileReadError& e) {
        in_->fail(keyword.where, "cannot open included file '" + path.string() + "': " + e.what());
    }
    parse(path.string(), std::move(text), path.parent_path(), canonical);
}

Material SceneParser::material(const Token& keyword) {
    Material material;
    block(keyword, material_keys, [&](const Token& key) {
        if (key.text == "color") {
            material_color(material);
        } else if (key.text == "reflection") {
            material.reflection = fraction("reflection");
        } else if (key.text == "ambient") {
            material.ambient = non_negative("ambient");
        } else if (key.text == "diffuse") {
            material.diffuse = non_negative("diffuse");
        } else if (key.text == "specular") {
            material.specular = non_negative("specular");
        } else {
            material.shininess = non_negative("shininess");
        }
    });
    return material;
}

Bounds SceneParser::bounds() {
    static constexpr std::string_view too_large_bounds =
        "the bounds are too large for double precision: the diagonal of their box overflows (keep them within about "
        "±5e307)";
    const Token& shape = in_->peek();
    const bool is_box = shape.kind == TokenKind::Name && shape.text == "box";
    const bool is_sphere = shape.kind == TokenKind::Name && shape.text == "sphere";
    if (shape.kind == TokenKind::Name && shape.text == "none") {
        in_->next();
        return Bounds::none();
    }
    if (!is_box && !is_sphere) in_->fail_expected("box(lo, hi), sphere(center, radius) or none");
    in_->next();
    in_->expect(TokenKind::LeftParen);
    if (is_box) {
        const auto [lo, where] = vector("box corner lo");
        in_->expect(TokenKind::Comma);
        const Vec3d hi = vector("box corner hi").value;
        in_->expect(TokenKind::RightParen);
        static constexpr std::array<std::string_view, 3> axes{"x", "y", "z"};
        for (int i = 0; i < 3; ++i) {
            if (!(lo[i] < hi[i])) {
                const std::string axis(axes[static_cast<std::size_t>(i)]);
                in_->fail(where, "box corner lo must be below hi in every coordinate, but lo." + axis + " = " +
                                     format_number(lo[i]) + " is not below hi." + axis + " = " +
                                     format_number(hi[i]));
            }
        }
        const Bounds box = Bounds::make_box({lo, hi});
        if (!std::isfinite(box.enclosing_box().diagonal())) in_->fail(where, std::string(too_large_bounds));
        return box;
    }
    const auto [center, at] = vector("the sphere center");
    in_->expect(TokenKind::Comma);
    const auto [radius, where] = number("the sphere radius");
    in_->expect(TokenKind::RightParen);
    if (!(radius > 0.0)) in_->fail(where, "sphere radius must be positive, but it is " + format_number(radius));
    const Bounds sphere = Bounds::make_sphere(center, radius);
    if (!std::isfinite(sphere.enclosing_box().diagonal())) in_->fail(at, std::string(too_large_bounds));
    return sphere;
}

const Token& SceneParser::choice(std::string_view what, std::span<const std::string_view> names) {
    const std::string expected = join_words(names, "or");
    if (!in_->at(TokenKind::Name)) in_->fail_expected("a " + std::string(what) + " (" + expected + ")");
    const Token& name = in_->next();
    if (std::ranges::find(names, name.text) == names.end())
        in_->fail(name.where, unknown_choice(what, name.text, names));
    return name;
}

Method SceneParser::method() {
    return *method_from_name(choice("method", names_of(all_methods(), method_name)).text);
}

Partition SceneParser::partition() {
    return *partition_from_name(choice("partition", names_of(all_partitions(), partition_name)).text);
}

PolynomialSolver SceneParser::polynomial_solver() {
    return *polynomial_solver_from_name(
        choice("polynomial solver", names_of(all_polynomial_solvers(), polynomial_solver_name)).text);
}

NormalMode SceneParser::normal_mode() {
    return *normal_mode_from_name(choice("normal mode", names_of(all_normal_modes(), normal_mode_name)).text);
}

void SceneParser::block(const Token& keyword, std::span<const std::string_view> keys,
                        const std::function<void(const Token& key)>& on_key,
                        std::span<const std::string_view> repeatable) {
    const std::string_view block_name = keyword.text;
    const auto expected_keys = [&] { return join_words(keys, "or"); };  // worded only for a message
    in_->expect(TokenKind::LeftBrace);
    std::map<std::string_view, SourceLocation> seen;
    while (!in_->accept(TokenKind::RightBrace)) {
        const Token& key = in_->peek();
        if (key.kind == TokenKind::End)
            in_->fail(key.where, "expected '}' to close the " + std::string(block_name) + " block opened at " +
                                     line_and_column(keyword.where) + ", but found end of file");
        if (key.kind != TokenKind::Name) in_->fail_expected("a key (" + expected_keys() + ") or '}'");
        if (!contains(keys, key.text))
            in_->fail(key.where, "unknown key '" + std::string(key.text) + "' in the " + std::string(block_name) +
                                     " block (expected " + expected_keys() + ")" + did_you_mean(key.text, keys));
        if (!contains(repeatable, key.text)) {
            if (const auto first = seen.find(key.text); first != seen.end())
                in_->fail(key.where, "'" + std::string(key.text) + "' is already set in this " + std::string(block_name) +
                                         " block (at " + line_and_column(first->second) + ")");
            seen.emplace(key.text, key.where);
        }
        in_->next();
        on_key(key);
    }
}

void SceneParser::once(std::optional<std::string>& first, const Token& keyword, std::string_view what) {
    if (first) in_->fail(keyword.where, "the scene already has " + std::string(what) + " (at " + *first + ")");
    first = format_location(in_->file_name(), keyword.where);
}

SceneParser::Located<Value> SceneParser::value() {
    const SourceLocation where = in_->peek().where;
    return {parse_expression(*in_, {scope_, models_, dir_, limits_.expression_nesting, clock_}), where};
}

SceneParser::Located<double> SceneParser::number(std::string_view what) {
    const auto [v, where] = value();
    return {constant_number(*in_, v, where, what), where};
}

SceneParser::Located<Vec3d> SceneParser::vector(std::string_view what) {
    const auto [v, where] = value();
    return {constant_vector(*in_, v, where, what), where};
}

double SceneParser::non_negative(std::string_view what) {
    const auto [x, where] = number(what);
    if (x < 0.0) in_->fail(where, std::string(what) + " must not be negative, but it is " + format_number(x));
    return x;
}

Vec3d SceneParser::color(std::string_view what) { return color_of(value(), what); }

Vec3d SceneParser::color_of(const Located<Value>& v, std::string_view what) {
    const Vec3d c = constant_vector(*in_, v.value, v.where, what);
    const SourceLocation where = v.where;
    if (c.x < 0.0 || c.y < 0.0 || c.z < 0.0)
        in_->fail(where, std::string(what) + " must not have negative components, but it is " + format_vector(c));
    return c;
}

double SceneParser::fraction(std::string_view what) {
    const auto [x, where] = number(what);
    if (!(x >= 0.0 && x <= 1.0))
        in_->fail(where, std::string(what) + " must be between 0 and 1, but it is " + format_number(x));
    return x;
}

void SceneParser::material_color(Material& material) {
    const Located<Value> v = value();
    if (v.value.is_vector() && !variables_of(v.value.vector()).empty())
        material.color_pattern = v.value.vector();
    else
        material.color = color_of(v, "the material color");
}

int SceneParser::count(std::string_view what, int max, int least) {
    const auto [n, where] = number(what);
    if (n < least || n != std::floor(n))
        in_->fail(where, std::string(what) +
                             (least == 1 ? " must be a positive integer" : " must be a whole number, at least " + std::to_string(least)) +
                             ", but it is " + format_number(n));
    if (n > max)
        in_->fail(where, std::string(what) + " must be at most " + std::to_string(max) + ", but it is " +
                             format_number(n));
    return static_cast<int>(n);
}

bool SceneParser::on_off(std::string_view what) {
    const Token& token = in_->peek();
    if (token.kind == TokenKind::Name && (token.text == "on" || token.text == "off")) {
        in_->next();
        return token.text == "on";
    }
    in_->fail(token.where, std::string(what) + " must be on or off, but found " + describe(token));
}

}  // namespace zeroset
