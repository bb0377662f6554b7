// Helpers shared by the scene-language tests: parse text and check the exact
// error a scene produces, evaluate a parsed surface, make temporary files.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace zeroset::test {

/// Parses `text` as the file "scene.zs" in the current directory.
inline Scene parse(const std::string& text) { return parse_scene(text, "scene.zs", "."); }

/// The error parsing `text` produces, as "file:line:column: message"; "" if it parses.
inline std::string error_of(const std::string& text, const std::filesystem::path& base_dir = ".") {
    try {
        parse_scene(text, "scene.zs", base_dir);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

/// f(x, y, z) of the surface `expression`, with `lets` (let statements) before it.
inline double evaluate(const std::string& expression, double x, double y, double z, const std::string& lets = "") {
    const Scene scene = parse(lets + "\nobject { surface " + expression + " }\n");
    const Tape tape(scene.objects.at(0).surface);
    Evaluator<double> eval(tape);
    return eval(x, y, z);
}

/// A fresh, empty directory under the system's temporary directory, removed at the end of the test.
class TempDir {
public:
    TempDir() {
        std::random_device random;
        path_ = std::filesystem::temp_directory_path() / ("zeroset-scene-test-" + std::to_string(random()));
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    [[nodiscard]] const std::filesystem::path& path() const { return path_; }

    /// Writes `text` to `name` inside the directory (creating subdirectories) and returns its path.
    std::filesystem::path write(const std::string& name, const std::string& text) const {
        const std::filesystem::path file = path_ / name;
        std::filesystem::create_directories(file.parent_path());
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }

private:
    std::filesystem::path path_;
};

}  // namespace zeroset::test
