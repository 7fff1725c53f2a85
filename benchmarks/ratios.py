# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
"""Turns Google Benchmark JSON files from benchmarks/run.sh into the ratio
tables of benchmarks/RESULTS.md (Markdown on stdout).

Every repetition of every round is pooled and the median taken. Most ratios
come from paired benchmarks (BenchTiming.h), which report them as counters;
everything is timed in wall time, what a user waits for. A speed-up is peer
time / Q3 time on identical work, which equals the ratio of vertices per
second.

Usage: python3 ratios.py RESULT.json [RESULT.json ...]
"""

import json
import re
import statistics
import sys

SECONDS = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}


class Runs:
    """Repetitions by benchmark name (without /min_time:... and /real_time)."""

    def __init__(self, paths):
        self.runs = {}
        self.errors = {}
        for path in paths:
            with open(path) as f:
                report = json.load(f)
            for entry in report["benchmarks"]:
                name = re.sub(r"/(min_time:[0-9.]+|real_time)", "", entry.get("run_name", entry["name"]))
                if entry.get("error_occurred"):
                    self.errors[name] = entry.get("error_message", "error")
                    continue
                if entry.get("run_type", "iteration") != "iteration":
                    continue
                self.runs.setdefault(name, []).append(entry)

    def has(self, name):
        return name in self.runs

    def time(self, name, clock):
        unit = SECONDS[self.runs[name][0]["time_unit"]]
        return statistics.median(e[clock] * unit for e in self.runs[name])

    def counter(self, name, key):
        return statistics.median(e[key] for e in self.runs[name])

    def count(self, name):
        return len(self.runs.get(name, []))


def fmt(value, digits=3):
    if value is None:
        return "n/a"
    if value == 0:
        return "0"
    if abs(value) >= 1e4 or abs(value) < 1e-3:
        return f"{value:.{digits - 1}e}"
    return f"{value:.{digits}g}"


def verdict(value, target, at_least):
    if value is None:
        return "missing"
    ok = value >= target if at_least else value <= target
    return ("meets" if ok else "MISSES") + (f" (≥ {target}×)" if at_least else f" (≤ {target}×)")


def missing(runs, *names):
    """The first benchmark without results, with its error if it had one."""
    for name in names:
        if not runs.has(name):
            return f"{name}: {runs.errors.get(name, 'no results')}"
    return None


