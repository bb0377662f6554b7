# The double cone x^2 + y^2 = k^2 z^2 with k = 0.6 (apex at the origin, axis z),
# cut to |z| <= 1.4 by its bounds:  x^2 + y^2 - 0.6^2 z^2   (negative inside)

camera { from (3.2, -4.2, 2.4)  at (0, 0, 0)  up (0, 0, 1)  fov 40 }
light  { from (-4, -6, 8) }
light  { direction (1, 0.6, -0.4)  color (0.25, 0.25, 0.3)  shadows off }

object "cone" {
  cut on   # the bounds clip the solid on purpose
  surface cone(0.6)
  bounds  box((-0.85, -0.85, -1.4), (0.85, 0.85, 1.4))
  material { color (0.85, 0.6, 0.25)  specular 0.4 }
}
