# A square column, twisted, tapered and bent — Barr's three deformations
# (survey §9), applied in that order to a rounded box standing on the y axis:
#   twist  a quarter turn over the column's height (0.5 rad per unit of y),
#   taper  the cross-section by 1 − 0.2·y (1.3 at the foot, 0.7 at the top),
#   bend   its upper half (0 ≤ y ≤ 1.5) into an arc of radius 1/0.6 towards +x,
#          straight below.
# Each step keeps an implicit function whose zero set is the deformed
# surface; the bounds were checked by interval arithmetic (f > 0 on every face).

camera { from (1.2, 1.0, -5.2)  at (0.3, 0, 0)  fov 40 }
light  { from (-4, 8, -6) }
light  { direction (1, -0.4, 1)  color (0.2, 0.2, 0.25)  shadows off }

let column = sd_round_box((0.35, 1.5, 0.35), 0.06)
let twisted = twist(column, (0, 1, 0), 0.5)
let tapered = taper(twisted, (0, 1, 0), -0.2)

object "column" {
  surface bend(tapered, (0, 1, 0), (1, 0, 0), 0.6, 0, 1.5)
  bounds  box((-0.7, -1.55, -0.7), (1.2, 1.6, 0.7))
  material { color (0.8, 0.78, 0.7)  specular 0.3  shininess 30 }
}

object "floor" {
  cut on   # the bounds clip the solid on purpose
  surface y + 1.5
  bounds  box((-8, -1.6, -4), (8, -1.4, 10))
  material { color (0.55, 0.6, 0.7)  specular 0 }
}
