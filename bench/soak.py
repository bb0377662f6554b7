#!/usr/bin/env python3
"""Soak test: renders thousands of generated and mutated scenes at 16×12 and
checks that each one ends well (docs/fuzzing.md).

Every run of `zeroset render` must either write an image whose pixels are all
finite (exit 0) or print an error and exit 1 without writing anything. The
script counts what does not: crashes (a signal, or a sanitizer's abort),
hangs (past the time cap), images with a non-finite pixel, failures that
left an output file or said nothing, and temporary files left behind. Each
such input is kept in the findings folder. It is a benchmark-style job,
not part of the quick suite:

    bench/soak.py --count 3000 --seed 1      # ./build/zeroset, 2 at a time

Scenes come from a small generator (random surfaces, bounds, methods,
cameras, lights, transforms and CSG, with extreme numbers on purpose) and
from mutations of the project's own scenes and seed corpus.
"""
import argparse
import collections
import concurrent.futures
import os
import math
import random
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
WIDTH, HEIGHT = 16, 12

EXTREMES = ["0", "1e-320", "1e-300", "1e-8", "1e8", "1e100", "1e300", "1e308", "0/0", "1/0"]
METHODS = ["auto", "sphere", "interval", "lg", "polynomial", "newton", "regula_falsi", "bisection"]


def number(rng):
    if rng.random() < 0.1:
        return rng.choice(EXTREMES)
    return repr(round(rng.uniform(0.05, 3.0), 3))


def expression(rng, depth):
    if depth <= 0 or rng.random() < 0.25:
        return rng.choice(["x", "y", "z", number(rng)])
    a = expression(rng, depth - 1)
    b = expression(rng, depth - 1)
    return rng.choice([
        f"({a} + {b})", f"({a} - {b})", f"({a} * {b})", f"({a} / {b})", f"({a})^{rng.randint(0, 5)}",
        f"-{a}", f"sin({a})", f"cos({a})", f"exp({a})", f"log({a})", f"sqrt({a})", f"abs({a})",
        f"tan({a})", f"atan({a})", f"floor({a})", f"min({a}, {b})", f"max({a}, {b})",
        f"atan2({a}, {b})", f"hypot({a}, {b})", f"mod({a}, {b})", f"clamp({a}, -1, 1)",
    ])


def surface(rng):
    r = number(rng)
    shapes = [
        f"x^2 + y^2 + z^2 - {r}",
        f"torus({r}, {number(rng)})",
        f"sd_sphere({r}, (x, y, z))",
        f"sd_box(({r}, {number(rng)}, {number(rng)}), (x, y, z))",
        f"1 - exp(-((x - 1)^2 + y^2 + z^2)) - exp(-((x + 1)^2 + y^2 + z^2))",
        "barth_sextic()",
        f"monomial(1, {rng.randint(0, 6)}, {rng.randint(0, 6)}, {rng.randint(0, 6)}) - {r}",
        f"x^4 + y^4 + z^4 - {r}",
        f"twist(torus(1, 0.3), (0, 0, 1), {number(rng)})",
        f"taper(sd_box((0.5, 0.5, 1), (x, y, z)), (0, 0, 1), {number(rng)})",
        f"bend(torus(1, 0.2), (1, 0, 0), (0, 1, 0), {number(rng)})",
    ]
    base = rng.choice(shapes)
    roll = rng.random()
    if roll < 0.35:
        return base
    if roll < 0.7:
        return f"{base} + {number(rng)} * {expression(rng, 2)}"
    if roll < 0.85:
        return f"smooth_union({base}, {rng.choice(shapes)}, {number(rng)})"
    return expression(rng, 4)


def vector(rng, scale=3.0):
    if rng.random() < 0.1:
        return f"({rng.choice(EXTREMES)}, {number(rng)}, {number(rng)})"
    return "(" + ", ".join(repr(round(rng.uniform(-scale, scale), 3)) for _ in range(3)) + ")"


def colour(rng):
    if rng.random() < 0.05:
        return f"({rng.choice(EXTREMES)}, 1, 1)"
    return "(" + ", ".join(repr(round(rng.uniform(0, 1.5), 3)) for _ in range(3)) + ")"


