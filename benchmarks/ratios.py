# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
"""Turns Google Benchmark JSON files from benchmarks/run.sh into the ratio
tables of benchmarks/RESULTS.md (Markdown on stdout).

Every repetition of every round is pooled and the median taken. Single-thread
work (tessellation) compares CPU time of the benchmark thread, which other
tenants of a shared machine disturb least; frames compare wall time, because
llvmpipe rasterizes on threads of its own. A speed-up is peer time / Q3 time
on identical work, which equals the ratio of vertices per second.

Usage: python3 ratios.py RESULT.json [RESULT.json ...]
"""

import json
import statistics
import sys

SECONDS = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}


class Runs:
    """Repetitions by benchmark name (without the /real_time suffix)."""

    def __init__(self, paths):
        self.runs = {}
        self.errors = {}
        for path in paths:
            with open(path) as f:
                report = json.load(f)
            for entry in report["benchmarks"]:
                name = entry.get("run_name", entry["name"]).replace("/real_time", "")
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


def tessellation(runs, out):
    out.append("### 1. Constant method, 64 segments per span (CPU time, medians)\n")
    out.append("| Measure | Q3 | GLU | Q3 Mvertices/s | GLU Mvertices/s | Speed-up | Target |")
    out.append("|---|---|---|---|---|---|---|")
    rows = [
        ("Kernel, rational cubic, 1000 points", "Q3_Constant/cubic", "GLU_Constant/cubic", 4.0),
        ("Kernel, order 16, 1000 points", "Q3_Constant/order16", "GLU_Constant/order16", 10.0),
        ("Q3Geometry_GetDecomposed, rational cubic", "Q3_GetDecomposed/cubic", "GLU_Constant/cubic", 2.5),
        ("Q3Geometry_GetDecomposed, order 16 (info)", "Q3_GetDecomposed/order16", "GLU_Constant/order16", None),
        ("From a cached Bezier form, cubic (info)", "Q3_ConstantForm/cubic", "GLU_Constant/cubic", None),
        ("From a cached Bezier form, order 16 (info)", "Q3_ConstantForm/order16", "GLU_Constant/order16", None),
    ]
    for label, q3, peer, target in rows:
        if not (runs.has(q3) and runs.has(peer)):
            out.append(f"| {label} | {runs.errors.get(q3, 'missing')} | {runs.errors.get(peer, 'missing')} | | | | |")
            continue
        tq, tp = runs.time(q3, "cpu_time"), runs.time(peer, "cpu_time")
        vertices = runs.counter(q3, "vertices")
        speedup = tp / tq
        goal = verdict(speedup, target, True) if target else "info"
        out.append(f"| {label} | {fmt(tq * 1e6)} µs | {fmt(tp * 1e6)} µs | {fmt(vertices / tq / 1e6)} | "
                   f"{fmt(vertices / tp / 1e6)} | **{speedup:.2f}×** | {goal} |")
    out.append("")
    out.append("Largest distance of a vertex from the long-double curve at its parameter "
               "(the curves span [-1, 1], so absolute = relative to the curve's size):\n")
    out.append("| Curve | Q3 | GLU | GLU / Q3 |")
    out.append("|---|---|---|---|")
    for label, q3, peer in [("rational cubic", "Q3_Constant/cubic", "GLU_Constant/cubic"),
                            ("order 16", "Q3_Constant/order16", "GLU_Constant/order16")]:
        if runs.has(q3) and runs.has(peer):
            eq, ep = runs.counter(q3, "rel_error"), runs.counter(peer, "rel_error")
            out.append(f"| {label} | {fmt(eq)} | {fmt(ep)} | {ep / eq:.1f} |")
    out.append("")


def adaptive(runs, out):
    out.append("### 2. Adaptive methods, c1 = arc length / (16 × spans) (CPU time, medians)\n")
    out.append("| Space, curve | Q3 Mvertices/s | GLU Mvertices/s | Q3 / GLU vertices/s | "
               "GLU time / Q3 time | Q3 segments / (L/c1) | GLU segments / (L/c1) | "
               "Q3 longest / c1 | GLU longest / c1 |")
    out.append("|---|---|---|---|---|---|---|---|---|")
    for space in ("world", "screen"):
        for curve, label in (("cubic", "rational cubic"), ("order16", "order 16")):
            q3, peer = f"Q3_Adaptive/{space}_{curve}", f"GLU_Adaptive/{space}_{curve}"
            if not (runs.has(q3) and runs.has(peer)):
                out.append(f"| {space}, {label} | {runs.errors.get(q3, 'missing')} | "
                           f"{runs.errors.get(peer, 'missing')} | | | | | | |")
                continue
            tq, tp = runs.time(q3, "cpu_time"), runs.time(peer, "cpu_time")
            vq, vp = runs.counter(q3, "vertices"), runs.counter(peer, "vertices")
            rq, rp = vq / tq, vp / tp
            out.append(f"| {space}, {label} | {fmt(rq / 1e6)} | {fmt(rp / 1e6)} | {rq / rp:.2f} | "
                       f"{tp / tq:.2f} | {runs.counter(q3, 'segments_per_ideal'):.3f} | "
                       f"{runs.counter(peer, 'segments_per_ideal'):.3f} | "
                       f"{runs.counter(q3, 'longest_over_c1'):.4f} | {runs.counter(peer, 'longest_over_c1'):.3f} |")
    out.append("")


