# Steiner's Roman surface, within |x|, |y|, |z| <= 1/2:
#   x^2 y^2 + y^2 z^2 + z^2 x^2 - x y z
# It is one-sided; f < 0 in the four lobes in the octants where x y z > 0.

camera { from (2.4, -2.0, 1.7)  at (0, 0, 0)  up (0, 0, 1)  fov 24 }
light  { from (-4, -6, 8) }
light  { direction (1, 0.6, -0.4)  color (0.25, 0.25, 0.3)  shadows off }

object "Roman surface" {
  surface steiner()
  bounds  box((-0.51, -0.51, -0.51), (0.51, 0.51, 0.51))
  material { color (0.8, 0.35, 0.3)  specular 0.4 }
}