def bounds(rng):
    half = rng.choice(["1", "2", "3", "1e3", "1e8", "1e100", "1e300", number(rng)])
    if rng.random() < 0.03:
        return "bounds none"  # an error unless the surface is a plane
    return rng.choice(["", "", f"bounds box((-{half}, -{half}, -{half}), ({half}, {half}, {half}))",
                       f"bounds sphere((0, 0, 0), {half})"])


def transform(rng):
    return rng.choice([
        "", "", f"translate {vector(rng)}", f"rotate {vector(rng, 180)}", f"scale {number(rng)}",
        f"scale {vector(rng)}", f"shear {{ xy {number(rng)} }}",
    ])


def object_block(rng):
    method = rng.choice(METHODS + [""] * 4)
    parts = [f"surface {surface(rng)}", bounds(rng), transform(rng)]
    if method:
        parts.append(f"method {method}")
    if rng.random() < 0.3:
        parts.append(f"material {{ color {colour(rng)}  specular {number(rng)} }}")
    return "object { " + "  ".join(p for p in parts if p) + " }"


def generated_scene(rng):
    lines = []
    distance = rng.choice(["4", "6", "10", "30", "1e6", "1e12"])
    lines.append(f"camera {{ from (0, 1, -{distance})  at {vector(rng, 0.5)}  fov {rng.choice(['1', '30', '45', '179'])} }}")
    for _ in range(rng.randint(0, 2)):
        if rng.random() < 0.5:
            lines.append(f"light {{ from {vector(rng, 10)}  color {colour(rng)} }}")
        else:
            lines.append(f"light {{ direction {vector(rng, 1)} }}")
    if rng.random() < 0.2:
        lines.append(f"ambient {colour(rng)}")
    objects = [object_block(rng) for _ in range(rng.randint(1, 3))]
    wrapper = rng.choice(["", "", "group", "union", "intersection", "difference"])
    if wrapper and len(objects) >= 2:
        lines.append(f"{wrapper} {{ {transform(rng)}\n  " + "\n  ".join(objects) + "\n}")
    else:
        lines.extend(objects)
    return "\n".join(lines) + "\n"


def seed_scenes():
    seeds = []
    for folder in (ROOT / "scenes", ROOT / "fuzz" / "corpus" / "scene"):
        for path in sorted(folder.rglob("*.zs")):
            text = path.read_text(encoding="utf-8", errors="replace")
            # Keep includes and models found: name them by absolute path.
            text = re.sub(r'"([^"\n]+\.(?:zs|vm))"',
                          lambda m: f'"{(path.parent / m.group(1)).resolve()}"'
                          if (path.parent / m.group(1)).exists() else m.group(0), text)
            seeds.append(text)
    return seeds


def mutated_scene(rng, seeds):
    text = rng.choice(seeds)
    for _ in range(rng.randint(1, 4)):
        numbers = list(re.finditer(r"\d+(?:\.\d*)?(?:[eE][+-]?\d+)?", text))
        roll = rng.random()
        if roll < 0.4 and numbers:
            m = rng.choice(numbers)
            text = text[:m.start()] + rng.choice(EXTREMES + [number(rng)]) + text[m.end():]
        elif roll < 0.55 and text:
            i = rng.randrange(len(text))
            text = text[:i] + text[i + rng.randint(1, 20):]
        elif roll < 0.7 and text:
            i = rng.randrange(len(text))
            text = text[:i] + rng.choice(["(", ")", "{", "}", ",", "^", "/", "-", "\0", "\r", "é", " x "]) + text[i:]
        elif roll < 0.85:
            lines = text.splitlines()
            if lines:
                i = rng.randrange(len(lines))
                lines.insert(i, lines[rng.randrange(len(lines))])
                text = "\n".join(lines)
        else:
            text = text[:rng.randrange(len(text) + 1)]
    return text


def finite_pfm(path):
    """Whether the PFM is whole and every pixel finite (a malformed one is a finding)."""
    try:
        header = path.read_bytes().split(b"\n", 3)
        if len(header) < 4 or header[0] != b"PF":
            return False
        width, height = map(int, header[1].split())
        endian = "<" if float(header[2]) < 0 else ">"
        count = width * height * 3
        pixels = struct.unpack(f"{endian}{count}f", header[3][:4 * count])
    except (ValueError, struct.error):
        return False
    return all(math.isfinite(p) for p in pixels)


