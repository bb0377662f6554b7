# 100 000 POV-Ray-kernel components at random in a 10-unit cube: the blob
# primitive's scale test (docs/blobs.md). The loop draws each center from a
# hash of its index (the fractional part of a large sine), so the cloud is
# the same on every machine without a 100 000-line file.

image  { width 512  height 512 }
camera { from (0, 6, -18)  at (0, 0, 0)  fov 50 }
light  { from (-20, 25, -15) }
background (0.05, 0.05, 0.08)

blob "cloud" {
  kernel povray  threshold 0.5
  for i from 0 to 99999 {
    let u = mod(abs(sin(i * 12.9898 + 78.233)) * 43758.5453, 1)
    let v = mod(abs(sin(i * 39.3468 + 11.135)) * 43758.5453, 1)
    let w = mod(abs(sin(i * 73.1563 + 52.235)) * 43758.5453, 1)
    component { center (10 * u - 5, 10 * v - 5, 10 * w - 5)  radius 0.16 }
  }
  material { color (0.3, 0.5, 0.8)  specular 0.4  shininess 40 }
}
