#!/usr/bin/env python3
"""One and two ranks on this machine, side by side: 1 process × 1 thread,
1 process × 2 threads, and mpirun -n 2 × 1 thread each, alternated, medians
of --repeat runs of the whole command (wall time, mpirun's start included);
every 2-rank image is checked to be the 1-process image byte for byte.

Usage: measure.py [--repeat 5] [--zeroset build/zeroset]   (from the repository)
Prints a Markdown table for docs/distributed.md.
"""
import argparse
import filecmp
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

SCENES = [
    ("default scene, 800×600", []),
    ("bear.vm, 192×192", ["bench/scenes/bear.zs", "--width", "192", "--height", "192"]),
]


def timed(command, env):
    start = time.perf_counter()
    subprocess.run(command, check=True, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--repeat", type=int, default=5)
    p.add_argument("--zeroset", default="build/zeroset")
    a = p.parse_args()
    mpirun = shutil.which("mpirun")
    if not mpirun:
        sys.exit("measure.py: mpirun not found (apt-get install openmpi-bin)")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    out = tempfile.mkdtemp()
    print("| scene | 1 process × 1 thread | 1 process × 2 threads | 2 ranks × 1 thread | 2 ranks / 1 process × 2 threads |")
    print("| --- | ---: | ---: | ---: | ---: |")
    for name, args in SCENES:
        configs = {
            "p1t1": [a.zeroset, "render", *args, "-q", "--threads", "1", "-o", f"{out}/p1t1.png"],
            "p1t2": [a.zeroset, "render", *args, "-q", "--threads", "2", "-o", f"{out}/p1t2.png"],
            "r2t1": [mpirun, "-n", "2", "--bind-to", "none", a.zeroset, "render", *args, "-q", "--threads", "1",
                     "-o", f"{out}/r2t1.png"],
        }
        times = {k: [] for k in configs}
        for _ in range(a.repeat):
            for key, command in configs.items():
                times[key].append(timed(command, env))
        if not filecmp.cmp(f"{out}/p1t1.png", f"{out}/r2t1.png", shallow=False):
            sys.exit(f"measure.py: {name}: the 2-rank image differs from the 1-process image")
        m = {k: statistics.median(v) for k, v in times.items()}
        print(f"| {name} | {m['p1t1']:.2f} s | {m['p1t2']:.2f} s | {m['r2t1']:.2f} s | {m['r2t1'] / m['p1t2']:.2f} |")
    shutil.rmtree(out)


if __name__ == "__main__":
    main()
