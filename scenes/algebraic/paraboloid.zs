# The paraboloid of revolution z = (x^2 + y^2)/k with k = 1, cut at z = 1:
#   x^2 + y^2 - k z   (negative inside, above the bowl)

camera { from (2.6, -3.4, 2.8)  at (0, 0, 0.45)  up (0, 0, 1)  fov 40 }
light  { from (-4, -6, 8) }
light  { direction (1, 0.6, -0.4)  color (0.25, 0.25, 0.3)  shadows off }

object "paraboloid" {
  cut on   # the bounds clip the solid on purpose
  surface paraboloid(1)
  bounds  box((-1.01, -1.01, -0.01), (1.01, 1.01, 1))
  material { color (0.7, 0.4, 0.75)  specular 0.4 }
}