def tessellation(runs, out):
    out.append("### 1. Constant method, 64 segments per span (wall time, medians)\n")
    out.append("Kernel rows: Q3 and GLU paired in one process (`Glu_Constant/*`). Public-call rows: "
               "`Q3Geometry_GetDecomposed` paired with the kernel in the Q3 process (`Q3_GetDecomposed/*`), "
               "chained with the kernel's speed-up; the direct cross-process ratio is shown as a check.\n")
    out.append("| Measure | Q3 | GLU | Q3 Mvertices/s | GLU Mvertices/s | Speed-up (GLU time / Q3 time) | Target |")
    out.append("|---|---|---|---|---|---|---|")
    for label, curve, target in (("Kernel, rational cubic, 1000 points", "cubic", 4.0),
                                 ("Kernel, order 16, 1000 points", "order16", 10.0),
                                 ("Kernel forced to baseline x86-64 (SSE2, no AVX2), cubic (info)",
                                  "cubic_baseline", None),
                                 ("Kernel forced to baseline x86-64 (SSE2, no AVX2), order 16 (info)",
                                  "order16_baseline", None)):
        name = f"Glu_Constant/{curve}"
        problem = missing(runs, name)
        if problem:
            out.append(f"| {label} | {problem} | | | | | |")
            continue
        tq, tp = runs.counter(name, "q3_ms"), runs.counter(name, "glu_ms")
        vertices = runs.counter(name, "vertices")
        speedup = runs.counter(name, "glu_over_q3")
        shown = f"**{speedup:.2f}×**" if target else f"{speedup:.2f}×"
        goal = verdict(speedup, target, True) if target else "info"
        out.append(f"| {label} | {fmt(tq)} ms | {fmt(tp)} ms | {fmt(vertices / tq / 1e3)} | "
                   f"{fmt(vertices / tp / 1e3)} | {shown} | {goal} |")
    for label, curve, target in (("Q3Geometry_GetDecomposed, rational cubic", "cubic", 2.5),
                                 ("Q3Geometry_GetDecomposed, order 16 (info)", "order16", None)):
        kernel, public = f"Glu_Constant/{curve}", f"Q3_GetDecomposed/{curve}"
        problem = missing(runs, kernel, public)
        if problem:
            out.append(f"| {label} | {problem} | | | | | |")
            continue
        slowdown = runs.counter(public, "decomposed_over_kernel")
        speedup = runs.counter(kernel, "glu_over_q3") / slowdown
        tq, tp = runs.counter(public, "decomposed_ms"), runs.counter(kernel, "glu_ms")
        vertices = runs.counter(public, "vertices")
        goal = verdict(speedup, target, True) if target else "info"
        out.append(f"| {label} | {fmt(tq)} ms | {fmt(tp)} ms | {fmt(vertices / tq / 1e3)} | "
                   f"{fmt(vertices / tp / 1e3)} | **{speedup:.2f}×** (public call = {slowdown:.2f}× the kernel's "
                   f"time; cross-process {tp / tq:.2f}×) | {goal} |")
    # The whole public sequence in wall time (issue: system time counts too):
    # Q3_PublicPath (TessellateBench.cpp) against Glu_WallPeer, medians of
    # the two processes of the same run.
    peer, public = "Glu_WallPeer/cubic", "Q3_PublicPath/cubic"
    problem = missing(runs, peer, public)
    label = "Public path in wall time (GetDecomposed, GetData, vertices read, EmptyData, Dispose), rational cubic"
    if problem:
        out.append(f"| {label} | {problem} | | | | | |")
    else:
        tq, tp = 1e3 * runs.time(public, "real_time"), 1e3 * runs.time(peer, "real_time")
        vertices = runs.counter(public, "vertices")
        speedup = tp / tq
        out.append(f"| {label} | {fmt(tq)} ms | {fmt(tp)} ms | {fmt(vertices / tq / 1e3)} | "
                   f"{fmt(runs.counter(peer, 'vertices') / tp / 1e3)} | **{speedup:.2f}×** | "
                   f"{verdict(speedup, 2.0, True)} |")
    for label, curve in (("From a cached Bezier form, cubic (info)", "cubic"),
                         ("From a cached Bezier form, order 16 (info)", "order16")):
        kernel, form, fromCurve = f"Glu_Constant/{curve}", f"Q3_ConstantForm/{curve}", f"Q3_Constant/{curve}"
        if missing(runs, kernel, form, fromCurve):
            continue
        gain = runs.time(fromCurve, "real_time") / runs.time(form, "real_time")
        out.append(f"| {label} | {fmt(runs.time(form, 'real_time') * 1e3)} ms | | | | "
                   f"{runs.counter(kernel, 'glu_over_q3') * gain:.2f}× (conversion is "
                   f"{100 * (1 - 1 / gain):.0f}% of the kernel's time) | info |")
    out.append("")
    out.append("Largest distance of a vertex from the long-double curve at its parameter "
               "(the curves span [-1, 1], so absolute = relative to the curve's size):\n")
    out.append("| Curve | Q3 | GLU | GLU / Q3 |")
    out.append("|---|---|---|---|")
    for label, curve in (("rational cubic", "cubic"), ("order 16", "order16")):
        name = f"Glu_Constant/{curve}"
        if runs.has(name):
            eq, ep = runs.counter(name, "q3_rel_error"), runs.counter(name, "glu_rel_error")
            out.append(f"| {label} | {fmt(eq)} | {fmt(ep)} | {ep / eq:.1f} |")
    out.append("")


