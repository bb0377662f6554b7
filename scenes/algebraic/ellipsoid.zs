# An ellipsoid with semi-axes 1.5, 1 and 0.6:
#   x^2/1.5^2 + y^2/1^2 + z^2/0.6^2 - 1   (negative inside)

camera { from (3, -4.4, 2.8)  at (0, 0, 0)  up (0, 0, 1)  fov 36 }
light  { from (-4, -6, 8) }
light  { direction (1, 0.6, -0.4)  color (0.25, 0.25, 0.3)  shadows off }

object "ellipsoid" {
  surface ellipsoid(1.5, 1, 0.6)
  bounds  box((-1.51, -1.01, -0.61), (1.51, 1.01, 0.61))
  material { color (0.3, 0.55, 0.85)  specular 0.5  shininess 60 }
}
