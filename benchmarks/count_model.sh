#!/bin/bash
# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
#
# Counts the instructions of ModelFrame's 300 frames (issue 26, item 8) with
# callgrind, for Q3 (ModelFrameQ3Only, inside the Q3 calls a frame makes) and
# for the raw OpenGL peer (ModelFrameRawOnly, inside its frame function),
# llvmpipe rasterizing on the calling thread (LP_NUM_THREADS=0) so that all
# of a frame is counted. Unlike the wall clock, the counts do not move with
# the machine's load: they show which work differs, not what it costs in
# cache misses. Prints each side's total and the total outside LLVM (whose
# shader compiles land in whichever frames first need a variant), then the
# 15 functions whose counts differ most (llvmpipe's generated code summed as
# "JIT"). Takes about 4 minutes per side on the 2-core machine.
#
# Usage: benchmarks/count_model.sh Q3_BENCH_MODEL_BINARY [OUTDIR]
# Exit codes: 0 done; 1 valgrind failed; 2 bad arguments.
set -u
if [ $# -lt 1 ] || [ ! -x "$1" ]; then
    echo "usage: $0 Q3_BENCH_MODEL_BINARY [OUTDIR]" >&2
    exit 2
fi
binary=$1
out=${2:-$(mktemp -d)}
mkdir -p "$out"
export GLIBC_TUNABLES=glibc.malloc.trim_threshold=268435456:glibc.malloc.mmap_threshold=33554432
export LP_NUM_THREADS=0
count() {
    local side=$1 filter=$2
    shift 2
    valgrind --tool=callgrind --callgrind-out-file="$out/$side.out" --collect-atstart=no "$@" \
        "$binary" --benchmark_filter="$filter" > "$out/$side.log" 2>&1 || return 1
    callgrind_annotate --threshold=100 "$out/$side.out" > "$out/$side.txt" 2> /dev/null
}
count q3 'ModelFrameQ3Only' --toggle-collect=Q3View_StartRendering --toggle-collect=Q3Shader_Submit \
    --toggle-collect=Q3Geometry_Submit --toggle-collect=Q3View_EndRendering || exit 1
count raw 'ModelFrameRawOnly' '--toggle-collect=q3::bench::RawModel::frame*' || exit 1
python3 - "$out/q3.txt" "$out/raw.txt" << 'EOF'
import re, sys

def load(path):
    counts = {}
    for line in open(path):
        m = re.match(r'\s*([\d,]+)\s+\(.*?\)\s+(.*)$', line)
        if not m or 'PROGRAM TOTALS' in m.group(2):
            continue
        name = m.group(2).strip()
        if name.startswith('???:0x') and '[???]' in name:
            name = 'JIT'
        elif 'libLLVM' in name:
            name = 'LLVM'
        counts[name] = counts.get(name, 0) + int(m.group(1).replace(',', ''))
    return counts

q3, raw = load(sys.argv[1]), load(sys.argv[2])
for label, counts in (('Q3', q3), ('peer', raw)):
    total = sum(counts.values())
    print(f"{label:5} {total:>16,} instructions, {total - counts.get('LLVM', 0):>16,} outside LLVM")
print(f"{'Q3':>16} {'peer':>16} {'Q3 - peer':>16}  function")
names = sorted(set(q3) | set(raw), key=lambda n: -abs(q3.get(n, 0) - raw.get(n, 0)))
for name in names[:15]:
    a, b = q3.get(name, 0), raw.get(name, 0)
    print(f"{a:>16,} {b:>16,} {a - b:>16,}  {name[:90]}")
EOF
