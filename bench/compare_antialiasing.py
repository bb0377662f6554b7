#!/usr/bin/env python3
"""Cone antialiasing against stratified samples (docs/antialiasing.md).

For each scene: renders a reference with 256 samples a pixel, then one ray a
pixel, one ray with --antialias cone, and 4 and 16 samples, each RUNS times
(median trace time from zeroset's summary line). Prints a Markdown table of
the trace times and of each image's difference from the reference in 8-bit
sRGB levels: the mean over all pixels, the mean over the edge pixels (where
one ray is more than 12 levels off) and the 99.9th percentile of the largest
channel difference.

  python3 bench/compare_antialiasing.py [SCENE.zs ...] [--size 640x360]
      [--runs 3] [--threads N] [--crop X,Y,W,H,ZOOM --crop-out FILE.png]
      [--columns NAME:X0-X1,...]

--crop writes the same crop of the one-ray, cone and 16-sample images side
by side, enlarged ZOOM times, as a PNG (for the docs). --columns also gives
the mean difference on the edge pixels of each band of columns [X0, X1) of
the first scene, one object's in silhouettes.zs, say. Needs ./build/zeroset
and numpy.
"""
import argparse
import os
import re
import statistics
import struct
import subprocess
import sys
import tempfile
import zlib

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ZEROSET = os.path.join(ROOT, "build", "zeroset")
DEFAULT_SCENES = ["scenes/antialiasing/silhouettes.zs", "scenes/hart1993/blinn_blobs.zs",
                  "scenes/blends/pipe_junction.zs"]
MODES = [("one ray", ["--spp", "1"]), ("cone", ["--spp", "1", "--antialias", "cone"]),
         ("4 samples", ["--spp", "4"]), ("16 samples", ["--spp", "16"])]


def read_ppm(path):
    data = open(path, "rb").read()
    fields, pos = [], 0
    while len(fields) < 4:  # magic, width, height, maximum; then one whitespace byte
        while data[pos:pos + 1].isspace():
            pos += 1
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    width, height = int(fields[1]), int(fields[2])
    return np.frombuffer(data[pos + 1:pos + 1 + width * height * 3], np.uint8).reshape(height, width, 3)


def write_png(path, pixels):
    height, width, _ = pixels.shape
    raw = b"".join(b"\x00" + pixels[y].tobytes() for y in range(height))

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) +
                  chunk(b"IEND", b""))


def render(scene, extra, out, size, threads):
    width, height = size.split("x")
    command = [ZEROSET, "render", scene, "-o", out, "--width", width, "--height", height] + extra
    if threads:
        command += ["--threads", str(threads)]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"compare_antialiasing: {' '.join(command)} failed:\n{result.stderr}")
    trace = re.search(r"trace ([0-9.]+) s", result.stderr)
    return float(trace.group(1))


def differences(image, reference, edges):
    levels = np.abs(image.astype(float) - reference.astype(float))
    largest = levels.max(axis=2)
    return levels.mean(), levels[edges].mean(), np.percentile(largest, 99.9)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("scenes", nargs="*", default=DEFAULT_SCENES)
    parser.add_argument("--size", default="640x360")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--crop")
    parser.add_argument("--crop-out")
    parser.add_argument("--columns")
    args = parser.parse_args()

    print("| scene | image | trace time | mean difference | on edges | 99.9th percentile |")
    print("|---|---|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as work:
        for scene in args.scenes:
            reference_path = os.path.join(work, "reference.ppm")
            render(scene, ["--spp", "256"], reference_path, args.size, args.threads)
            reference = read_ppm(reference_path)
            images = {}
            for name, extra in MODES:
                path = os.path.join(work, name.replace(" ", "_") + ".ppm")
                times = [render(scene, extra, path, args.size, args.threads) for _ in range(args.runs)]
                images[name] = (read_ppm(path), statistics.median(times))
            edges = np.abs(images["one ray"][0].astype(float) - reference.astype(float)).max(axis=2) > 12
            label = os.path.basename(scene)
            for name, (image, seconds) in images.items():
                mean, on_edges, high = differences(image, reference, edges)
                print(f"| {label} | {name} | {seconds:.3f} s | {mean:.3f} | {on_edges:.2f} | {high:.0f} |")
                label = ""
            print(f"| | ({edges.sum()} edge pixels) | | | | |")
            if args.columns:
                for band in args.columns.split(","):
                    name, columns = band.split(":")
                    x0, x1 = (int(v) for v in columns.split("-"))
                    inside = np.zeros_like(edges)
                    inside[:, x0:x1] = True
                    on_band = edges & inside
                    line = ", ".join(f"{n} {differences(images[n][0], reference, on_band)[1]:.2f}" for n in images)
                    print(f"| | {name}: {on_band.sum()} edge pixels: {line} | | | | |")
                args.columns = None  # the first scene's only
            if args.crop and args.crop_out:
                x, y, w, h, zoom = (int(v) for v in args.crop.split(","))
                tiles = [np.repeat(np.repeat(images[n][0][y:y + h, x:x + w], zoom, 0), zoom, 1)
                         for n in ("one ray", "cone", "16 samples")]
                gap = np.full((h * zoom, 4, 3), 255, np.uint8)
                write_png(args.crop_out, np.concatenate([tiles[0], gap, tiles[1], gap, tiles[2]], 1))
                args.crop_out = None  # the first scene's only


if __name__ == "__main__":
    main()
