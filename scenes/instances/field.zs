# A field of 10 000 instances of one shape: a little torus (an exact quartic,
# traced by the polynomial method) tilted, turned and coloured at random —
# one tape for all of them, each instance only a transform and a material,
# found by the BVH over the 10 000 (see docs/scene-structure.md). The ground
# is a plane without bounds, so the field runs to the horizon.

image  { width 800  height 450 }
camera { from (0, 6, -12)  at (0, 0, 12)  fov 35 }
light  { from (-30, 40, -20) }
light  { direction (1, -0.5, 0.5)  color (0.15, 0.15, 0.2)  shadows off }
background (0.55, 0.65, 0.8)

shape ring {
  object { surface torus(0.3, 0.09)  bounds box((-0.4, -0.4, -0.1), (0.4, 0.4, 0.1)) }
}

for i from 0 to 99 {
  for j from 0 to 99 {
    let k = 100 * i + j
    # Pseudo-random numbers in [0, 1) from the instance's number.
    let r1 = mod(sin(12.9898 * k) * 43758.5453, 1)
    let r2 = mod(sin(78.233 * k) * 43758.5453, 1)
    let r3 = mod(sin(39.425 * k) * 43758.5453, 1)
    instance ring {
      rotate (90 * r1, 360 * r2, 0)
      translate (i - 49.5 + 0.6 * r3, 0.4, j - 20 + 0.6 * r2)
      material { color (0.35 + 0.6 * r1, 0.3 + 0.5 * r3, 0.25 + 0.6 * r2)  specular 0.5 }
    }
  }
}

object "ground" { surface y  bounds none  material { color (0.45, 0.5, 0.4)  specular 0 } }
