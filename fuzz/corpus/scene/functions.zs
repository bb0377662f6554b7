let s = sd_sphere(0.5, (x - 1, y, z))
let b = sd_box((0.4, 0.3, 0.2), (x, y, z))
object { surface smooth_union(s, b, 0.2) }
object { surface twist(torus(1, 0.2), (0, 0, 1), 1.5) }
object { surface atan2(y, x) + floor(z) + mod(x, 1) + clamp(y, -1, 1) + hypot(x, y) - 2 }
object { surface -1/x - 0.5  bounds box((-2, -2, -2), (2, 2, 2)) }
object { surface barth_sextic() }
object { surface monomial(1, 2, 2, 0) - 0.5 }