def adaptive(runs, out):
    out.append("### 2. Adaptive methods, c1 = arc length / (16 × spans) (paired, wall time, medians)\n")
    out.append("| Space, curve | Q3 Mvertices/s | GLU Mvertices/s | Q3 / GLU vertices/s | "
               "GLU time / Q3 time | Target | Q3 segments / (L/c1) | GLU segments / (L/c1) | "
               "Q3 longest / c1 | GLU longest / c1 |")
    out.append("|---|---|---|---|---|---|---|---|---|---|")
    targets = []
    for space in ("world", "screen"):
        for curve, label in (("cubic", "rational cubic"), ("order16", "order 16")):
            name = f"Glu_Adaptive/{space}_{curve}"
            problem = missing(runs, name)
            if problem:
                out.append(f"| {space}, {label} | {problem} | | | | | | | | |")
                if space == "screen":
                    targets.append((label, None))
                continue
            c = lambda k: runs.counter(name, k)
            rq, rp = c("q3_vertices") / c("q3_ms") / 1e3, c("glu_vertices") / c("glu_ms") / 1e3
            speedup = c("glu_over_q3")
            goal = "info"
            if space == "screen":
                goal = verdict(speedup, 1.5, True)
                targets.append((label, speedup))
            out.append(f"| {space}, {label} | {fmt(rq)} | {fmt(rp)} | {rq / rp:.2f} | **{speedup:.2f}×** | {goal} | "
                       f"{c('q3_segments_per_ideal'):.3f} | {c('glu_segments_per_ideal'):.3f} | "
                       f"{c('q3_longest_over_c1'):.4f} | {c('glu_longest_over_c1'):.3f} |")
    out.append("")
    shown = " / ".join(f"{label} {fmt(v)}×" if v is not None else f"{label} missing" for label, v in targets)
    worst = min((v for _, v in targets if v is not None), default=None)
    out.append(f"Target row: adaptive screen-space vs GLU_PATH_LENGTH ≥ 1.5× (per curve, wall time): "
               f"{shown}: {verdict(worst, 1.5, True) if len(targets) == 2 and None not in dict(targets).values() else 'missing'}\n")


def frames(runs, out):
    out.append("### 3. Frames: 1000 retained curves of 64 segments (paired, wall time, medians)\n")
    out.append("| Image | Q3 | raw, glDrawArrays per strip | raw, glMultiDrawArrays | "
               "Q3 / raw (per strip) | Q3 / raw (multi) | Target (vs the faster raw) | "
               "raw direct into BGRA (info) | curves subdivided: 1st frame after edit, unchanged 2nd | "
               "pixels differing (per strip, multi, direct) |")
    out.append("|---|---|---|---|---|---|---|---|---|---|")
    for size in (512, 1024):
        name = f"Frame/{size}"
        problem = missing(runs, name)
        if problem:
            out.append(f"| {size}² | {problem} | | | | | | | | |")
            continue
        c = lambda k: runs.counter(name, k)
        worst = max(c("q3_over_raw"), c("q3_over_rawmulti"))
        out.append(f"| {size}² | {fmt(c('q3_ms'))} ms | {fmt(c('raw_ms'))} ms | {fmt(c('rawmulti_ms'))} ms | "
                   f"{c('q3_over_raw'):.3f} | {c('q3_over_rawmulti'):.3f} | **{worst:.3f}×** "
                   f"{verdict(worst, 1.15, False)} | {fmt(c('rawdirect_ms'))} ms (Q3 / it "
                   f"{c('q3_over_rawdirect'):.2f}) | {c('evaluated_first_frame'):.0f}, "
                   f"{c('evaluated_second_frame'):.0f} | {c('pixels_differing'):.0f}, "
                   f"{c('pixels_differing_multi'):.0f}, {c('pixels_differing_direct'):.0f} of {size * size} |")
    for size in (512, 1024):
        name = f"FrameDepth/{size}"
        if runs.has(name):
            c = lambda k: runs.counter(name, k)
            out.append(f"\nInfo: the same frame against raw OpenGL doing Q3's hidden-line removal (24-bit depth "
                       f"buffer, GL_LEQUAL), {size}²: {fmt(c('q3_ms'))} ms, {c('q3_over_rawdepth'):.3f}× rawdepth "
                       f"({fmt(c('rawdepth_ms'))} ms), {c('q3_over_rawmulti'):.3f}× rawmulti in the same loop; "
                       f"pixels differing {c('pixels_differing_depth'):.0f}.")
    for size in (512, 1024):
        name = f"FrameEdited/{size}"
        if runs.has(name):
            out.append(f"\nInfo: a frame after all 1000 curves were edited (so each is tessellated again), "
                       f"{size}²: {fmt(runs.counter(name, 'q3edited_ms'))} ms, "
                       f"{runs.counter(name, 'q3edited_over_raw'):.3f}× the raw frame.")
    for size in (512, 1024):
        name = f"FrameScreenSpace/{size}"
        if runs.has(name):
            out.append(f"\nInfo: the same 1000 curves under the default style (screen space, 20 px), {size}²: "
                       f"{fmt(runs.counter(name, 'q3screen_ms'))} ms, {runs.counter(name, 'q3screen_over_raw'):.3f}× "
                       f"the raw frame of the constant polylines; curves subdivided per frame "
                       f"{runs.counter(name, 'evaluated_per_frame'):.0f}.")
    out.append("")
    out.append("### 4. Fixed cost per frame: empty scene (paired, wall time, medians)\n")
    out.append("| Image | Q3 Start..EndRendering | raw clear + glFinish + glReadPixels | Q3 / raw | Target | "
               "raw clear + glFinish into a BGRA buffer (info) | Q3 / that |")
    out.append("|---|---|---|---|---|---|---|")
    for size in (512, 1024):
        name = f"EmptyFrame/{size}"
        problem = missing(runs, name)
        if problem:
            out.append(f"| {size}² | {problem} | | | | | |")
            continue
        c = lambda k: runs.counter(name, k)
        out.append(f"| {size}² | {fmt(c('q3_ms'))} ms | {fmt(c('raw_ms'))} ms | **{c('q3_over_raw'):.2f}×** | "
                   f"{verdict(c('q3_over_raw'), 1.2, False)} | {fmt(c('rawdirect_ms'))} ms | "
                   f"{c('q3_over_rawdirect'):.2f} |")
    out.append("")


