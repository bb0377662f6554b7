# Kummer's quartic with 16 real nodes, mu^2 = 1.69:
#   (x^2 + y^2 + z^2 - mu^2)^2 - lambda p q r s,  lambda = (3 mu^2 - 1)/(3 - mu^2)
#   p, q = 1 - z -+ sqrt(2) x,  r, s = 1 + z +- sqrt(2) y
# It is unbounded (four double cones run off to infinity); the bounds cut it.

camera { from (4.8, -7.0, 4.0)  at (0, 0, 0)  up (0, 0, 1)  fov 36 }
light  { from (-4, -6, 8) }
light  { direction (1, 0.6, -0.4)  color (0.25, 0.25, 0.3)  shadows off }

object "Kummer surface" {
  cut on   # the bounds clip the solid on purpose
  surface kummer(1.69)
  bounds  sphere((0, 0, 0), 2.6)
  material { color (0.45, 0.6, 0.85)  specular 0.4 }
}
