# The unit sphere as the ellipsoid with a = b = c = 1:
#   x^2 + y^2 + z^2 - 1   (negative inside)

camera { from (2.6, -3.6, 2.2)  at (0, 0, 0)  up (0, 0, 1)  fov 36 }
light  { from (-4, -6, 8) }
light  { direction (1, 0.6, -0.4)  color (0.25, 0.25, 0.3)  shadows off }

object "sphere" {
  surface ellipsoid(1, 1, 1)
  bounds  sphere((0, 0, 0), 1.001)
  material { color (0.8, 0.3, 0.2)  specular 0.5  shininess 60 }
}
