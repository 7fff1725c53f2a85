# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
"""Issue 30's outside comparison: Q3's public path against GLU, each in a
process of its own (q3_bench_public_outside, q3_bench_glu_count), run N
times each in turns (Q3 first in odd rounds, GLU first in even ones) so both
see the same machine. Each process times 200 calls as one loop and prints
wall time, CPU time (user + system) and minor faults; this prints the median
of each and the ratios of medians:

  speed-up        Q3 vertices per second / GLU vertices per second (each its
                  own count: GLU repeats every span's joint vertex, so it
                  delivers 65 per span where Q3's polyline has 64 per span
                  plus one)
  per curve       GLU time per curve / Q3 time per curve (the same curve at
                  the same 64 segments per span)

in the loop's wall time (the issue's measure), in CPU time (the guide on a
loaded machine) and in the wall time of the median call (which leaves out the
calls the scheduler preempted), with the load average before and after.

Usage: python3 outside.py BUILD_DIR [--runs N]   (default 15 runs each)
Prints Markdown; exits 1 if a program fails.
"""

import os
import statistics
import subprocess
import sys


def run(exe):
    result = subprocess.run([exe], capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"{exe} failed: {result.stderr.strip()}")
    fields = result.stdout.split()
    values = dict(f.split("=", 1) for f in fields[1:])
    return {k: float(v) for k, v in values.items()}


def main(argv):
    if not argv or argv[0].startswith("-"):
        sys.exit(__doc__)
    build = argv[0]
    runs = 15
    if len(argv) == 3 and argv[1] == "--runs":
        runs = int(argv[2])
    elif len(argv) != 1:
        sys.exit(__doc__)
    exes = {"q3": os.path.join(build, "benchmarks", "q3_bench_public_outside"),
            "glu": os.path.join(build, "benchmarks", "q3_bench_glu_count")}
    load_before = os.getloadavg()
    results = {"q3": [], "glu": []}
    for i in range(runs):
        order = ("q3", "glu") if i % 2 == 0 else ("glu", "q3")
        for tool in order:
            results[tool].append(run(exes[tool]))
    load_after = os.getloadavg()

    def med(tool, key):
        return statistics.median(r[key] for r in results[tool])

    q, g = "q3", "glu"
    print(f"Runs: {runs} per program, alternated; 200 calls per run; medians. "
          f"Load average before {load_before[0]:.2f} {load_before[1]:.2f} {load_before[2]:.2f}, "
          f"after {load_after[0]:.2f} {load_after[1]:.2f} {load_after[2]:.2f}.\n")
    print("| Program | vertices per call | wall ms per call (loop / calls) | CPU ms per call (user + sys) | "
          "sys ms per call | median call, wall ms | minor faults per call | Mvertices/s wall | Mvertices/s CPU | "
          "Mvertices/s median call |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for tool, label in ((q, "Q3 public path"), (g, "GLU, counting callback")):
        calls = med(tool, "calls")
        print(f"| {label} | {med(tool, 'vertices_per_call'):.0f} | {1e3 * med(tool, 'wall_s') / calls:.3f} | "
              f"{1e3 * med(tool, 'cpu_s') / calls:.3f} | {1e3 * med(tool, 'sys_s') / calls:.3f} | "
              f"{1e3 * med(tool, 'median_call_s'):.3f} | "
              f"{med(tool, 'minflt') / calls:.1f} | {med(tool, 'vertices_per_s') / 1e6:.1f} | "
              f"{med(tool, 'cpu_vertices_per_s') / 1e6:.1f} | {med(tool, 'median_call_vertices_per_s') / 1e6:.1f} |")
    wall = med(q, "vertices_per_s") / med(g, "vertices_per_s")
    cpu = med(q, "cpu_vertices_per_s") / med(g, "cpu_vertices_per_s")
    call = med(q, "median_call_vertices_per_s") / med(g, "median_call_vertices_per_s")
    wall_curve = med(g, "wall_s") / med(q, "wall_s")
    cpu_curve = med(g, "cpu_s") / med(q, "cpu_s")
    print(f"\nSpeed-up, vertices per second (Q3 / GLU): **{wall:.2f}×** wall time of the loop, **{cpu:.2f}×** "
          f"CPU time, {call:.2f}× wall time of the median call (target ≥ 2.5×). Per curve (GLU time / Q3 time): "
          f"{wall_curve:.2f}× wall, {cpu_curve:.2f}× CPU.")


if __name__ == "__main__":
    main(sys.argv[1:])
