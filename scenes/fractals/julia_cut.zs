# A quaternion Julia set cut by a plane, the classic picture of Hart, Sandin
# and Kauffman's "Ray tracing deterministic 3-D fractals" (1989): the set of
# z ← z² + c over quaternions, sliced at k = 0, sphere traced by its distance
# estimate (docs/fractals.md); the cut shows its solid inside.
#
#   zeroset render scenes/fractals/julia_cut.zs -o julia_cut.png

image  { width 640  height 480 }
camera { from (1.6, 2.2, -2.6)  at (0, 0, 0)  fov 40 }
light  { from (-4, 6, -5) }
light  { direction (1, -0.5, 1)  color (0.25, 0.25, 0.3)  shadows off }
background (0.08, 0.09, 0.14)

intersection "cut julia" {
  fractal "julia" {
    kind julia
    c (-0.8, 0.16, 0)  # c = −0.8 + 0.16i + 0j + 0k
    slice 0
    iterations 30
    material { color (0.86, 0.62, 0.3)  specular 0.4  shininess 30 }
  }
  object "cut" {       # keep z ≥ 0: the near half is cut away
    surface -z
    bounds  none
    material { color (0.75, 0.22, 0.18)  specular 0.1 }
  }
  rotate (0, 30, 0)
}
