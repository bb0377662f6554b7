# A filleted pipe junction — Hoffman and Hopcroft's algebraic blends (survey
# §3.3; Hoffman & Hopcroft 1985), integrated into the model by CSG as the
# survey says they must be. A post x² + z² = 0.5² stands on a plate y = 0
# and a pipe (y − 1.2)² + z² = 0.3² runs through it. Every surface is a
# polynomial — the cylinders of degree 2, the plate 1, the two fillets 4 —
# so every object is traced by its exact ray polynomial.

camera { from (2.4, 2.5, -4.3)  at (0, 0.6, 0)  fov 42 }
light  { from (-4, 8, -6) }
light  { direction (1, -0.4, 1)  color (0.2, 0.2, 0.24)  shadows off }

let post  = x^2 + z^2 - 0.5^2
let plate = y
let pipe  = (y - 1.2)^2 + z^2 - 0.3^2

# The blend of g and h that leaves h = 0 where g = a and g = 0 where h = b,
# clipped to g ≤ a and h ≤ b (beyond, the blend is not a fillet); lo and hi
# are a box around that clipped region.
shape fillet(g, h, a, b, lo, hi) {
  intersection {
    object { cut on surface algebraic_blend(g, h, a, b)  bounds box(lo, hi) }
    object { cut on surface g - a  bounds box(lo, hi) }
    object { cut on surface h - b  bounds box(lo, hi) }
  }
}

union "junction" {
  object "plate" { cut on surface plate  bounds box((-2.2, -0.25, -2.2), (2.2, 0, 2.2))  material { color (0.36, 0.38, 0.42)  specular 0.1 } }
  object "post"  { cut on surface post   bounds box((-0.5, -0.25, -0.5), (0.5, 1.9, 0.5)) }
  object "pipe"  { cut on surface pipe   bounds box((-1.9, 0.9, -0.3), (1.9, 1.5, 0.3)) }
  # The foot: g = 0.36 is the circle of radius √(0.25 + 0.36) ≈ 0.78 on the
  # plate, h = 0.3 the height where the fillet meets the post.
  instance fillet(post, plate, 0.36, 0.3, (-0.79, -0.01, -0.79), (0.79, 0.31, 0.79))
  # The joint: the fillet meets the pipe where the distance from the post's
  # axis is √(0.25 + 0.2) ≈ 0.67, and the post where the distance from the
  # pipe's axis is √(0.09 + 0.12) ≈ 0.46.
  instance fillet(post, pipe, 0.2, 0.12, (-0.68, 0.73, -0.5), (0.68, 1.67, 0.5))
  material { color (0.62, 0.64, 0.68)  specular 0.6  shininess 60 }
}
