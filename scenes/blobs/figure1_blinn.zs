# The survey's Figure 1 (Hart 1993, eq. 12) as a Blinn blob: two unit
# spheres at (±1.2, 0, 0) whose Gaussians sum to the threshold,
#
#   h = 1 - e^(-f) - e^(-g),   f = |p - c1|² - 1,  g = |p - c2|² - 1.
#
# Blinn's kernel is s·e^(B(u - 1)) with u = r²/R², so e^(-f) = e^(1 - r²) is
# the component with strength 1, radius 1, blobbiness -1 at threshold 1.
# scenes/hart1993/blinn_blobs.zs writes the same field as an expression.

image  { width 800  height 600 }
camera { from (0, 2.5, -9)  at (0, -0.2, 0)  fov 30 }
light  { from (-10, 10, -10) }
light  { direction (1, -1, 1)  color (0.15, 0.15, 0.18)  shadows off }

blob "blobs" {
  kernel    blinn
  threshold 1
  component { center ( 1.2, 0, 0)  radius 1  strength 1  blobbiness -1 }
  component { center (-1.2, 0, 0)  radius 1  strength 1  blobbiness -1 }
  material  { color (0.8, 0.3, 0.2)  specular 0.4  shininess 40 }
}

object "floor" {
  cut on   # the bounds clip the solid on purpose
  surface y + 1.3
  bounds  box((-12, -1.4, -6), (12, -1.2, 14))
  material { color (0.75, 0.75, 0.72)  specular 0 }
}