def run_one(binary, index, text, seconds, megabytes, findings, keep, slow):
    with tempfile.TemporaryDirectory(prefix="soak-") as folder:
        scene = Path(folder) / "scene.zs"
        image = Path(folder) / "out.pfm"
        scene.write_bytes(text.encode("utf-8", errors="replace"))
        command = [binary, "render", str(scene), "-o", str(image), "--width", str(WIDTH),
                   "--height", str(HEIGHT), "--threads", "1", "--quiet"]
        if megabytes > 0:  # prlimit, not preexec_fn: the runs are started from threads
            command = ["prlimit", f"--as={megabytes << 20}", "--"] + command
        started = time.monotonic()
        try:
            done = subprocess.run(command, capture_output=True, timeout=seconds)
            code, stderr = done.returncode, done.stderr.decode("utf-8", errors="replace")
        except subprocess.TimeoutExpired:
            code, stderr = None, ""
        elapsed = time.monotonic() - started
        leftovers = [p.name for p in Path(folder).iterdir() if p.name not in ("scene.zs", "out.pfm")]
        if code is None:
            verdict = "hang"
        elif code < 0 or code >= 128:
            verdict = "crash"
        elif code == 0:
            verdict = "rendered" if image.exists() and finite_pfm(image) else "non-finite or missing image"
        elif code == 1:
            verdict = "error" if stderr.strip() and not image.exists() else "error without message or with output"
        else:
            verdict = f"exit {code}"
        if leftovers:
            verdict = "leftover files"
        slow_one = slow is not None and elapsed > slow and verdict in ("rendered", "error")
        if verdict not in ("rendered", "error") or (keep and re.search(keep, stderr)) or slow_one:
            kept = findings / f"{index:05d}-{'slow' if slow_one else verdict.split()[0]}.zs"
            shutil.copy(scene, kept)
            (kept.with_suffix(".stderr")).write_text(stderr)
        first_line = stderr.strip().splitlines()[0] if stderr.strip() else ""
        message = re.sub(r"^.*?:\d+:\d+: ", "", first_line)[:70]
        return verdict, elapsed, message


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--count", type=int, default=3000)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--seconds", type=float, default=60, help="time cap per render")
    parser.add_argument("--memory-mb", type=int, default=4096,
                        help="address-space cap per render; 0 for none (needed for a sanitizer build)")
    parser.add_argument("--binary", default=str(ROOT / "build" / "zeroset"))
    parser.add_argument("--findings", default=str(ROOT / "build" / "soak-findings"))
    parser.add_argument("--keep", help="also keep the scenes whose messages match this regular expression")
    parser.add_argument("--slow", type=float,
                        help="also keep the scenes whose render or error takes longer than this many seconds")
    args = parser.parse_args()

    findings = Path(args.findings)
    findings.mkdir(parents=True, exist_ok=True)
    rng = random.Random(args.seed)
    seeds = seed_scenes()
    scenes = [generated_scene(rng) if i % 2 == 0 else mutated_scene(rng, seeds) for i in range(args.count)]

    verdicts = collections.Counter()
    messages = collections.Counter()
    times = []
    started = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = [pool.submit(run_one, args.binary, i, text, args.seconds, args.memory_mb, findings,
                               args.keep, args.slow)
                   for i, text in enumerate(scenes)]
        for future in concurrent.futures.as_completed(futures):
            verdict, elapsed, message = future.result()
            verdicts[verdict] += 1
            times.append(elapsed)
            if verdict == "error":
                messages[message] += 1
    times.sort()

    print(f"soak: {args.count} scenes (seed {args.seed}) in {time.monotonic() - started:.0f} s, "
          f"median {times[len(times) // 2]:.3f} s, slowest {times[-1]:.2f} s per render")
    for verdict, count in verdicts.most_common():
        print(f"  {verdict:40s} {count}")
    print("  most frequent errors:")
    for message, count in messages.most_common(12):
        print(f"    {count:5d}  {message}")
    if args.slow is not None:
        slow = sum(1 for t in times if t > args.slow)
        print(f"  {slow} runs slower than {args.slow:g} s, kept in {findings}")
    bad = sum(c for v, c in verdicts.items() if v not in ("rendered", "error"))
    if bad:
        print(f"soak: {bad} findings, kept in {findings}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
