// The one surface a command works on: a .vm model (fidget's format) as it
// is, or an object of a scene file (--object NAME, default its first) with
// its bounds and its placement in the scene — for `slice` and `mesh`.
#pragma once

#include <filesystem>
#include <optional>

#include "options.hpp"
#include "zeroset/expr/expr.hpp"
#include "zeroset/math/box3.hpp"
#include "zeroset/math/mat4.hpp"

namespace zeroset::cli {

struct ModelInput {
    Expr surface;                         // in the object's own space
    std::optional<Box3> bounds;           // the box enclosing its bounds; none for a .vm model or unbounded object
    Mat4 to_scene = Mat4::identity();     // the object's placement; identity for a .vm model
};

/// Reads PATH (a .vm model or a scene). Throws SceneError for a bad file and
/// UsageError for --object with a model or a name the scene lacks.
ModelInput load_model_input(const std::filesystem::path& path, const Options& options);

}  // namespace zeroset::cli
