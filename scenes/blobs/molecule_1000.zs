# A 1 000-atom chain molecule: 500 backbone atoms a bond apart along a
# trefoil knot, each with a side atom turning around the chain, as soft
# objects (Wyvill's kernel, eq. 23) that blend where neighbours overlap.
# docs/blobs.md times it.

image  { width 640  height 480 }
camera { from (0, 4, -40)  at (0, 0, 0)  fov 40 }
light  { from (-40, 50, -40) }
light  { direction (1, -0.5, 1)  color (0.2, 0.2, 0.25)  shadows off }
background (0.04, 0.05, 0.07)

blob "molecule" {
  kernel soft  threshold 0.5
  for i from 0 to 499 {
    let a = i * 2 * pi / 500
    let p = (sin(a) + 2 * sin(2 * a), cos(a) - 2 * cos(2 * a), -sin(3 * a)) * 5
    component { center p  radius 0.8 }
    component { center p + (cos(30 * a), sin(30 * a), sin(11 * a)) * 0.9  radius 0.75 }
  }
  material { color (0.85, 0.55, 0.3)  specular 0.5  shininess 60 }
}
