# The two hyperboloids, cut to |z| <= 1.2, side by side; each is written at a
# hand-moved point (the last argument) so that it stays in standard form:
#   one sheet  (left):  (x^2 + y^2)/0.5^2  - z^2/0.7^2 - 1   (negative inside the waist)
#   two sheets (right): (x^2 + y^2)/0.35^2 - z^2/0.4^2 + 1   (negative inside the bowls)

camera { from (0, -6.5, 2.2)  at (0, 0, 0)  up (0, 0, 1)  fov 36 }
light  { from (-4, -6, 8) }
light  { direction (1, 0.6, -0.4)  color (0.25, 0.25, 0.3)  shadows off }

object "one sheet" {
  cut on   # the bounds clip the solid on purpose
  surface hyperboloid(0.5, 0.7, 1, (x + 1.2, y, z))
  bounds  box((-2.2, -1, -1.2), (-0.2, 1, 1.2))
  material { color (0.3, 0.6, 0.85)  specular 0.4 }
}

object "two sheets" {
  cut on   # the bounds clip the solid on purpose
  surface hyperboloid(0.35, 0.4, 2, (x - 1.2, y, z))
  bounds  box((0.2, -1, -1.2), (2.2, 1, 1.2))
  material { color (0.85, 0.45, 0.3)  specular 0.4 }
}
