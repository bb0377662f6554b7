#!/usr/bin/python3
"""POV-Ray's own sample scenes rendered by POV-Ray 3.7 and by zeroset's
importer (docs/povray.md), side by side in the same run: the image
difference, the difference of the hit masks, and the times.

The corpus is every scene of Debian's povray-examples under
objects/quartic/, plus objects/blob*.pov and objects/isosurfaces.pov, read
where the package installed them. Both renderers draw the same size with one
sample a pixel (POV-Ray -A), on the same threads.

  bench/compare_povray_corpus.py [--zeroset build/zeroset] [--size 640x480]
                                 [--threads 2] [--repeat 3] [--keep DIR] [SCENE …]

For each scene:
  - mean |Δ| and the 99th percentile of the largest channel difference per
    pixel, in 8-bit levels, between the two images;
  - the hit mask difference: both render a copy of the scene that ends with
    `background { rgb <1, 0, 1> }`, and a pixel is a miss where it is that
    magenta exactly; the share of pixels where the two masks disagree;
  - POV-Ray's own "Trace Time" and zeroset's render time (its summary line's
    total: preparing the objects and tracing, without reading the scene),
    each the median of --repeat runs (the two renderers alternated), and
    their ratio.
Prints a Markdown table; --keep DIR keeps the images (pov_X.ppm, zs_X.ppm).
"""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

MAGENTA = (255, 0, 255)


def find_corpus():
    """The corpus's scenes, from where povray-examples installed them."""
    try:
        files = subprocess.run(["dpkg", "-L", "povray-examples"], capture_output=True, text=True, check=True).stdout.split()
    except (OSError, subprocess.CalledProcessError):
        sys.exit("povray-examples is not installed (apt-get install povray-examples)")
    scenes = [f for f in files if re.search(r"/objects/quartic/[^/]+\.pov$", f)]
    scenes += [f for f in files if re.search(r"/objects/(blob[^/]*|isosurfaces)\.pov$", f)]
    return sorted(set(scenes))


def read_ppm(path):
    with open(path, "rb") as f:
        data = f.read()
    fields = []
    pos = 0
    while len(fields) < 4:  # P6, width, height, maxval (comments skipped)
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos) + 1
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    pos += 1
    width, height, maxval = int(fields[1]), int(fields[2]), int(fields[3])
    if fields[0] != b"P6":
        raise ValueError(f"{path}: not a binary PPM")
    step = 2 if maxval > 255 else 1
    pixels = data[pos:pos + width * height * 3 * step]
    if step == 2:  # 16-bit: keep the high bytes, scaled to 8 bits
        pixels = bytes(round(((pixels[i] << 8) | pixels[i + 1]) * 255 / maxval) for i in range(0, len(pixels), 2))
    return width, height, pixels


def image_difference(a, b):
    (wa, ha, pa), (wb, hb, pb) = a, b
    if (wa, ha) != (wb, hb):
        raise ValueError(f"sizes differ: {wa}x{ha} and {wb}x{hb}")
    total = 0
    largest = []
    for i in range(0, len(pa), 3):
        d = [abs(pa[i + k] - pb[i + k]) for k in range(3)]
        total += sum(d)
        largest.append(max(d))
    largest.sort()
    return total / len(pa), largest[min(len(largest) - 1, int(0.99 * len(largest)))]


