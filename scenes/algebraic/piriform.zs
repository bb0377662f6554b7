# The piriform (pear) surface: the piriform curve y^2 = x^3 (1 - x) turned
# about the x axis, 0 <= x <= 1 (negative inside):
#   x^4 - x^3 + y^2 + z^2

camera { from (1.6, -1.9, 0.8)  at (0.5, 0, 0)  up (0, 0, 1)  fov 36 }
light  { from (-4, -6, 8) }
light  { direction (1, 0.6, -0.4)  color (0.25, 0.25, 0.3)  shadows off }

object "piriform" {
  surface piriform()
  bounds  box((-0.01, -0.34, -0.34), (1.01, 0.34, 0.34))
  material { color (0.75, 0.75, 0.25)  specular 0.4 }
}
