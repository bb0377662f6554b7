// The built-in default scene: two blended spheres, the survey's Figure 1.
#pragma once

#include <string_view>

#include "zeroset/scene/scene.hpp"

namespace zeroset {

/// The default scene's text: exactly scenes/hart1993/blinn_blobs.zs.
std::string_view default_scene_text();

/// default_scene_text() parsed, with file name "<default>".
Scene default_scene();

}  // namespace zeroset
