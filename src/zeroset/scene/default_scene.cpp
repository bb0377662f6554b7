// The built-in default scene — the survey's Figure 1, rendered when no scene
// file is given. Its text is scenes/hart1993/blinn_blobs.zs, embedded at
// build time (src/CMakeLists.txt generates default_scene_text()).
#include "zeroset/scene/default_scene.hpp"

#include "zeroset/scene/load_scene.hpp"

namespace zeroset {

Scene default_scene() { return parse_scene(default_scene_text(), "<default>", {}); }

}  // namespace zeroset
