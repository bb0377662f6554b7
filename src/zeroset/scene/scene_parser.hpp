// SceneParser: the statement half of the scene language — image, camera,
// light, background, ambient, let, include and object — filling a Scene as
// it reads. One parser reads a whole scene, following includes; expressions
// are read by expression_parser.hpp.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "zeroset/scene/model_library.hpp"
#include "zeroset/scene/scene.hpp"
#include "zeroset/scene/scope.hpp"
#include "zeroset/scene/token_stream.hpp"

namespace zeroset {

class SceneParser {
public:
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

    void statement();
    void image(const Token& keyword);
    void camera(const Token& keyword);
    void light(const Token& keyword);
    void let();
    void include(const Token& keyword);
    void object(const Token& keyword);
    Material material(const Token& keyword);
    Bounds bounds();
    /// A name from `names` (the error lists them); `what` names the choice in messages.
    const Token& choice(std::string_view what, std::span<const std::string_view> names);
    Method method();
    PolynomialSolver polynomial_solver();
    NormalMode normal_mode();

    /// Reads `{ key value … }`: keys from `keys`, each at most once, in any
    /// order; `on_key` reads the value of the key just consumed.
    void block(const Token& keyword, std::span<const std::string_view> keys,
               const std::function<void(const Token& key)>& on_key);
    /// Records the first `keyword` statement of its kind; fails on a second.
    void once(std::optional<std::string>& first, const Token& keyword, std::string_view what);

    Located<Value> value();
    Located<double> number(std::string_view what);
    Located<Vec3d> vector(std::string_view what);
    double non_negative(std::string_view what);
    Vec3d color(std::string_view what);
    int count(std::string_view what, int max);
    bool on_off(std::string_view what);

    Scene scene_;
    Scope scope_;
    ModelLibrary models_;
    struct OpenFile {
        std::filesystem::path canonical;
        std::string name;
    };
    std::vector<OpenFile> open_files_;          // the chain of includes being read
    std::set<std::filesystem::path> included_;  // every file read so far, canonical
    std::optional<std::string> image_at_, camera_at_, background_at_, ambient_at_;
    TokenStream* in_ = nullptr;  // the file being read
    std::filesystem::path dir_;  // its directory
};

}  // namespace zeroset
