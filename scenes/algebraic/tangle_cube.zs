# The tanglecube (negative inside; |x|, |y|, |z| < 2.27):
#   x^4 - 5 x^2 + y^4 - 5 y^2 + z^4 - 5 z^2 + 11.8

camera { from (6.8, -8.6, 5.6)  at (0, 0, 0)  up (0, 0, 1)  fov 36 }
light  { from (-4, -6, 8) }
light  { direction (1, 0.6, -0.4)  color (0.25, 0.25, 0.3)  shadows off }

object "tanglecube" {
  surface tangle_cube()
  bounds  box((-2.3, -2.3, -2.3), (2.3, 2.3, 2.3))
  material { color (0.3, 0.65, 0.7)  specular 0.4 }
}
