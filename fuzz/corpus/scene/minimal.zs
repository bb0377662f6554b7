object { surface x^2 + y^2 + z^2 - 1 }
