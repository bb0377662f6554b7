// SceneParser: the statement half of the scene language — image, camera,
// light, background, ambient, let, include, the objects and the structure
// above them (groups, CSG, transforms, shapes and their instances, loops) —
// filling a Scene as it reads. One parser reads a whole scene, following
// includes; expressions are read by expression_parser.hpp. The statements
// are split over scene_parser.cpp (settings and files), scene_nodes.cpp
// (objects and the tree), blob_statement.cpp (blobs), fractal_statement.cpp (fractals) and transforms.cpp
// (affine maps).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "zeroset/scene/model_library.hpp"
#include "zeroset/scene/scene.hpp"
#include "zeroset/scene/scene_limits.hpp"
#include "zeroset/scene/scope.hpp"
#include "zeroset/scene/token_stream.hpp"

namespace zeroset {

/// The keys that apply an affine map, in every block that takes transforms.
inline constexpr std::array<std::string_view, 5> transform_keys{"translate", "rotate", "scale", "shear", "matrix"};

/// True when the token is a name among `names`.
inline bool is_one_of(std::span<const std::string_view> names, const Token& token) {
    return token.kind == TokenKind::Name && std::ranges::find(names, token.text) != names.end();
}

/// `shape NAME(PARAMETERS) { … }`: a body to read once per distinct list of
/// arguments, each reading placed by `instance` as often as wanted.
struct ShapeDefinition {
    std::string name;
    std::vector<std::string> parameters;
    TokenStream* stream;  // the file it is written in …
    std::size_t body;     // … at its '{'
    std::size_t visible;  // the Scope mark where it is defined
    std::filesystem::path dir;  // the directory of its file (paths in it start there)
    /// Each reading, by its arguments: a constant by its bits, any other
    /// number by the id of its expression node (the arguments are kept with
    /// the reading, so that no id is ever reused).
    struct Reading {
        std::vector<Value> arguments;
        SceneNodePtr node;
    };
    std::map<std::vector<std::uint64_t>, Reading> read;
};

class SceneParser {
public:
    /// `clock` is the value the scene's `clock` reads (an animation's time).
    explicit SceneParser(const SceneLimits& limits = {}, double clock = 0.0);
    ~SceneParser();
    SceneParser(const SceneParser&) = delete;
    SceneParser& operator=(const SceneParser&) = delete;

    /// Parses scene text into scene(); throws SceneError. `base_dir` is where
    /// the text's relative paths start; `source`, the canonical path of the
    /// file the text came from (if it did), lets includes of it be caught.
    void parse(std::string file_name, std::string text, const std::filesystem::path& base_dir,
               const std::filesystem::path& source = {});

    [[nodiscard]] Scene take_scene() { return std::move(scene_); }

private:
    template <class T>
    struct Located {
        T value;
        SourceLocation where;
    };
    /// Where a block's nodes go: the scene's top level or a parent's children.
    using NodeSink = std::function<void(SceneNodePtr)>;

    // scene_parser.cpp: settings, let, include, and the readers of values.
    void statement();
    void image(const Token& keyword);
    void camera(const Token& keyword);
    void light(const Token& keyword);
    void let();
    void include(const Token& keyword);
    Material material(const Token& keyword);
    Bounds bounds();
    /// A name from `names` (the error lists them); `what` names the choice in messages.
    const Token& choice(std::string_view what, std::span<const std::string_view> names);
    Method method();
    PolynomialSolver polynomial_solver();
    Partition partition();
    NormalMode normal_mode();
    /// Reads `{ key value … }`: keys from `keys`, each at most once unless it
    /// is `repeatable`, in any order; `on_key` reads the value of the key
    /// just consumed.
    void block(const Token& keyword, std::span<const std::string_view> keys,
               const std::function<void(const Token& key)>& on_key,
               std::span<const std::string_view> repeatable = {});
    /// Records the first `keyword` statement of its kind; fails on a second.
    void once(std::optional<std::string>& first, const Token& keyword, std::string_view what);
    /// Fails unless `name` may be bound here (not built in, not bound yet).
    void check_unbound(const Token& name) const;
    Located<Value> value();
    Located<double> number(std::string_view what);
    Located<Vec3d> vector(std::string_view what);
    double non_negative(std::string_view what);
    Vec3d color(std::string_view what);
    Vec3d color_of(const Located<Value>& v, std::string_view what);
    /// A number in [0, 1].
    double fraction(std::string_view what);
    /// A material's `color`: a constant vector, or one of expressions in x, y, z (a pattern).
    void material_color(Material& material);
    /// A whole number in [least, max].
    int count(std::string_view what, int max, int least = 1);
    bool on_off(std::string_view what);

