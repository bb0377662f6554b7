# Object CSG with a different intersection method for every object (survey
# §7; Roth 1982): a torus traced as a polynomial (its exact quartic along the
# ray), minus a gyroid traced by the interval method, minus a smooth blob of
# balls traced by sphere tracing. Each object hands over only the spans of the
# ray inside it; the merged spans give the visible surface, which keeps the
# owning object's normal and material — the gyroid's walls are blue, the
# bite the blob takes is red.

camera { from (0, 3.1, -3.3)  at (0, -0.1, 0)  fov 42 }
light  { from (-4, 8, -5) }
light  { direction (1, -0.3, 1)  color (0.2, 0.2, 0.25)  shadows off }

difference "spongy ring" {
  object "ring" {
    surface torus(1.1, 0.45)                    # around z: turned to lie flat
    bounds  box((-1.56, -1.56, -0.46), (1.56, 1.56, 0.46))
    method  polynomial
    rotate  (90, 0, 0)
    material { color (0.85, 0.75, 0.45)  specular 0.4 }
  }
  object "gyroid" {
    cut on   # the bounds clip the solid on purpose
    surface sin(5*x)*cos(5*y) + sin(5*y)*cos(5*z) + sin(5*z)*cos(5*x) + 0.7
    bounds  box((-1.6, -0.5, -1.6), (1.6, 0.5, 1.6))
    method  interval
    material { color (0.25, 0.45, 0.85) }
  }
  object "bite" {
    surface smooth_union(sd_sphere(0.42, (x - 1.15, y - 0.35, z + 0.25)), sd_sphere(0.35, (x - 0.95, y - 0.3, z - 0.35)), 0.2)
    bounds  box((0.55, -0.15, -0.75), (1.65, 0.85, 0.75))
    method  sphere
    material { color (0.85, 0.25, 0.2) }
  }
}

object "plate" { cut on surface y + 0.47  bounds box((-2.3, -0.55, -1.9), (2.3, -0.47, 2.4))  material { color (0.7, 0.7, 0.68)  specular 0 } }
