object { surface x^2 +  bounds box((1, 1, 1), (0, 0, 0)) method nope }
