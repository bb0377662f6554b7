# Silhouettes for cone antialiasing (docs/antialiasing.md): a ball, a tilted
# torus seen through its hole, and a cube with a ball taken out of it, over
# a slab floor whose bounds cut its far edge against the sky.
#
#   zeroset render scenes/antialiasing/silhouettes.zs --antialias cone
#
# One ray a pixel, widened to the cone of its footprint (Hart 1993), blends
# every silhouette — against the sky, the floor and the other objects. The
# cube's creases (its edges seen between two faces, the rim of the hollow)
# are not silhouettes, and no cone blends them. The key light casts no
# shadows here, so that the comparison with many samples measures edges of
# geometry alone; shadow edges are never blended by the cone.

image  { width 640  height 360 }
camera { from (0, 1.6, -7)  at (0, -0.1, 0)  fov 36 }
light  { from (-6, 8, -8)  shadows off }
light  { direction (1, -0.6, 0.8)  color (0.15, 0.15, 0.18)  shadows off }
background (0.12, 0.16, 0.32)

object "ball" {
  surface x^2 + y^2 + z^2 - 0.81
  bounds  box((-1, -1, -1), (1, 1, 1))
  translate (-2.1, 0, 0.4)
  material { color (0.85, 0.32, 0.22)  specular 0.4  shininess 50 }
}

object "ring" {
  surface (sqrt(x^2 + z^2) - 0.7)^2 + y^2 - 0.06
  bounds  box((-1, -0.3, -1), (1, 0.3, 1))
  rotate (-65, 20, 0)
  translate (0, 0.05, 0)
  material { color (0.9, 0.7, 0.2)  specular 0.5  shininess 60 }
}

difference "hollowed cube" {
  object { surface max(abs(x), abs(y), abs(z)) - 0.7  bounds box((-0.8, -0.8, -0.8), (0.8, 0.8, 0.8)) }
  object { surface x^2 + (y - 0.35)^2 + (z + 0.35)^2 - 0.36  bounds box((-0.7, -0.3, -1), (0.7, 1, 0.3)) }
  rotate (0, 30, 0)
  translate (2.1, -0.2, 0.3)
  material { color (0.25, 0.65, 0.35)  specular 0.3 }
}

object "floor" {
  cut on   # the bounds clip the solid on purpose: its far edge meets the sky
  surface y + 0.95
  bounds  box((-5, -1.1, -9), (5, -0.9, 4))
  material { color (0.78, 0.78, 0.74)  specular 0 }
}
