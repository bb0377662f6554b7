// Helpers shared by the scene-language tests: parse text and check the exact
// error a scene produces, evaluate a parsed surface, and temporary files (support/temp_dir.hpp).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/temp_dir.hpp"
#include "zeroset/expr/evaluator.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace zeroset::test {

/// Parses `text` as the file "scene.zs" in the current directory.
inline Scene parse(const std::string& text) { return parse_scene(text, "scene.zs", "."); }

/// The error parsing `text` produces, as "file:line:column: message"; "" if it parses.
inline std::string error_of(const std::string& text, const std::filesystem::path& base_dir = ".",
                            const SceneLimits& limits = {}) {
    try {
        parse_scene(text, "scene.zs", base_dir, limits);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

/// f(x, y, z) of the surface `expression`, with `lets` (let statements) before it.
inline double evaluate(const std::string& expression, double x, double y, double z, const std::string& lets = "") {
    const Scene scene = parse(lets + "\nobject { surface " + expression + " }\n");
    const Tape tape(placed_objects(scene).at(0).object().surface);
    Evaluator<double> eval(tape);
    return eval(x, y, z);
}


}  // namespace zeroset::test
