# Wyvill's soft objects (the survey's §3.2, eqs. 23-24, Figure 8) as a blob:
# the two spheres of Figure 1, each the kernel C(r²) with radius of influence
# R = 2 (magic = 1/2) and strength 2, at threshold 1:
#
#   h = 1 - 2 C(r1²) - 2 C(r2²)
#
# scenes/hart1993/soft_objects.zs writes the same field as an expression.

camera { from (0, 1.5, -9)  at (0, 0, 0)  fov 30 }
light  { from (-10, 10, -10) }

blob "soft" {
  kernel    soft
  threshold 1
  component { center ( 1.2, 0, 0)  radius 2  strength 2 }
  component { center (-1.2, 0, 0)  radius 2  strength 2 }
  material  { color (0.3, 0.7, 0.4)  specular 0.4 }
}
