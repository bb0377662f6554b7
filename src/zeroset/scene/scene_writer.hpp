// Writing a Scene as scene-language text (docs/scene-language.md): what
// `zeroset import` saves of a POV-Ray scene, and a way to keep a scene
// built in code. Reading the text back gives the same scene: every number
// is written to 17 significant digits, transforms as matrices, objects with
// their expressions, blobs and sweeps by their components and pieces.
// A node shared by several parents (a shape placed twice) is written once,
// as a shape, and placed as instances.
#pragma once

#include <string>

#include "zeroset/scene/scene.hpp"

namespace zeroset {

/// The scene as text; `header` comes first as comment lines (without their
/// '#'). The scene's warnings are written as comments too.
std::string write_scene(const Scene& scene, const std::string& header = {});

}  // namespace zeroset
