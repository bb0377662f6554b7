object { surface x^4 + y^4 + z^4 - 1  bounds box((-2, -2, -2), (2, 2, 2))  method polynomial  solver sturm }
object { surface torus(1, 0.3)  method interval  bounds box((-2, -2, -1), (2, 2, 1)) }
object { surface sin(x) * cos(y) + sin(y) * cos(z) + sin(z) * cos(x)  method lg  bounds box((-3, -3, -3), (3, 3, 3)) }
object { surface x - 0.5 + 0 * y  method newton }
object { surface exp(-(x^2 + y^2 + z^2)) - 0.3  method regula_falsi }
object { surface y + 1.5  bounds none }