def meshes(runs, out):
    out.append("### 6. Frames: one retained TriMesh of 100,352 triangles with vertex colours "
               "(paired, wall time, medians)\n")
    out.append("| Image | Q3 (interactive renderer) | raw glDrawElements, same depth test and shading | "
               "Q3 / raw | Target | raw direct into BGRA (info) | mesh rebuilt by an unchanged 2nd frame | "
               "pixels differing (raw, direct) |")
    out.append("|---|---|---|---|---|---|---|---|")
    for size in (512, 1024):
        name = f"MeshFrame/{size}"
        problem = missing(runs, name)
        if problem:
            out.append(f"| {size}² | {problem} | | | | | | |")
            continue
        c = lambda k: runs.counter(name, k)
        out.append(f"| {size}² | {fmt(c('q3_ms'))} ms | {fmt(c('raw_ms'))} ms | **{c('q3_over_raw'):.3f}×** | "
                   f"{verdict(c('q3_over_raw'), 1.15, False)} | {fmt(c('rawdirect_ms'))} ms (Q3 / it "
                   f"{c('q3_over_rawdirect'):.2f}) | {c('mesh_builds_second_frame'):.0f} | "
                   f"{c('pixels_differing'):.0f}, {c('pixels_differing_direct'):.0f} of {size * size} |")
    out.append("")


def models(runs, out):
    out.append("### 8. A real-world-like model: 10,240 textured Phong triangles in 20 meshes, 4 textures, "
               "a translucent column, two lights, 512² (paired, wall time, medians)\n")
    out.append("| Q3 frame | raw OpenGL, static buffers, one draw per material | Q3 / raw | Target | "
               "first frame of a new view | Target | the process's first frame (info) | pixels differing (info) |")
    out.append("|---|---|---|---|---|---|---|---|")
    problem = missing(runs, "ModelFrame", "FirstFrame")
    if problem:
        out.append(f"| {problem} | | | | | | | |")
        out.append("")
        return
    c = lambda k: runs.counter("ModelFrame", k)
    first = runs.counter("FirstFrame", "first_frame_ms")
    out.append(f"| {fmt(c('q3_ms'))} ms | {fmt(c('raw_ms'))} ms | **{c('q3_over_raw'):.3f}×** | "
               f"{verdict(c('q3_over_raw'), 1.05, False)} | {fmt(first)} ms | "
               f"{'meets' if first <= 15 else 'MISSES'} (≤ 15 ms) | {fmt(c('process_first_frame_ms'))} ms | "
               f"{c('pixels_differing'):.0f} of {512 * 512} |")
    out.append("")


