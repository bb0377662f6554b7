# Barth's sextic with 65 real nodes, phi the golden ratio, cut by a ball:
#   (1 + 2 phi)(x^2 + y^2 + z^2 - 1)^2 - 4 (phi^2 x^2 - y^2)(phi^2 y^2 - z^2)(phi^2 z^2 - x^2)
# (the published form negated: f > 0 on nearly all of the ball's boundary, so
# the cut leaves only the tips of the spikes as caps).

camera { from (3.4, -4.4, 2.6)  at (0, 0, 0)  up (0, 0, 1)  fov 36 }
light  { from (-4, -6, 8) }
light  { direction (1, 0.6, -0.4)  color (0.25, 0.25, 0.3)  shadows off }

object "Barth sextic" {
  cut on   # the bounds clip the solid on purpose
  surface barth_sextic()
  bounds  sphere((0, 0, 0), 1.8)
  material { color (0.55, 0.7, 0.35)  specular 0.4 }
}
