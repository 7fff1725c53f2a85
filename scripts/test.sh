#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
#
# Installs what is missing, builds Q3 and runs every test: the Release suite,
# the same suite under AddressSanitizer + UndefinedBehaviorSanitizer, the
# thread test under ThreadSanitizer, and a bounded libFuzzer run.
# Build trees: build/, build-asan/, build-tsan/, build-fuzz/ (all ignored by git).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs="${Q3_JOBS:-2}"

bash scripts/setup.sh

echo "== Release build and tests"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$jobs"
ctest --test-dir build -j"$jobs" --output-on-failure --timeout 300