def mask_difference(a, b):
    (_, _, pa), (_, _, pb) = a, b
    differ = 0
    for i in range(0, len(pa), 3):
        miss_a = tuple(pa[i:i + 3]) == MAGENTA
        miss_b = tuple(pb[i:i + 3]) == MAGENTA
        differ += miss_a != miss_b
    return differ / (len(pa) // 3)


def run_povray(scene, out, width, height, threads, include_dir):
    cmd = ["povray", f"+I{scene}", f"+O{out}", "+FP", f"+W{width}", f"+H{height}", "-D", "-A", f"+WT{threads}",
           f"+L{include_dir}"]
    r = subprocess.run(cmd, capture_output=True, text=True, cwd=os.path.dirname(scene))
    found = re.search(r"Trace Time:.*\(([\d.]+) seconds\)", r.stderr + r.stdout)
    if r.returncode != 0 or not found:
        raise RuntimeError("POV-Ray failed on " + scene + ":\n" + (r.stderr + r.stdout)[-2000:])
    return float(found.group(1))


def run_zeroset(zeroset, scene, out, width, height, threads, include_dir):
    cmd = [zeroset, "render", scene, "-o", out, "--width", str(width), "--height", str(height), "--threads",
           str(threads), "--include-path", include_dir]
    r = subprocess.run(cmd, capture_output=True, text=True, cwd=os.path.dirname(scene))
    found = re.search(r"threads: ([\d.]+) s", r.stderr)
    if r.returncode != 0 or not found:
        raise RuntimeError("zeroset failed on " + scene + ":\n" + r.stderr[-2000:])
    warnings = [line for line in r.stderr.splitlines() if line.startswith("zeroset: warning:")]
    return float(found.group(1)), warnings


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--zeroset", default=os.path.join(os.path.dirname(__file__), "..", "build", "zeroset"))
    parser.add_argument("--size", default="640x480")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--keep", help="a folder to keep the images in")
    parser.add_argument("scenes", nargs="*", help="scenes to compare (default: the whole corpus)")
    args = parser.parse_args()
    if shutil.which("povray") is None:
        sys.exit("povray is not installed (apt-get install povray)")
    width, height = (int(v) for v in args.size.split("x"))
    zeroset = os.path.abspath(args.zeroset)
    scenes = [os.path.abspath(s) for s in args.scenes] or find_corpus()
    work = tempfile.mkdtemp(prefix="zeroset-povray-")
    keep = args.keep
    if keep:
        os.makedirs(keep, exist_ok=True)
    print(f"| scene | mean \\|Δ\\| | 99th pct | hit masks differ | POV-Ray trace (s) | zeroset (s) | POV-Ray / zeroset |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    ratios = []
    for scene in scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        include_dir = os.path.dirname(scene)
        pov_out, zs_out = os.path.join(work, f"pov_{name}.ppm"), os.path.join(work, f"zs_{name}.ppm")
        try:
            # Alternated, so that both renderers see the shared machine's same moments.
            pov_times, zs_runs = [], []
            for _ in range(args.repeat):
                pov_times.append(run_povray(scene, pov_out, width, height, args.threads, include_dir))
                zs_runs.append(run_zeroset(zeroset, scene, zs_out, width, height, args.threads, include_dir))
            # The masks: the same scene against a magenta background.
            masked = os.path.join(work, f"{name}_mask.pov")
            with open(scene, "rb") as src, open(masked, "wb") as dst:
                dst.write(src.read() + b"\nbackground { rgb <1, 0, 1> }\n")
            run_povray(masked, os.path.join(work, "pov_mask.ppm"), width, height, args.threads, include_dir)
            run_zeroset(zeroset, masked, os.path.join(work, "zs_mask.ppm"), width, height, args.threads, include_dir)
        except RuntimeError as e:
            print(f"| {name} | failed: {str(e).splitlines()[0]} | | | | | |")
            continue
        mean, p99 = image_difference(read_ppm(pov_out), read_ppm(zs_out))
        masks = mask_difference(read_ppm(os.path.join(work, "pov_mask.ppm")), read_ppm(os.path.join(work, "zs_mask.ppm")))
        pov_t = statistics.median(pov_times)
        zs_t = statistics.median(t for t, _ in zs_runs)
        ratio = pov_t / zs_t if zs_t > 0 else float("inf")
        ratios.append(ratio)
        print(f"| {name} | {mean:.1f} | {p99} | {100 * masks:.2f} % | {pov_t:.3f} | {zs_t:.3f} | {ratio:.2f}× |", flush=True)
        if keep:
            shutil.copy(pov_out, os.path.join(keep, f"pov_{name}.ppm"))
            shutil.copy(zs_out, os.path.join(keep, f"zs_{name}.ppm"))
        for w in zs_runs[0][1]:
            print(f"<!-- {name}: {w} -->", file=sys.stderr)
    if ratios:
        print(f"\nmedian POV-Ray / zeroset: {statistics.median(ratios):.2f}× over {len(ratios)} scenes, "
              f"{width}x{height}, {args.threads} threads, medians of {args.repeat} runs")
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
