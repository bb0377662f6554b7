# The infinite circular cylinder of radius 0.5 along z, cut to |z| <= 1.2
# by its bounds:  x^2 + y^2 - 0.5^2   (negative inside). The camera stays below
# z = 1.2: the cut end would show a filled disc shaded with the side-pointing gradient.

camera { from (2.8, -3.6, 0.9)  at (0, 0, 0)  up (0, 0, 1)  fov 40 }
light  { from (-4, -6, 8) }
light  { direction (1, 0.6, -0.4)  color (0.25, 0.25, 0.3)  shadows off }

object "cylinder" {
  cut on   # the bounds clip the solid on purpose
  surface cylinder(0.5)
  bounds  box((-0.51, -0.51, -1.2), (0.51, 0.51, 1.2))
  material { color (0.35, 0.7, 0.45)  specular 0.4 }
}
