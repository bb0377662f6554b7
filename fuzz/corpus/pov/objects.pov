#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0.5 }
#declare R = 0.5;
#declare T = texture { pigment { color rgb <1, 0.5, 0.2> } finish { phong 0.8 phong_size 30 ambient 0.2 } }
camera { location <0, 2, -6> look_at <0, 0, 0> right x*image_width/image_height angle 45 }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <5, 1, -3> color rgb 0.3 shadowless }
background { color rgb <0.1, 0.1, 0.2> }
sphere { <0, 0, 0>, R texture { T } }
box { <-1, -1, -1>, <1, 1, 1> scale 0.3 rotate <10, 20, 30> translate x }
cylinder { 0, y, 0.2 open pigment { color red 1 } }
cone { 0, 0.3, <0, 1, 0>, 0.1 translate -x }
torus { 1, 0.2 rotate 90*x }
plane { y, -1 pigment { checker color rgb 1 color rgb 0 } }
quartic { <4, 0, 0, -4, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
           0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0> bounded_by { sphere { 0, 2 } } }
poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0, -1> clipped_by { plane { x, 0.5 } } }
polynomial { 2, xyz(2, 0, 0): 1, xyz(0, 2, 0): 1, xyz(0, 0, 0): -1 }
blob { threshold 0.5 sphere { 0, 1, 1 } cylinder { -x, x, 0.5, strength 2 } component 1, 0.5, <0, 1, 0> }
isosurface { function { x*x + y*y + z*z - 1 } contained_by { sphere { 0, 2 } } max_gradient 4 open }
intersection { sphere { 0, 1 } sphere { x, 1 inverse } }
difference { box { -1, 1 } sphere { 0, 1.2 } }
union { sphere { 0, 0.1 } sphere { y, 0.1 } translate z }
