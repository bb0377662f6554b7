#!/usr/bin/env python3
"""Writes a scene of an N-atom "exp molecule" (default 50): Blinn's blobby
model (survey eq. 12) as one expression, f = 1 − Σ exp(−4 (|p − cᵢ|² − 0.25)),
each atom alone a ball of radius 0.5, placed along a seeded random walk of
0.55-long bonds (so neighbours blend). With --blob, the same field as a
Blinn blob (radius 0.5, blobbiness −1: e^(−(u − 1)) with u = r²/0.25).
Used by bench/complex_models.sh."""
import math
import random
import sys

arguments = [a for a in sys.argv[1:] if a != "--blob"]
as_blob = "--blob" in sys.argv[1:]
atoms = int(arguments[0]) if arguments else 50
rng = random.Random(1993)
centres = [(0.0, 0.0, 0.0)]
while len(centres) < atoms:
    x, y, z = centres[rng.randrange(len(centres))]
    theta, u = rng.uniform(0, 2 * math.pi), rng.uniform(-1, 1)
    s = math.sqrt(1 - u * u)
    c = (x + 0.55 * s * math.cos(theta), y + 0.55 * s * math.sin(theta), z + 0.55 * u)
    if all(math.dist(c, o) > 0.45 for o in centres):
        centres.append(c)
lo = [min(c[i] for c in centres) - 1.2 for i in range(3)]
hi = [max(c[i] for c in centres) + 1.2 for i in range(3)]
mid = [(a + b) / 2 for a, b in zip(lo, hi)]
size = max(b - a for a, b in zip(lo, hi))
terms = " +\n    ".join(
    f"exp(-4 * ((x - {x:.4f})^2 + (y - {y:.4f})^2 + (z - {z:.4f})^2 - 0.25))" for x, y, z in centres)
components = "\n".join(
    f"  component {{ center ({x:.4f}, {y:.4f}, {z:.4f})  radius 0.5  blobbiness -1 }}" for x, y, z in centres)
body = f"""object "molecule" {{
  surface 1 - (
    {terms})
  bounds box(({lo[0]:.3f}, {lo[1]:.3f}, {lo[2]:.3f}), ({hi[0]:.3f}, {hi[1]:.3f}, {hi[2]:.3f}))
  material {{ color (0.3, 0.5, 0.8)  specular 0.4  shininess 40 }}
}}""" if not as_blob else f"""blob "molecule" {{
  kernel blinn  threshold 1
{components}
  material {{ color (0.3, 0.5, 0.8)  specular 0.4  shininess 40 }}
}}"""
print(f"""# A {atoms}-atom exp molecule, written by bench/models/molecule.py.
image  {{ width 640  height 480 }}
camera {{ from ({mid[0]:.3f}, {mid[1] + 0.4 * size:.3f}, {mid[2] - 1.6 * size:.3f})  at ({mid[0]:.3f}, {mid[1]:.3f}, {mid[2]:.3f})  fov 40 }}
light  {{ from ({mid[0] - size:.3f}, {mid[1] + 2 * size:.3f}, {mid[2] - 2 * size:.3f}) }}

{body}""")
