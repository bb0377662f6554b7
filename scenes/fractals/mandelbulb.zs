# The power-8 Mandelbulb (White and Nylander's triplex map z ← z⁸ + z₀),
# sphere traced by its customary distance estimate (docs/fractals.md).
#
#   zeroset render scenes/fractals/mandelbulb.zs -o mandelbulb.png

image  { width 640  height 480 }
camera { from (0.6, 1.9, -2.4)  at (0, -0.05, 0)  fov 40 }
light  { from (-4, 6, -5) }
light  { direction (1, -0.5, 1)  color (0.25, 0.25, 0.3)  shadows off }
background (0.08, 0.09, 0.14)

fractal "bulb" {
  kind mandelbulb
  power 8
  iterations 10
  rotate (-90, 0, 0)
  material { color (0.45, 0.62, 0.85)  specular 0.3  shininess 30 }
}
