// The scene language's front door: load a .zs file, parse scene text, or
// take the built-in default scene. Every problem with a scene — syntax, a bad
// value, a missing include or model — is a SceneError whose what() reads
// `file:line:column: message`. The language is docs/scene-language.md.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "zeroset/scene/default_scene.hpp"
#include "zeroset/scene/scene.hpp"
#include "zeroset/scene/scene_error.hpp"
#include "zeroset/scene/scene_limits.hpp"

namespace zeroset {

/// Reads and parses a scene file; its includes and models are found relative
/// to it. A file that cannot be read is a SceneError with line 0
/// ("file: cannot open the scene file: …"). The scene's `clock` reads
/// `clock` (an animation's time, 0 → 1 over `render --frames`).
Scene load_scene(const std::filesystem::path& file, const SceneLimits& limits = {}, double clock = 0.0);

/// Parses scene text; errors name `file_name`, and relative include and
/// model paths start at `base_dir`.
Scene parse_scene(std::string_view text, const std::string& file_name, const std::filesystem::path& base_dir,
                  const SceneLimits& limits = {}, double clock = 0.0);

}  // namespace zeroset
