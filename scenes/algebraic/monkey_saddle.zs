# The monkey saddle z = x^3 - 3 x y^2 over |x|, |y| <= 0.8 (the bounds cut it):
#   z - x^3 + 3 x y^2   (negative below the graph, so the cut shows a block with the saddle on top)

camera { from (1.9, -2.5, 4.4)  at (0, 0, -0.1)  up (0, 0, 1)  fov 36 }
light  { from (-4, -6, 8) }
light  { direction (1, 0.6, -0.4)  color (0.25, 0.25, 0.3)  shadows off }

object "monkey saddle" {
  cut on   # the bounds clip the solid on purpose
  surface monkey_saddle()
  bounds  box((-0.8, -0.8, -1.03), (0.8, 0.8, 1.03))   # max |x^3 - 3 x y^2| there is 1.024, at the corners
  material { color (0.6, 0.5, 0.35)  specular 0.3 }
}
