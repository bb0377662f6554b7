// Helpers for the POV-Ray importer's tests: import text, check the exact
// error it gives, and evaluate an imported object's surface.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/pov/pov_import.hpp"

namespace zeroset::pov::test {

/// Imports `text` as "scene.pov" in the current directory, at 320×240.
inline PovImport import(const std::string& text) {
    PovOptions options;
    options.width = 320;
    options.height = 240;
    options.max_loop_iterations = 1000;
    return parse_pov_scene(text, "scene.pov", ".", options);
}

/// The error importing `text` gives, as "file:line:column: message"; "" if it imports.
inline std::string error_of(const std::string& text) {
    try {
        import(text);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

/// The first top-level object of the imported text (a copy: the import may be a temporary).
inline SceneNode first_node(const PovImport& imported) { return *imported.scene.nodes.at(0); }

/// f of an object node at a point of its own space.
inline double value_at(const SceneNode& node, double x, double y, double z) {
    const Tape tape(node.object.surface);
    Evaluator<double> f(tape);
    return f(x, y, z);
}

/// Whether some warning contains `part`.
inline bool warned(const PovImport& imported, const std::string& part) {
    for (const std::string& w : imported.scene.warnings)
        if (w.find(part) != std::string::npos) return true;
    return false;
}

}  // namespace zeroset::pov::test
