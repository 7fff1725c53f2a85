#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
#
# Renders the develop article's curve figures through Q3:
#   bash scripts/figures.sh [OUTDIR]      (default out/figures)
# Installs what is missing, builds the article_figures sample in build/ and
# writes OUTDIR/figureNN.png plus OUTDIR/index.md (figure, file, knot vector).
# A relative OUTDIR is taken from the current directory; the default is in
# the repository.
set -euo pipefail
caller="$PWD"
cd "$(dirname "$0")/.."
out="${1:-out/figures}"
if [ $# -ge 1 ] && [ "${out#/}" = "$out" ]; then out="$caller/$out"; fi

bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2 --target article_figures
./build/samples/article_figures "$out"
echo "figures: $out/index.md"
