object { surface 0/0 + x }
