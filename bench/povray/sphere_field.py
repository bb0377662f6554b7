#!/usr/bin/env python3
"""Writes the same field of N random spheres as a POV-Ray scene and as a
zeroset scene, for bench/compare_spheres.sh. The spheres fill the cube
[-5, 5]^3 with radii shrinking like N^(-1/3), so that every N covers about
the same part of the image; the seed fixes the field.

zeroset styles: `instances` places one shared unit-sphere shape N times
(translate and scale), `objects` writes N separate objects, each its own
polynomial (x - a)^2 + ... - r^2 with its own bounds.
"""
import argparse
import math
import random


def spheres(n, seed):
    rng = random.Random(seed)
    scale = (1000.0 / n) ** (1.0 / 3.0)
    for _ in range(n):
        c = [rng.uniform(-5.0, 5.0) for _ in range(3)]
        r = rng.uniform(0.15, 0.35) * scale
        color = [rng.uniform(0.2, 0.9) for _ in range(3)]
        yield c, r, color


def vertical_fov(horizontal_degrees, width, height):
    half = math.radians(horizontal_degrees) / 2.0
    return math.degrees(2.0 * math.atan(math.tan(half) * height / width))


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("n", type=int)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--width", type=int, default=400)
    p.add_argument("--height", type=int, default=300)
    p.add_argument("--pov", help="write the POV-Ray scene here")
    p.add_argument("--zs", help="write the zeroset scene here")
    p.add_argument("--style", choices=["instances", "objects"], default="instances")
    a = p.parse_args()
    field = list(spheres(a.n, a.seed))
    angle = 40.0  # POV-Ray's camera angle is horizontal
    if a.pov:
        with open(a.pov, "w") as f:
            f.write("#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n")
            f.write("camera { location <0, 0, -18> look_at <0, 0, 0> angle %g right x*%d/%d }\n"
                    % (angle, a.width, a.height))
            f.write("light_source { <-20, 20, -20> color rgb 1 }\nbackground { color rgb <0.05, 0.05, 0.08> }\n")
            for c, r, col in field:
                f.write("sphere { <%.6f, %.6f, %.6f>, %.6f pigment { color rgb <%.3f, %.3f, %.3f> } "
                        "finish { ambient 0.1 diffuse 0.9 phong 0.3 phong_size 40 } }\n" % (*c, r, *col))
    if a.zs:
        with open(a.zs, "w") as f:
            f.write("# %d random spheres (bench/povray/sphere_field.py %d --seed %d --style %s)\n"
                    % (a.n, a.n, a.seed, a.style))
            f.write("image { width %d height %d }\n" % (a.width, a.height))
            f.write("camera { from (0, 0, -18) at (0, 0, 0) fov %.6f }\n" % vertical_fov(angle, a.width, a.height))
            f.write("light { from (-20, 20, -20) }\nbackground (0.05, 0.05, 0.08)\n")
            if a.style == "instances":
                f.write("shape ball { object { surface x^2 + y^2 + z^2 - 1  bounds sphere((0, 0, 0), 1.001) } }\n")
                for c, r, col in field:
                    f.write("instance ball { scale %.6f translate (%.6f, %.6f, %.6f) material { color (%.3f, %.3f, %.3f) } }\n"
                            % (r, *c, *col))
            else:
                for c, r, col in field:
                    f.write("object { surface (x - %.6f)^2 + (y - %.6f)^2 + (z - %.6f)^2 - %.6f  "
                            "bounds sphere((%.6f, %.6f, %.6f), %.6f)  material { color (%.3f, %.3f, %.3f) } }\n"
                            % (*c, r * r, *c, r * 1.001, *col))


if __name__ == "__main__":
    main()
