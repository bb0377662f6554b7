# A benchmark scene (not an example: it needs the shared models folder beside
# the repository). A bear's head: a real f-rep model in fidget's .vm format, imported with
# model(). The path is relative to this file; the model lives in the shared
# models folder beside the repository (MPL-2.0, see LICENSE-MPL-2.0.txt there).
# The bear faces -x; its surface lies within x in [-0.63, 0.96],
# y in [-0.58, 0.81], z in [-0.67, 0.60].

image  { width 800  height 600 }
camera { from (-2.6, 0.7, 2)  at (0.15, 0.1, -0.05)  fov 33 }
light  { from (-2.5, 6, 7) }
light  { direction (1, -0.3, -0.3)  color (0.25, 0.25, 0.3)  shadows off }

object "bear" {
  surface model("../../../shared/models/bear.vm")
  bounds  box((-0.7, -0.65, -0.75), (1.05, 0.9, 0.7))
  material { color (0.55, 0.38, 0.25)  specular 0.2  shininess 20 }
}
