# Two unit spheres centred at (±1.2, 0, 0), blended as Blinn's blobs: the
# survey's Figure 1 (Hart 1993, eqs. 5, 6 and 12). This is zeroset's built-in
# default scene; a floor below the blobs catches their shadow.
#
#   f = |p - (1.2, 0, 0)|² - 1,   g = |p + (1.2, 0, 0)|² - 1,
#   h = 1 - e^(-f) - e^(-g)          negative where the two Gaussians sum past 1

image  { width 800  height 600 }
camera { from (0, 2.5, -9)  at (0, -0.2, 0)  fov 30 }
light  { from (-10, 10, -10) }                                            # key light: up, left, in front
light  { direction (1, -1, 1)  color (0.15, 0.15, 0.18)  shadows off }    # dim fill from the left

let f = (x - 1.2)^2 + y^2 + z^2 - 1
let g = (x + 1.2)^2 + y^2 + z^2 - 1

object "blobs" {
  surface 1 - exp(-f) - exp(-g)
  bounds  box((-2.4, -1.2, -1.2), (2.4, 1.2, 1.2))   # the surface lies within |x| < 2.2, |y|, |z| < 1
  material { color (0.8, 0.3, 0.2)  specular 0.4  shininess 40 }
}

object "floor" {
  cut on   # the bounds clip the solid on purpose
  surface y + 1.3
  bounds  box((-12, -1.4, -6), (12, -1.2, 14))
  material { color (0.75, 0.75, 0.72)  specular 0 }
}
