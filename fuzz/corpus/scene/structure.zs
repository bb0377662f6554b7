let r = 0.5
let blob = exp(-4 * (x^2 + y^2 + z^2)) + exp(-4 * ((x - 0.8)^2 + y^2 + z^2)) - 0.4
shape peg(h) { object { surface max(abs(x) - 0.1, abs(y) - h)  bounds box((-0.2, -h - 0.1, -0.2), (0.2, h + 0.1, 0.2)) } }
group {
  translate (0, 1, 0)
  rotate (0, 45, 0)
  scale (1, 2, 1)
  object { surface blob  bounds box((-1, -1, -1), (2, 1, 1)) }
  for i from 0 to 3 step 1 {
    instance peg(0.2 + 0.1 * i) { translate (i, 0, 0)  material { color (1, 0, 0) } }
  }
}
difference {
  object { surface max(max(abs(x), abs(y)), abs(z)) - 1 }
  intersection {
    object { surface x^2 + y^2 - r^2 }
    object { surface z^2 - 4  shear { xy 0.1  zx -0.2 } }
  }
}
union { object { surface x^2 + y^2 + z^2 - 0.1  matrix (1,0,0,0, 0,1,0,0, 0,0,1,0) } }
