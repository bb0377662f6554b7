// The values a POV-Ray scene computes and names with #declare: numbers,
// vectors and colours (up to five components: red, green, blue, filter,
// transmit), strings, and the things a scene builds — objects, textures,
// transforms, functions — as the importer represents them.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "zeroset/math/mat4.hpp"
#include "zeroset/scene/scene.hpp"
#include "zeroset/scene/source_location.hpp"

namespace zeroset::pov {

/// A finish as written: only what was set (the rest comes from the default
/// finish, which #default may change).
struct PovFinish {
    std::optional<double> ambient, diffuse, brilliance, phong, phong_size, specular, roughness, reflection;
    /// Later settings override earlier ones, field by field.
    void merge(const PovFinish& later);
};

/// A texture as the importer keeps it: a constant colour and a finish, and
/// what it could not keep (each a located "… is not supported; rendered as
/// …" note, reported when the texture is used).
struct PovTexture {
    std::optional<std::array<double, 5>> color;  // rgb, filter, transmit
    PovFinish finish;
    std::vector<std::string> unsupported;
    void merge(const PovTexture& later);
};

/// A function { … }: its parameters and its body — read where it is
/// defined, as POV-Ray does, with its (at most three) parameters standing
/// as x, y and z, so the names it uses keep the values they had there; a
/// body that cannot be read there is read again at each call, with the
/// arguments bound, to say why. Or one of POV-Ray's internal functions
/// (functions.inc: `function { internal(n) }`), by the name it was declared as.
struct PovFunction {
    std::vector<std::string> parameters;  // x, y, z when none are written
    std::size_t file = 0;                 // the source file's index
    std::size_t begin = 0, end = 0;       // the body's tokens, [begin, end)
    std::optional<Expr> body;             // read at its definition, parameters as x, y, z
    std::optional<int> internal;
    std::string name;         // the name it was first declared as
    std::string unsupported;  // what it is, when zeroset cannot read it ("a function of a pattern")
};

/// An object read into the scene's tree, with what CSG needs to know of it.
struct PovObject {
    SceneNodePtr node;
    bool inverse = false;  // `inverse`: the solid's outside
    /// A sphere or box: its solid exactly, in the node's own space (before
    /// node->transform), for clipping another object by it.
    std::optional<Bounds> shape;
    /// Its texture lets all light through (rgbf <1, 1, 1, 1>, transmit 1):
    /// in an intersection it only clips the others.
    bool clear = false;
    /// The texture given to this node itself, if any (node->material is its
    /// material), for a texture given again to go over it.
    std::optional<PovTexture> texture;
    std::string kind;      // "sphere", "quartic", …: for messages
    SourceLocation where;
};

struct PovValue {
    /// Other: a block zeroset does not read (a color_map, a spline, …),
    /// named in `text`; an error wherever it is used.
    enum class Kind { Float, Vector, String, Object, Texture, Transform, Function, Other };
    Kind kind = Kind::Float;
    std::array<double, 5> v{};  // Float: v[0]; Vector: v[0 … size − 1]
    int size = 1;               // Vector: 2 … 5 components
    std::string text;
    std::shared_ptr<const PovObject> object;
    std::shared_ptr<const PovTexture> texture;
    Mat4 transform = Mat4::identity();
    std::shared_ptr<const PovFunction> function;
    /// The warnings and notes its declaration gave, reported where it is
    /// used (so an include file's unused declarations say nothing).
    std::vector<std::string> deferred_warnings, deferred_notes;

    static PovValue number(double x) {
        PovValue value;
        value.v[0] = x;
        return value;
    }
    static PovValue vector(const Vec3d& p) {
        PovValue value;
        value.kind = Kind::Vector;
        value.v = {p.x, p.y, p.z, 0.0, 0.0};
        value.size = 3;
        return value;
    }
    [[nodiscard]] bool is_number() const { return kind == Kind::Float; }
    [[nodiscard]] bool is_numeric() const { return kind == Kind::Float || kind == Kind::Vector; }
    [[nodiscard]] Vec3d xyz() const { return kind == Kind::Float ? Vec3d{v[0], v[0], v[0]} : Vec3d{v[0], v[1], v[2]}; }
};

/// What a kind of value is called in messages: "a number", "an object", …
std::string kind_name(PovValue::Kind kind);

}  // namespace zeroset::pov
