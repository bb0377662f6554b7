image { width 32  height 24  spp 2 }
camera { from (0, 1, -4)  at (0, 0, 0)  fov 40 }
light { from (-3, 5, -4) }
light { direction (1, -1, 0.5)  color (0.2, 0.2, 0.3)  shadows off }
background (0.1, 0.1, 0.2)
ambient (0.1, 0.1, 0.1)
object "ball" {
  surface sqrt(x^2 + y^2 + z^2) - 1
  bounds sphere((0, 0, 0), 1.5)
  method sphere
  normals central
  material { color (0.8, 0.3, 0.2)  specular 0.4  shininess 30 }
}
