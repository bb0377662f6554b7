# Wyvill's soft objects (the survey's §3.2, eqs. 23-24): the same two spheres
# as Figure 1, each replaced by the polynomial kernel C(r^2) with R = 2 and
# magic = 1/2, where r^2 is the squared distance from the sphere's centre:
#
#   C(s) = -s^3/144 + 17 s^2/144 - 11 s/18 + 1   for s < 4, and 0 beyond
#   h    = 1 - 2 C(r1^2) - 2 C(r2^2)
#
# C(4) = C'(4) = 0, so C(min(s, 4)) is C with its zero tail.

camera { from (0, 1.5, -9)  at (0, 0, 0)  fov 30 }
light  { from (-10, 10, -10) }

let r1 = (x - 1.2)^2 + y^2 + z^2
let r2 = (x + 1.2)^2 + y^2 + z^2
let s1 = min(r1, 4)
let s2 = min(r2, 4)

object "soft" {
  surface 1 - 2 * (-s1^3 / 144 + 17 * s1^2 / 144 - 11 * s1 / 18 + 1)
            - 2 * (-s2^3 / 144 + 17 * s2^2 / 144 - 11 * s2 / 18 + 1)
  bounds  box((-3.3, -2.1, -2.1), (3.3, 2.1, 2.1))
  material { color (0.3, 0.7, 0.4)  specular 0.4 }
}
