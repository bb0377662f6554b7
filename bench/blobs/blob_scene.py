#!/usr/bin/env python3
"""Writes one blob of N components as a zeroset scene and as a POV-Ray
scene, for bench/compare_blobs.sh and the scale table of docs/blobs.md.
POV-Ray's blob kernel is s(1 - r^2/R^2)^2, zeroset's `povray` kernel, so
the two render the same surface; the other kernels are written for zeroset
only.

Layouts (all fill about the same part of the image whatever N is):
  cloud     components at random in the cube [-5, 5]^3, radii like N^(-1/3)
  surface   components spread over a torus (R = 4, r = 1.5), radii like N^(-1/2)
  molecule  a seeded random walk of bonds 0.55 R long, scaled to fit
"""
import argparse
import math
import random


def cloud(n, rng):
    scale = (1000.0 / n) ** (1.0 / 3.0)
    for _ in range(n):
        yield [rng.uniform(-5.0, 5.0) for _ in range(3)], rng.uniform(0.6, 0.9) * scale


def surface(n, rng):
    radius = 0.6 * (1000.0 / n) ** 0.5
    for _ in range(n):
        a, b = rng.uniform(0, 2 * math.pi), rng.uniform(0, 2 * math.pi)
        w = 4.0 + 1.5 * math.cos(b)
        yield [w * math.cos(a), 1.5 * math.sin(b), w * math.sin(a)], radius


def molecule(n, rng):
    centres = [(0.0, 0.0, 0.0)]
    while len(centres) < n:
        x, y, z = centres[rng.randrange(len(centres))]
        theta, u = rng.uniform(0, 2 * math.pi), rng.uniform(-1, 1)
        s = math.sqrt(1 - u * u)
        c = (x + 0.55 * s * math.cos(theta), y + 0.55 * s * math.sin(theta), z + 0.55 * u)
        if all(math.dist(c, o) > 0.45 for o in centres[-200:]):
            centres.append(c)
    lo = [min(c[i] for c in centres) for i in range(3)]
    hi = [max(c[i] for c in centres) for i in range(3)]
    mid = [(a + b) / 2 for a, b in zip(lo, hi)]
    k = 9.0 / max(max(b - a for a, b in zip(lo, hi)), 1.0)
    for c in centres:
        yield [(c[i] - mid[i]) * k for i in range(3)], 0.75 * k


def vertical_fov(horizontal_degrees, width, height):
    half = math.radians(horizontal_degrees) / 2.0
    return math.degrees(2.0 * math.atan(math.tan(half) * height / width))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("n", type=int)
    p.add_argument("--layout", choices=["cloud", "surface", "molecule"], default="cloud")
    p.add_argument("--kernel", choices=["povray", "soft", "metaball", "blinn"], default="povray")
    p.add_argument("--threshold", type=float, default=0.5)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--width", type=int, default=512)
    p.add_argument("--height", type=int, default=512)
    p.add_argument("--pov", help="write the POV-Ray scene here (povray kernel only)")
    p.add_argument("--zs", help="write the zeroset scene here")
    a = p.parse_args()
    rng = random.Random(a.seed)
    components = list({"cloud": cloud, "surface": surface, "molecule": molecule}[a.layout](a.n, rng))
    angle = 50.0  # POV-Ray's camera angle is horizontal
    eye, light = (0.0, 6.0, -18.0), (-20.0, 25.0, -15.0)
    if a.pov:
        if a.kernel != "povray":
            p.error("POV-Ray's blob has the povray kernel only")
        with open(a.pov, "w") as f:
            f.write("#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n")
            f.write("camera { location <%g, %g, %g> look_at <0, 0, 0> angle %g right x*%d/%d }\n"
                    % (*eye, angle, a.width, a.height))
            f.write("light_source { <%g, %g, %g> color rgb 1 }\nbackground { color rgb <0.05, 0.05, 0.08> }\n" % light)
            f.write("blob { threshold %g\n" % a.threshold)
            for c, r in components:
                f.write("  sphere { <%.6f, %.6f, %.6f>, %.6f, 1 }\n" % (*c, r))
            f.write("  pigment { color rgb <0.3, 0.5, 0.8> } finish { ambient 0.1 diffuse 0.9 phong 0.4 phong_size 40 }\n}\n")
    if a.zs:
        with open(a.zs, "w") as f:
            f.write("# %d components, %s layout, %s kernel (bench/blobs/blob_scene.py %d --layout %s --kernel %s --seed %d)\n"
                    % (a.n, a.layout, a.kernel, a.n, a.layout, a.kernel, a.seed))
            f.write("image { width %d height %d }\n" % (a.width, a.height))
            f.write("camera { from (%g, %g, %g) at (0, 0, 0) fov %.6f }\n" % (*eye, vertical_fov(angle, a.width, a.height)))
            f.write("light { from (%g, %g, %g) }\nbackground (0.05, 0.05, 0.08)\n" % light)
            f.write('blob "%s" {\n  kernel %s  threshold %g\n' % (a.layout, a.kernel, a.threshold))
            for c, r in components:
                f.write("  component { center (%.6f, %.6f, %.6f) radius %.6f }\n" % (*c, r))
            f.write("  material { color (0.3, 0.5, 0.8) specular 0.4 shininess 40 }\n}\n")


if __name__ == "__main__":
    main()
