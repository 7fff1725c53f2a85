#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
#
# Installs what is missing, builds Q3 and runs every test: the Release suite,
# its golden-image tests again at llvmpipe's baseline SIMD width and through the
# EGL backend, the same suite under AddressSanitizer + UndefinedBehaviorSanitizer, the
# thread test under ThreadSanitizer, and a bounded libFuzzer run.
# Build trees: build/, build-asan/, build-tsan/, build-fuzz/ (all ignored by git).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs="${Q3_JOBS:-2}"
# Each stage's header says how long the run has taken so far, so that the
# stages' costs can be read from any CI log (the run must stay under 45 min).
stage() { echo "== $1 (at ${SECONDS} s)"; }

bash scripts/setup.sh

stage "Release build and tests"
# The test programs at -O1 (the library stays at -O3): they are about two
# thirds of the build's compile time, and -O1 compiles them about a quarter
# faster than -O3 while their own code is never what a test measures.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DQ3_TEST_OPTIMIZE=-O1
cmake --build build -j"$jobs"
ctest --test-dir build -j"$jobs" --output-on-failure --timeout 300

stage "Golden images again, llvmpipe forced to its baseline SIMD width"
# The goldens must not depend on the host's SIMD level (docs/golden-testing.md):
# the Release run above used the host's (AVX2 where the CPU has it); this one
# makes llvmpipe generate 128-bit (SSE-width) code. Mesa 22.3 reads
# LP_NATIVE_VECTOR_WIDTH; it has no LP_FORCE_SSE2, and its
# GALLIUM_OVERRIDE_CPU_CAPS (nosse only) is unset by Q3. Only the tests
# labelled golden run (a few seconds).
# On a CPU with AVX-512, Mesa 22.3's llvmpipe at 128-bit vectors corrupts the
# heap drawing the Phong-lit textured patch (malloc aborts inside OSMesa's
# flush; the 256-bit default draws it right, and under valgrind, which has no
# AVX-512, it passes with no error): that test is left out there until Mesa
# is fixed (docs/golden-testing.md, "Known problem").
baseline_skip=()
if grep -qw avx512f /proc/cpuinfo 2> /dev/null; then
  baseline_skip=(-E '^TextureGoldenTest\.PatchLitPerVertexWithPhongHighlights$')
fi
LP_NATIVE_VECTOR_WIDTH=128 ctest --test-dir build -j"$jobs" --output-on-failure --timeout 300 \
  --no-tests=error -L '^golden$' "${baseline_skip[@]}"

stage "Golden images again through the EGL backend"
# Both rendering backends must draw every golden (the same files, the same
# pixels: README "Rendering backends"); the Release run above used the
# default, OSMesa.
Q3_RENDER_BACKEND=egl ctest --test-dir build -j"$jobs" --output-on-failure --timeout 300 \
  --no-tests=error -L '^golden$'

# Sanitizer runtime settings shared by the stages below. Leaks are errors;
# the only suppressed ones are Mesa's own (tests/sanitizers/lsan.supp says
# why). Any undefined behaviour stops the test that hit it.
lsan_options="suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0"
ubsan_options="halt_on_error=1:print_stacktrace=1"

stage "AddressSanitizer + UndefinedBehaviorSanitizer build and tests"
# Build flags: the library at -O1 with line tables (what the sanitizers'
# documentation recommends, and enough for file:line in every report), the test
# programs at -O0 (tests/CMakeLists.txt says why).
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=gcc -DCMAKE_CXX_COMPILER=g++ \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DQ3_TEST_OPTIMIZE=-O0 \
  -DQ3_SANITIZE=address,undefined -DQ3_BUILD_BENCHMARKS=OFF -DQ3_TEST_PER_SUITE=ON
cmake --build build-asan -j"$jobs"
# Q3_TEST_PER_SUITE: one process per GoogleTest suite, not per test. A
# sanitized process costs about half a second before its first test and at
# exit; over 2,200 tests that was most of this stage (cmake/Q3SuiteTests.cmake).
# The Release run above still runs every test in a process of its own.
# intercept_tls_get_addr=0: the backends dlopen Mesa (OSMesa, EGL), whose
# driver's dynamic thread-local block has a range the leak checker's tracer
# cannot read: with the interception on, LeakSanitizer itself sometimes dies at
# exit ("Tracer caught signal 11") after a test that passed.
ASAN_OPTIONS=detect_leaks=1:intercept_tls_get_addr=0 LSAN_OPTIONS="$lsan_options" UBSAN_OPTIONS="$ubsan_options" \
  ctest --test-dir build-asan -j"$jobs" --output-on-failure --timeout 900 -E '^Install\.'
# The install check builds and runs a program from outside the tree with the
# plain compiler; the sanitized libq3 it links needs the ASan runtime loaded
# first, so it is preloaded (and leak checking is left to the tests above:
# the build tools the check runs would report their own leaks).
LD_PRELOAD="$(gcc -print-file-name=libasan.so)" ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS="$ubsan_options" \
  ctest --test-dir build-asan --output-on-failure --timeout 300 -R '^Install\.'

stage "ThreadSanitizer build and thread tests"
cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=gcc -DCMAKE_CXX_COMPILER=g++ \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DQ3_SANITIZE=thread -DQ3_BUILD_BENCHMARKS=OFF -DQ3_BUILD_SAMPLES=OFF
cmake --build build-tsan -j"$jobs" --target q3_thread_tests
TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$PWD/tests/sanitizers/tsan.supp" \
  ctest --test-dir build-tsan --output-on-failure --timeout 900 --no-tests=error -R '^Threads'

stage "libFuzzer: the API fuzzer for 60 seconds"
bash tests/fuzz/run.sh 60
stage "All stages passed"
