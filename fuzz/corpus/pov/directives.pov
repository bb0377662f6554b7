#declare F = function(a, b) { a * a + b * b - 1 }
#macro Ball(P, S) sphere { P, S } #end
#declare I = 0;
#while (I < 3)
  object { Ball(<I, 0, 0>, 0.3) }
  #declare I = I + 1;
#end
#for (J, 0, 2) #if (mod(J, 2) = 0) Ball(<0, J, 0>, 0.2) #else Ball(<0, -J, 0>, 0.2) #end #end
#switch (2) #case (1) #declare C = 1; #break #range (2, 3) #declare C = 2; #break #else #declare C = 3; #end
#ifdef(C) isosurface { function { F(x, y) + z } } #end
#declare V = vrotate(<1, 0, 0>, <0, 90, 0>) * 2;
sphere { V, vlength(V) / 4 }
light_source { <1, 2, 3> color rgb 1 }
