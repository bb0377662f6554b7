# The torus around the z axis, major radius R = 1, minor radius r = 0.35, as a quartic:
#   (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + y^2)   (negative inside)

camera { from (0, -3.2, 2.4)  at (0, 0, 0)  up (0, 0, 1)  fov 40 }
light  { from (-4, -6, 8) }
light  { direction (1, 0.6, -0.4)  color (0.25, 0.25, 0.3)  shadows off }

object "torus" {
  surface torus(1, 0.35)
  bounds  box((-1.36, -1.36, -0.36), (1.36, 1.36, 0.36))
  material { color (0.85, 0.65, 0.2)  specular 0.5  shininess 60 }
}