def frames(runs, out):
    out.append("### 3. Frames: 1000 retained curves of 64 segments (wall time, medians)\n")
    out.append("| Image | Q3 | raw, glDrawArrays per strip | raw, glMultiDrawArrays | "
               "Q3 / raw (per strip) | Q3 / raw (multi) | Target (vs the faster raw) | "
               "re-tessellated in an unchanged 2nd frame | pixels differing |")
    out.append("|---|---|---|---|---|---|---|---|---|")
    for size in (512, 1024):
        q3, raw, multi = f"Q3_Frame/{size}", f"Raw_Frame/{size}", f"RawMulti_Frame/{size}"
        if not (runs.has(q3) and runs.has(raw) and runs.has(multi)):
            out.append(f"| {size}² | {runs.errors.get(q3, 'missing')} | {runs.errors.get(raw, 'missing')} | "
                       f"{runs.errors.get(multi, 'missing')} | | | | | |")
            continue
        tq, tr, tm = (runs.time(n, "real_time") for n in (q3, raw, multi))
        out.append(f"| {size}² | {fmt(tq * 1e3)} ms | {fmt(tr * 1e3)} ms | {fmt(tm * 1e3)} ms | "
                   f"{tq / tr:.3f} | {tq / tm:.3f} | {verdict(tq / min(tr, tm), 1.15, False)} | "
                   f"{runs.counter(q3, 'retessellated_second_frame'):.0f} of "
                   f"{runs.counter(q3, 'tessellated_first_frame'):.0f} | "
                   f"{runs.counter(raw, 'pixels_differing'):.0f} of {size * size} |")
    for size in (512, 1024):
        edited, raw = f"Q3_FrameEdited/{size}", f"Raw_Frame/{size}"
        if runs.has(edited) and runs.has(raw):
            out.append(f"\nInfo: a frame in which all 1000 curves were edited (so re-tessellated), {size}²: "
                       f"{fmt(runs.time(edited, 'real_time') * 1e3)} ms, "
                       f"{runs.time(edited, 'real_time') / runs.time(raw, 'real_time'):.3f}× the raw frame.")
    out.append("")
    out.append("### 4. Fixed cost per frame: empty scene (wall time, medians)\n")
    out.append("| Image | Q3 Start..EndRendering | raw clear + glFinish + glReadPixels | Q3 / raw | Target |")
    out.append("|---|---|---|---|---|")
    for size in (512, 1024):
        q3, raw = f"Q3_EmptyFrame/{size}", f"Raw_EmptyFrame/{size}"
        if not (runs.has(q3) and runs.has(raw)):
            out.append(f"| {size}² | {runs.errors.get(q3, 'missing')} | {runs.errors.get(raw, 'missing')} | | |")
            continue
        tq, tr = runs.time(q3, "real_time"), runs.time(raw, "real_time")
        out.append(f"| {size}² | {fmt(tq * 1e3)} ms | {fmt(tr * 1e3)} ms | **{tq / tr:.2f}×** | "
                   f"{verdict(tq / tr, 1.2, False)} |")
    out.append("")


def memory(runs, out):
    out.append("### 5. Memory held per retained curve (after one frame, constant c1 = 64)\n")
    out.append("| Curve | data bytes | object + copies | cache | held / data | of which Bezier form | "
               "polyline | heap blocks | added by a 2nd frame |")
    out.append("|---|---|---|---|---|---|---|---|---|")
    for name, label in (("bezier4", "4-point cubic Bezier (65 vertices)"),
                        ("cubic", "rational cubic, 1000 points"), ("order16", "order 16, 1000 points")):
        key = f"Q3_RetainedCurve/{name}"
        if not runs.has(key):
            out.append(f"| {label} | {runs.errors.get(key, 'missing')} | | | | | | | |")
            continue
        c = lambda k: runs.counter(key, k)
        out.append(f"| {label} | {c('data_bytes'):.0f} | {c('created_bytes'):.0f} | {c('cache_bytes'):.0f} | "
                   f"**{c('held_over_data'):.1f}×** | {c('bezier_form_bytes'):.0f} | {c('polyline_bytes'):.0f} | "
                   f"{c('blocks'):.1f} | {c('second_frame_bytes'):.0f} |")
    out.append("")


def main(paths):
    runs = Runs(paths)
    out = []
    tessellation(runs, out)
    adaptive(runs, out)
    frames(runs, out)
    memory(runs, out)
    counts = sorted({runs.count(n) for n in runs.runs})
    out.append(f"Repetitions pooled per benchmark: {', '.join(map(str, counts))}.")
    if runs.errors:
        out.append("\nErrors: " + "; ".join(f"{k}: {v}" for k, v in sorted(runs.errors.items())))
    print("\n".join(out))


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
