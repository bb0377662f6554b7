# Chmutov's octic with 144 real nodes, T8(x) + T8(y) + T8(z) + 1 = 0, T8 the Chebyshev
# polynomial 128 t^8 - 256 t^6 + 160 t^4 - 32 t^2 + 1 (negative inside; |x|, |y|, |z| < 1).

camera { from (3.0, -3.9, 2.9)  at (0, 0, 0)  up (0, 0, 1)  fov 36 }
light  { from (-4, -6, 8) }
light  { direction (1, 0.6, -0.4)  color (0.25, 0.25, 0.3)  shadows off }

object "Chmutov octic" {
  surface chmutov_octic()
  bounds  box((-1.001, -1.001, -1.001), (1.001, 1.001, 1.001))
  material { color (0.8, 0.7, 0.3)  specular 0.4 }
}
