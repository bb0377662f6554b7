# Constructive solid geometry with min and max: the classic CSG tree — a cube
# intersected with a ball, minus three cylinders along the axes.
#   union A ∪ B = min(a, b),  intersection A ∩ B = max(a, b),  difference A − B = max(a, -b)

camera { from (2.6, 2.4, -3.6)  at (0, 0, 0)  fov 38 }
light  { from (-4, 8, -6) }
light  { direction (-1, -0.4, 1)  color (0.2, 0.2, 0.25)  shadows off }

let cube = max(abs(x), abs(y), abs(z)) - 1
let ball = sqrt(x^2 + y^2 + z^2) - 1.35
let rods = min(sqrt(y^2 + z^2), sqrt(x^2 + z^2), sqrt(x^2 + y^2)) - 0.55

object "cube and ball minus rods" {
  surface max(cube, ball, -rods)
  bounds  box((-1.1, -1.1, -1.1), (1.1, 1.1, 1.1))
  material { color (0.35, 0.7, 0.4)  specular 0.3  shininess 30 }
}
