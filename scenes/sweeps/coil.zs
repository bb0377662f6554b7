# A coiled tube: a sphere swept along a helix that tightens as it climbs,
# its radius shrinking from 0.25 to 0.07 — a B-spline through 97 points,
# each of its cubic pieces a swept sphere of linearly varying radius
# (van Wijk 1984; the survey's §3.4; docs/sweeps.md). A straight horn
# (a round cone: one linear piece) stands beside it.
#
#   zeroset render scenes/sweeps/coil.zs -o coil.png

image  { width 640  height 480 }
camera { from (0, 3.2, -8.5)  at (0, 1.4, 0)  fov 40 }
light  { from (-5, 9, -7) }
light  { direction (1, -0.4, 1)  color (0.25, 0.25, 0.3)  shadows off }
background (0.06, 0.07, 0.1)

sweep "coil" {
  curve b_spline
  for i from 0 to 96 {
    let u = i / 96
    let a = 2 * pi * 5 * u
    let r = 1.3 - 0.7 * u
    point (r * cos(a), 3.6 * u, r * sin(a))  radius 0.25 - 0.18 * u
  }
  material { color (0.75, 0.6, 0.2)  specular 0.7  shininess 80 }
  translate (-1, 0, 0)
}

sweep "horn" {
  curve linear
  point (0, 0, 0)  radius 0.45
  point (0.4, 2.4, 0.2)  radius 0.05
  material { color (0.2, 0.45, 0.75)  specular 0.5  shininess 60 }
  translate (2, 0, 0)
}

object "floor" {
  surface y + 0.3
  bounds  none
  material { color (0.5, 0.52, 0.55)  specular 0 }
}
