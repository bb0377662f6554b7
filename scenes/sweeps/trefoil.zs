# A trefoil knot: a sphere swept along a closed Catmull–Rom spline through
# 48 points of (sin u + 2 sin 2u, cos u − 2 cos 2u, −sin 3u), the swept
# spheres of van Wijk (1984; the survey's §3.4), each of the 48 cubic
# pieces traced by the roots of its degree-10 polynomial (docs/sweeps.md).
#
#   zeroset render scenes/sweeps/trefoil.zs -o trefoil.png

image  { width 640  height 480 }
camera { from (0, 1.5, -9.5)  at (0, 0.1, 0)  fov 40 }
light  { from (-6, 8, -8) }
light  { direction (1, -0.3, 1)  color (0.25, 0.25, 0.3)  shadows off }
background (0.06, 0.07, 0.1)

sweep "trefoil" {
  curve catmull_rom  closed on  radius 0.42
  for i from 0 to 47 {
    let u = 2 * pi * i / 48
    point (sin(u) + 2 * sin(2 * u), cos(u) - 2 * cos(2 * u), -sin(3 * u))
  }
  material { color (0.85, 0.45, 0.15)  specular 0.5  shininess 60 }
  rotate (-20, 0, 0)
}

object "floor" {
  surface y + 3.2
  bounds  none
  material { color (0.5, 0.52, 0.55)  specular 0 }
}
