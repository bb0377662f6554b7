# Clebsch's diagonal cubic surface (all 27 lines real), cut by a ball:
#   81(x^3 + y^3 + z^3) - 189(x^2 y + x^2 z + y^2 x + y^2 z + z^2 x + z^2 y) + 54 x y z
#   + 126(x y + x z + y z) - 9(x^2 + y^2 + z^2) - 9(x + y + z) + 1
# negated here (same zero set): a cubic has no inside, and a ball cut fills in
# the negative side, so the minus sign puts the filled side away from the camera.
# The ball is centred on (1/3, 1/3, 1/3): on the surface, fixed by permuting x, y, z.

camera { from (4.0, -2.0, 2.9)  at (0.3333, 0.3333, 0.3333)  up (0, 0, 1)  fov 36 }
light  { from (-4, -6, 8) }
light  { direction (1, 0.6, -0.4)  color (0.25, 0.25, 0.3)  shadows off }

object "Clebsch surface" {
  cut on   # the bounds clip the solid on purpose
  surface -clebsch()
  bounds  sphere((0.3333333, 0.3333333, 0.3333333), 1.3)
  material { color (0.85, 0.55, 0.3)  specular 0.4 }
}
