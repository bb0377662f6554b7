# Gerono's lemniscate x^4 = x^2 - y^2 turned about the x axis: two drops
# meeting at a node at the origin, |x| <= 1 (negative inside):
#   x^4 - x^2 + y^2 + z^2

camera { from (1.4, -2.6, 1.2)  at (0, 0, 0)  up (0, 0, 1)  fov 40 }
light  { from (-4, -6, 8) }
light  { direction (1, 0.6, -0.4)  color (0.25, 0.25, 0.3)  shadows off }

object "lemniscate of Gerono" {
  surface lemniscate_of_gerono()
  bounds  box((-1.01, -0.51, -0.51), (1.01, 0.51, 0.51))
  material { color (0.85, 0.4, 0.5)  specular 0.4 }
}
