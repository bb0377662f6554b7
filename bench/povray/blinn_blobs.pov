// POV-Ray 3.7 twin of scenes/hart1993/blinn_blobs.zs (zeroset's default
// scene), for timing comparisons (bench/compare_povray.sh SCENE=blobs):
// the same Blinn blend h = 1 − e^(−f) − e^(−g) as an isosurface in the same
// box, the same floor, camera and lights, no anti-aliasing. POV-Ray needs a
// max_gradient: |∇h| ≤ 2·(2r e^(1−r²)) ≤ 4.67 (each term peaks at r = 1/√2),
// so 4.7 is the bound that cannot miss; accuracy 0.001 is its default.
// zeroset's fov 30 is vertical; POV-Ray's angle is horizontal:
// 2·atan(tan 15° · 4/3) = 39.3° at 4:3.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  perspective
  location <0, 2.5, -9>
  right x * image_width / image_height
  angle 39.3
  look_at <0, -0.2, 0>
}
light_source { <-10, 10, -10> color rgb 1 }
light_source { <-1000, 1000, -1000> color rgb <0.15, 0.15, 0.18> parallel point_at <0, 0, 0> shadowless }
background { color rgb <0.05, 0.05, 0.08> }
isosurface {
  function {
    1 - exp(-((x - 1.2) * (x - 1.2) + y * y + z * z - 1)) - exp(-((x + 1.2) * (x + 1.2) + y * y + z * z - 1))
  }
  contained_by { box { <-2.4, -1.2, -1.2>, <2.4, 1.2, 1.2> } }
  max_gradient 4.7
  accuracy 0.001
  pigment { color rgb <0.8, 0.3, 0.2> }
  finish { ambient 0.1 diffuse 0.9 specular 0.4 }
}
box {
  <-12, -1.4, -6>, <12, -1.3, 14>
  pigment { color rgb <0.75, 0.75, 0.72> }
  finish { ambient 0.1 diffuse 0.9 }
}
