#!/usr/bin/env python3
"""Expands the Barth sextic into monomials for POV-Ray's `polynomial` object.

f = 4(φ²x² − y²)(φ²y² − z²)(φ²z² − x²) − (1 + 2φ)(x² + y² + z² − 1)², φ the
golden ratio — the same equation as docs/algebraic-surfaces.md. Prints one
`xyz(i, j, k): c,` line per monomial, for bench/povray/barth_sextic.pov.
"""
import math

PHI = (1 + math.sqrt(5)) / 2


def mul(p, q):
    r = {}
    for (a, ca) in p.items():
        for (b, cb) in q.items():
            k = (a[0] + b[0], a[1] + b[1], a[2] + b[2])
            r[k] = r.get(k, 0.0) + ca * cb
    return r


def add(p, q, s=1.0):
    r = dict(p)
    for k, c in q.items():
        r[k] = r.get(k, 0.0) + s * c
    return r


X2, Y2, Z2, ONE = {(2, 0, 0): 1.0}, {(0, 2, 0): 1.0}, {(0, 0, 2): 1.0}, {(0, 0, 0): 1.0}
p2 = PHI * PHI
a = add({(2, 0, 0): p2}, Y2, -1)
b = add({(0, 2, 0): p2}, Z2, -1)
c = add({(0, 0, 2): p2}, X2, -1)
first = {k: 4 * v for k, v in mul(mul(a, b), c).items()}
s = add(add(add(X2, Y2), Z2), ONE, -1)
second = {k: (1 + 2 * PHI) * v for k, v in mul(s, s).items()}
f = add(first, second, -1)
terms = [(k, v) for k, v in sorted(f.items(), reverse=True) if abs(v) > 1e-12]
for i, (k, v) in enumerate(terms):
    print(f"  xyz({k[0]}, {k[1]}, {k[2]}): {v:.17g}" + ("," if i + 1 < len(terms) else ""))
