# A ring of six atoms joined by bonds, each atom with an outward bond to a
# smaller one — spheres and POV-Ray's cylinder components in one blob, so
# bonds and atoms melt together (docs/blobs.md). A cylinder component is
# the kernel of the distance to its segment: round at both ends.

image  { width 640  height 480 }
camera { from (0, 7, -10)  at (0, 0, 0)  fov 45 }
light  { from (-10, 20, -12) }
background (0.06, 0.06, 0.09)

blob "ring" {
  kernel povray  threshold 0.5
  for i from 0 to 5 {
    let a = i * pi / 3
    let b = (i + 1) * pi / 3
    let atom = (2.4 * cos(a), 0, 2.4 * sin(a))
    let next = (2.4 * cos(b), 0, 2.4 * sin(b))
    let outer = (4.2 * cos(a), 0, 4.2 * sin(a))
    component { center atom  radius 1.3  strength 1 }
    component { from atom  to next  radius 0.7  strength 0.7 }
    component { from atom  to outer  radius 0.6  strength 0.7 }
    component { center outer  radius 0.9  strength 1 }
  }
  material { color (0.85, 0.55, 0.3)  specular 0.5  shininess 60 }
}
