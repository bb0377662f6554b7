# A torus around the y axis, major radius 1, minor radius 0.35:
#   f = (sqrt(x² + z²) - 1)² + y² - 0.35²
# seen from above the front so that the hole shows.

camera { from (0, 2.2, -3.4)  at (0, 0, 0)  fov 40 }
light  { from (-5, 8, -5) }
light  { direction (-1, -0.5, 1)  color (0.2, 0.2, 0.25)  shadows off }

let R = 1      # major radius: from the y axis to the centre of the tube
let r = 0.35   # minor radius: of the tube

object "torus" {
  surface (sqrt(x^2 + z^2) - R)^2 + y^2 - r^2
  bounds  box((-1.4, -0.4, -1.4), (1.4, 0.4, 1.4))   # |x|, |z| <= R + r, |y| <= r
  material { color (0.85, 0.65, 0.2)  specular 0.5  shininess 60 }
}
