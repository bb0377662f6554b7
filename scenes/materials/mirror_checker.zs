# A mirror ball over a checkered floor: a material's colour as an expression
# of the object's coordinates (the floor's checker, the column's stripes)
# and a mirror `reflection` (docs/rendering.md#materials). The ball rolls
# along x with the animation clock:
#   zeroset render scenes/materials/mirror_checker.zs --frames 24 -o roll.png
# writes roll_0000.png … roll_0023.png with clock running from 0 to 1.

image  { width 640  height 400  reflection_depth 4 }
camera { from (0, 2.2, -7)  at (0, 0.6, 0)  fov 40 }
light  { from (-6, 8, -6) }
light  { direction (1, -1, 0.5)  color (0.2, 0.2, 0.25)  shadows off }
background (0.55, 0.65, 0.85)

# 1 on one colour of a unit checker, 0 on the other.
let checker = mod(floor(x) + floor(z), 2)

object "floor" {
  surface y
  bounds none
  material { color (0.9, 0.9, 0.85) * checker + (0.15, 0.15, 0.2) * (1 - checker)  specular 0 }
}

object "ball" {
  surface x^2 + (y - 1)^2 + z^2 - 1
  bounds box((-1.1, -0.1, -1.1), (1.1, 2.1, 1.1))
  material { color (0.05, 0.05, 0.05)  diffuse 0.2  specular 0.8  shininess 200  reflection 0.85 }
  translate (3 * clock - 1.5, 0, 0)
}

object "column" {
  surface max(sqrt(x^2 + z^2) - 0.5, abs(y - 1.5) - 1.5)
  bounds box((-0.6, -0.1, -0.6), (0.6, 3.1, 0.6))
  # Stripes up the column: a smooth colour from a sine of the height.
  material { color (0.8, 0.3 + 0.25 * sin(8 * y), 0.2)  specular 0.3 }
  translate (2.2, 0, 2.5)
}