    // scene_nodes.cpp: the tree.
    /// True when the current token starts a node statement (object, group,
    /// union, intersection, difference, instance) or a loop of them.
    [[nodiscard]] bool at_node_statement() const;
    /// Reads one node statement (or a loop of them) into `sink`.
    void node_statement(const NodeSink& sink);
    SceneNodePtr object(const Token& keyword);
    /// A new object node for the statement `keyword` (counted against the
    /// object limit), with the name that follows it if one does.
    std::shared_ptr<SceneNode> object_node(const Token& keyword);
    /// The entries every object body with items shares — `let`, `for` (its
    /// body read with `entry`) and transforms of `node`; false at none.
    bool body_entry(SceneNode& node, std::string_view items, const std::function<bool()>& entry);
    /// Records a key that may be set once; fails on the second, naming the first.
    void set_once(std::map<std::string_view, SourceLocation>& seen, const Token& key, std::string_view block);
    SceneNodePtr composite(const Token& keyword, SceneNode::Kind kind);

    // blob_statement.cpp: blobs.
    struct BlobReading;
    SceneNodePtr blob(const Token& keyword);
    SceneNodePtr fractal(const Token& keyword);
    // sweep_statement.cpp: swept spheres.
    struct SweepReading;
    SceneNodePtr sweep(const Token& keyword);
    /// Reads one entry of a sweep's body into `reading`; false at none.
    bool sweep_entry(SweepReading& reading);
    /// Reads one entry of a blob's body into `reading`; false at none.
    bool blob_entry(BlobReading& reading);
    BlobComponent blob_component(const Token& keyword, BlobKernel kernel);
    SceneNodePtr instance(const Token& keyword);
    void shape();
    /// Skips a `{ … }` unread (up to its matching '}').
    void skip_block(std::string_view what);
    /// Reads a child node, a loop of them or a let into `node`; false when
    /// the current token starts none of these.
    bool child_entry(SceneNode& node);
    /// `for NAME from A to B [step S] { … }`; each iteration reads the body
    /// with `body`, in a frame binding NAME.
    void loop(const Token& keyword, const std::function<void()>& body);
    /// Reads a block's entries up to its '}': child nodes, loops and lets
    /// into `node`'s children, its transforms and material into `node`.
    void node_body(std::string_view what, SourceLocation opened_at, SceneNode& node);
    /// While it lives, the parser reads a shape's body where it is written
    /// (its file, at its '{', paths relative to its directory); then it goes
    /// back to where it was, whether the body was read or threw.
    class Detour {
    public:
        Detour(SceneParser& parser, const ShapeDefinition& to);
        ~Detour();
        Detour(const Detour&) = delete;
        Detour& operator=(const Detour&) = delete;

    private:
        SceneParser& parser_;
        TokenStream* stream_;
        std::filesystem::path dir_;
        std::size_t position_;
    };
    /// Reads one `translate …`, `rotate …`, … after its keyword and applies
    /// it after the node's earlier ones, refusing a singular map (transforms.cpp).
    void add_transform(const Token& keyword, SceneNode& node);
    Mat4 read_transform(const Token& keyword);
    /// Counts one level of nested blocks while it lives; fails past the limit.
    class Nesting;

    Scene scene_;
    Scope scope_;
    ModelLibrary models_;
    struct OpenFile {
        std::filesystem::path canonical;
        std::string name;
    };
    std::vector<OpenFile> open_files_;          // the chain of includes being read
    std::set<std::filesystem::path> included_;  // every file read so far, canonical
    std::vector<std::unique_ptr<TokenStream>> streams_;  // every file read, kept for the bodies written in them
    std::optional<std::string> image_at_, camera_at_, background_at_, ambient_at_;
    TokenStream* in_ = nullptr;  // the file being read
    std::filesystem::path dir_;  // its directory
    int depth_ = 0;              // nested blocks and bodies being read
    long long iterations_ = 0;   // loop iterations read so far
    long long objects_ = 0;      // objects made so far
    SceneLimits limits_;
    double clock_ = 0.0;
};

}  // namespace zeroset
