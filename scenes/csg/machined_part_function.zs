# A machined part as one expression — CSG at the function level (survey §7,
# Ricci): a rounded block, a boss filleted onto it (smooth_union: the
# fillet is what only function CSG can do), and five drilled holes taken
# away with max(body, -hole). The same part as object CSG (Roth's span
# lists) is machined_part_roth.zs; a test renders both and compares them.

camera { from (2.6, 2.8, -3.4)  at (0.1, 0.1, 0)  fov 40 }
light  { from (-4, 9, -6) }
light  { direction (1, -0.4, 1)  color (0.2, 0.2, 0.24)  shadows off }

include "machined_part.inc"

object "part" {
  surface max(body, -min(boss_drill, min(drill_a, drill_b, drill_c, drill_d)))
  bounds  box((-1.65, -0.4, -1.05), (1.65, 0.86, 1.05))   # the fillet grows the body by at most k/4 = 0.03
  method  sphere   # distances with many kinks: 2.3 times faster than auto's interval method here
  material { color (0.62, 0.64, 0.68)  specular 0.6  shininess 60 }
}

object "plate" { cut on surface y + 0.35  bounds box((-3, -0.45, -2.2), (3, -0.35, 2.6))  material { color (0.35, 0.37, 0.4)  specular 0.1 } }
