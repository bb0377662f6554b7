# A torus twisted about the x axis, the axis through its ring — Barr's twist
# (survey §9): the plane at x along the axis turns by 0.8·x radians, so
# the flat ring warps into a saddle. sd_torus is an exact distance; the
# twisted function f∘D⁻¹ is not, and sphere tracing takes its step bound from
# interval arithmetic. See docs/shapes.md.
#
# A twist about x keeps |x| ≤ R + r = 1.3 and the distance from the x axis,
# at most √(1.3² + 0.3²) < 1.34 on the torus: the bounds below hold it.

camera { from (0.3, 2.3, -3.9)  at (0, 0, 0)  fov 40 }
light  { from (-5, 8, -6) }
light  { direction (-1, -0.5, 1)  color (0.2, 0.2, 0.25)  shadows off }

object "twisted torus" {
  surface twist(sd_torus(1, 0.3), (1, 0, 0), 0.8)
  bounds  box((-1.35, -1.35, -1.35), (1.35, 1.35, 1.35))
  material { color (0.85, 0.55, 0.2)  specular 0.5  shininess 60 }
}

object "floor" {
  cut on   # the bounds clip the solid on purpose
  surface y + 1.6
  bounds  box((-8, -1.7, -4), (8, -1.5, 10))
  material { color (0.75, 0.75, 0.72)  specular 0 }
}
