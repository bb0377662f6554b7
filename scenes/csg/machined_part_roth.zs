# The machined part of machined_part_function.zs as object CSG (survey §7;
# Roth 1982): the filleted body minus five drills, each drill an object of
# its own — a cylinder x² + z² − r² clipped by its bounds, traced by the
# polynomial method, while the body is sphere traced. The
# span lists of the six objects are merged along every ray; the drills'
# walls keep their own material (the bores are darker).

camera { from (2.6, 2.8, -3.4)  at (0.1, 0.1, 0)  fov 40 }
light  { from (-4, 9, -6) }
light  { direction (1, -0.4, 1)  color (0.2, 0.2, 0.24)  shadows off }

include "machined_part.inc"

shape drill(r) {
  object { cut on surface x^2 + z^2 - r^2  bounds box((-r, -1, -r), (r, 1.5, r))  material { color (0.4, 0.42, 0.46)  specular 0.3 } }
}

difference "part" {
  object "body" { surface body  bounds box((-1.65, -0.4, -1.05), (1.65, 0.86, 1.05))  method sphere }
  instance drill(0.22) { translate (-0.8, 0, 0) }
  instance drill(0.15) { translate (0.55, 0, 0.5) }
  instance drill(0.15) { translate (0.55, 0, -0.5) }
  instance drill(0.15) { translate (1.15, 0, 0.5) }
  instance drill(0.15) { translate (1.15, 0, -0.5) }
  material { color (0.62, 0.64, 0.68)  specular 0.6  shininess 60 }
}

object "plate" { cut on surface y + 0.35  bounds box((-3, -0.45, -2.2), (3, -0.35, 2.6))  material { color (0.35, 0.37, 0.4)  specular 0.1 } }