def memory(runs, out):
    out.append("### 5. Memory held per retained curve (after one frame, constant c1 = 64)\n")
    out.append("| Curve | data bytes | object + copies | added by a 1st frame | held / data | Target | "
               "heap blocks | added by a 2nd frame | subdivisions per frame | the view's curve buffer (info) |")
    out.append("|---|---|---|---|---|---|---|---|---|---|")
    worst = None
    for name, label in (("bezier4", "4-point cubic Bezier (65 vertices)"),
                        ("cubic", "rational cubic, 1000 points"), ("order16", "order 16, 1000 points"),
                        ("order16_large", "order 16, 100,000 points")):
        key = f"Q3_RetainedCurve/{name}"
        if not runs.has(key):
            out.append(f"| {label} | {runs.errors.get(key, 'missing')} | | | | | | | | |")
            worst = float("inf")
            continue
        c = lambda k: runs.counter(key, k)
        held = c("held_over_data")
        worst = held if worst is None else max(worst, held)
        out.append(f"| {label} | {c('data_bytes'):.0f} | {c('created_bytes'):.0f} | {c('cache_bytes'):.0f} | "
                   f"**{held:.2f}×** | {verdict(held, 4, False)} | {c('blocks'):.1f} | "
                   f"{c('second_frame_bytes'):.0f} | {c('evaluations_per_frame'):.0f} | "
                   f"{fmt(c('view_scratch_bytes'))} bytes |")
    out.append("")
    shown = "missing" if worst is None or worst == float("inf") else f"**{worst:.2f}×** (the largest of the four)"
    out.append(f"Target row: retained curve memory <= 4x data: {shown} "
               f"{verdict(None if worst in (None, float('inf')) else worst, 4, False)}")
    out.append("")


def patches(runs, out):
    out.append("### 7. NURB patch (torus, rational biquadratic) against gluNurbsSurface, same triangles "
               "(paired, wall time, medians)\n")
    out.append("| m (triangles) | Q3 | GLU | GLU time / Q3 time | Target | Q3 max error | GLU max error |")
    out.append("|---|---|---|---|---|---|---|")
    for m in (16, 64):
        name = f"Glu_Surface/torus_m{m}"
        problem = missing(runs, name)
        if problem:
            out.append(f"| {m} | {problem} | | | | | |")
            continue
        c = lambda k: runs.counter(name, k)
        speedup = 1.0 / c("q3_over_glu")
        out.append(f"| {m} ({c('triangles'):.0f}) | {fmt(c('q3_ms'))} ms | {fmt(c('glu_ms'))} ms | "
                   f"**{speedup:.2f}×** | {verdict(speedup, 3.0, True)} | {fmt(c('q3_max_error'))} | "
                   f"{fmt(c('glu_max_error'))} |")
    out.append("")


def misuse(runs, out):
    """Issue 16's misuse frame (FrameBench.cpp, MisuseFrame): each style's
    frame time over the default style's, paired in one run, wall time."""
    name = "MisuseFrame"
    if not runs.has(name):
        return
    out.append("### Misuse frame: 16 curves in a 128² pane, each style / the default style (paired, wall time, medians)\n")
    out.append("| Style | frame | / default frame | Target |")
    out.append("|---|---|---|---|")
    out.append(f"| default (screen space, 20 px) | {fmt(runs.counter(name, 'default_ms'))} ms | 1 | |")
    for key, label in (("screen0_5", "screen space 0.5 px"), ("screen0_01", "screen space 0.01 px"),
                       ("screen1e_6", "screen space 1e-6 px"), ("world1e_6", "world space 1e-6"),
                       ("constant1024", "constant 1024")):
        ratio = 1.0 / runs.counter(name, f"default_over_{key}")
        out.append(f"| {label} | {fmt(runs.counter(name, key + '_ms'))} ms | **{ratio:.2f}×** | "
                   f"{verdict(ratio, 15, False)} |")
    out.append("")


def main(paths):
    runs = Runs(paths)
    out = []
    tessellation(runs, out)
    adaptive(runs, out)
    frames(runs, out)
    misuse(runs, out)
    memory(runs, out)
    meshes(runs, out)
    patches(runs, out)
    models(runs, out)
    counts = sorted({runs.count(n) for n in runs.runs})
    out.append(f"Repetitions pooled per benchmark: {', '.join(map(str, counts))}.")
    if runs.errors:
        out.append("\nErrors: " + "; ".join(f"{k}: {v}" for k, v in sorted(runs.errors.items())))
    print("\n".join(out))


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
