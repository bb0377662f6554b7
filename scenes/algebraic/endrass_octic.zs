# Endrass's octic X+ with 168 real nodes (w = 1), cut by a ball:
#   Q^2 - 64 (x^2 - 1)(y^2 - 1)((x + y)^2 - 2)((x - y)^2 - 2)   (the published form negated),
#   Q = -4(1 + sqrt 2)(x^2 + y^2)^2 + (8(2 + sqrt 2) z^2 + 2(2 + 7 sqrt 2))(x^2 + y^2)
#       - 16 z^4 + 8(1 - 2 sqrt 2) z^2 - (1 + 12 sqrt 2)

camera { from (0, -7.5, 5.5)  at (0, 0, 0)  up (0, 0, 1)  fov 28 }
light  { from (-4, -6, 8) }
light  { direction (1, 0.6, -0.4)  color (0.25, 0.25, 0.3)  shadows off }

object "Endrass octic" {
  cut on   # the bounds clip the solid on purpose
  surface endrass_octic()
  bounds  sphere((0, 0, 0), 1.8)
  material { color (0.65, 0.45, 0.8)  specular 0.4 }
}
