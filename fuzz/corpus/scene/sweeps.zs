sweep "knot" { curve catmull_rom closed on radius 0.3 for i from 0 to 7 { let u = 2 * pi * i / 8  point (cos(u), sin(u), 0.3 * sin(2 * u)) } }
sweep { curve linear point (0, 0, 0) radius 0.5 point (1, 1, 0) radius 0 }
sweep { curve bezier radius 0.2 point (0, 0, 0) point (1, 2, 0) point (2, -2, 0) point (3, 0, 0) translate (0, 0, 1) }
difference { sweep { curve b_spline radius 0.4 point (-1, 0, 0) point (0, 0, 0) point (1, 0, 0) point (2, 1, 0) } object { surface x^2 + y^2 + z^2 - 0.2 } }
