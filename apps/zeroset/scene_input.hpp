// The scene file a command reads: zeroset's own language (.zs) or a POV-Ray
// scene (.pov, read by the importer, pov/pov_import.hpp), so that every
// command takes either. A POV-Ray scene needs the image size before it is
// read (it may use image_width and image_height), so the command's
// --width and --height are passed in.
#pragma once

#include <filesystem>
#include <optional>

#include "options.hpp"
#include "zeroset/scene/scene.hpp"

namespace zeroset::cli {

/// The options every command that reads a scene file takes for POV-Ray's.
inline constexpr std::array<const char*, 1> scene_input_options{"--include-path"};

/// Reads the scene file. For a .pov file, the image size is --width and
/// --height (else 640×480), #include also searches --include-path (folders
/// separated by ':'), and the importer's notes (settings zeroset does not
/// need) are printed to stderr unless `quiet`. Throws SceneError.
Scene load_scene_file(const std::filesystem::path& file, const Options& options, double clock = 0.0, bool quiet = false);

/// The help text of the options above.
std::string scene_input_help();

}  // namespace zeroset::cli
