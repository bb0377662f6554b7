// The built-in default scene — the survey's Figure 1, rendered when no scene
// file is given. Its text is scenes/hart1993/blinn_blobs.zs, embedded here
// word for word (a test keeps the two equal).
#include "zeroset/scene/default_scene.hpp"

#include "zeroset/scene/load_scene.hpp"

namespace zeroset {

std::string_view default_scene_text() {
    return R"zs(# Two unit spheres centred at (±1.2, 0, 0), blended as Blinn's blobs: the
# survey's Figure 1 (Hart 1993, eqs. 5, 6 and 12). This is zeroset's built-in
# default scene.
#
#   f = |p - (1.2, 0, 0)|² - 1,   g = |p + (1.2, 0, 0)|² - 1,
#   h = 1 - e^(-f) - e^(-g)          negative where the two Gaussians sum past 1

image  { width 800  height 600 }
camera { from (0, 1.5, -9)  at (0, 0, 0)  fov 30 }
light  { from (-10, 10, -10) }                                           # key light: up, left, in front
light  { direction (-1, -0.2, 1)  color (0.25, 0.25, 0.3)  shadows off }  # dim fill from the right

let f = (x - 1.2)^2 + y^2 + z^2 - 1
let g = (x + 1.2)^2 + y^2 + z^2 - 1

object "blobs" {
  surface 1 - exp(-f) - exp(-g)
  bounds  box((-2.4, -1.2, -1.2), (2.4, 1.2, 1.2))   # the surface lies within |x| < 2.2, |y|, |z| < 1
  material { color (0.8, 0.3, 0.2)  specular 0.4  shininess 40 }
}
)zs";
}

Scene default_scene() { return parse_scene(default_scene_text(), "<default>", {}); }

}  // namespace zeroset
