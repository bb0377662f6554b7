# One unit sphere centred at (1.2, 0, 0): the survey's eq. (5). Along the
# survey's ray, x_o = (-4.905, -0.67, 0.364), x_d = (0.981, 0.174, 0.0872),
# it gives F(t) = t^2 - 12.1t + 36.9 (eqs. 8-11, to the survey's rounding).

camera { from (0, 1.5, -9)  at (1.2, 0, 0)  fov 30 }
light  { from (-10, 10, -10) }

object "sphere" {
  surface (x - 1.2)^2 + y^2 + z^2 - 1
  bounds  box((0.1, -1.1, -1.1), (2.3, 1.1, 1.1))
  material { color (0.3, 0.5, 0.8)  specular 0.4 }
}
