# The unit sphere, written as its distance function f = |p| - 1: the
# simplest implicit surface, and a first scene to edit.

camera { from (0, 0, -4)  at (0, 0, 0)  fov 40 }
light  { from (-5, 5, -5) }

object "sphere" {
  surface sqrt(x^2 + y^2 + z^2) - 1
  bounds  sphere((0, 0, 0), 1.1)
  material { color (0.2, 0.45, 0.8)  specular 0.5  shininess 60 }
}
