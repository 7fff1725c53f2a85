#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
#
# Installs the build tree into a scratch prefix, then builds a C program from
# outside the tree twice: with pkg-config (as legacy makefiles do) and with
# find_package(Q3 CONFIG), and runs both. Then builds samples/golden-test (an
# outside project with two golden-image tests, q3_add_golden_test) against
# the prefix and runs its tests; on a copy of it, checks that a wrong golden
# fails with the actual and diff pictures written and named, and that
# Q3_UPDATE_GOLDENS=1 re-blesses it.
set -euo pipefail
build_dir="$1"
source_dir="$2"
prefix="$(mktemp -d)"
trap 'rm -rf "$prefix"' EXIT

cmake --install "$build_dir" --prefix "$prefix" > /dev/null
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig:$prefix/lib/x86_64-linux-gnu/pkgconfig"
test -f "$prefix/include/Q3/QD3DGeometry.h"
test -f "$prefix/include/Q3/QD3DIO.h"

# The tools run from the prefix (they find the library through their rpath).
"$prefix/bin/q3convert" "$source_dir/tests/data/scene.3dmf" "$prefix/scene.bin.3dmf" --binary
"$prefix/bin/q3render" "$prefix/scene.bin.3dmf" -o "$prefix/scene.png" --size 80x60
test -s "$prefix/scene.png"
# Their man pages, where man looks for them.
test -f "$prefix/share/man/man1/q3render.1"
test -f "$prefix/share/man/man1/q3convert.1"
test -f "$prefix/share/man/man1/q3compare.1"
# q3view (built where Xlib is found, as on every Debian set up by
# scripts/setup.sh): it runs from the prefix, and without a display says so
# with exit status 3.
if [ -f "$build_dir/tools/q3view" ]; then
  "$prefix/bin/q3view" --help > /dev/null
  test -f "$prefix/share/man/man1/q3view.1"
  status=0
  env -u DISPLAY "$prefix/bin/q3view" "$prefix/scene.bin.3dmf" 2> /dev/null || status=$?
  test "$status" -eq 3
fi
"$prefix/bin/q3compare" "$prefix/scene.png" "$prefix/scene.png"

cc -std=c99 -Wall -Werror "$source_dir/tests/install/outside.c" -o "$prefix/outside" \
   $(pkg-config --cflags --libs q3)
LD_LIBRARY_PATH="$(pkg-config --variable=libdir q3)" "$prefix/outside"

mkdir -p "$prefix/cmake-consumer"
cat > "$prefix/cmake-consumer/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.20)
project(Consumer C)
find_package(Q3 CONFIG REQUIRED)
add_executable(outside "$source_dir/tests/install/outside.c")
target_link_libraries(outside PRIVATE Q3::q3)
CMAKE
cmake -S "$prefix/cmake-consumer" -B "$prefix/cmake-consumer/build" -DCMAKE_PREFIX_PATH="$prefix" > /dev/null
cmake --build "$prefix/cmake-consumer/build" > /dev/null
"$prefix/cmake-consumer/build/outside"

# ---- samples/golden-test, as its README says to build it.
sample="$prefix/golden-test"
cmake -S "$source_dir/samples/golden-test" -B "$sample/build" -DCMAKE_PREFIX_PATH="$prefix" > /dev/null
cmake --build "$sample/build" > /dev/null
ctest --test-dir "$sample/build" --output-on-failure > "$sample/pass.log" || { cat "$sample/pass.log"; exit 1; }
grep -q "100% tests passed, 0 tests failed out of 2" "$sample/pass.log"
test "$(ctest --test-dir "$sample/build" -N -L q3-golden | grep -c 'Test *#')" = 2

# A copy whose curves golden is wrong (the TriMesh's picture): the test fails,
# keeps the actual and the diff, and names both.
cp -R "$source_dir/samples/golden-test" "$sample/copy"
cp "$source_dir/samples/golden-test/golden/lit_trimesh.png" "$sample/copy/golden/curves.png"
cmake -S "$sample/copy" -B "$sample/copy-build" -DCMAKE_PREFIX_PATH="$prefix" > /dev/null
cmake --build "$sample/copy-build" > /dev/null
if ctest --test-dir "$sample/copy-build" --output-on-failure -R '^curves$' > "$sample/fail.log" 2>&1; then
    echo "a wrong golden passed"; cat "$sample/fail.log"; exit 1
fi
grep -q "does not match its golden" "$sample/fail.log"
grep -q "pixels differ by more than 0" "$sample/fail.log"
grep -q "actual: $sample/copy-build/curves.png" "$sample/fail.log"
grep -q "diff:   $sample/copy-build/curves.diff.png" "$sample/fail.log"
test -s "$sample/copy-build/curves.png"
test -s "$sample/copy-build/curves.diff.png"
# The diff is the golden's size and shows the mismatch: q3compare tells it
# from the golden.
set +e
"$prefix/bin/q3compare" "$sample/copy-build/curves.diff.png" "$sample/copy/golden/curves.png" > /dev/null
test $? = 1 || { echo "the diff picture is not a picture of the golden's size"; exit 1; }
set -e

# Q3_UPDATE_GOLDENS=1 re-blesses: the actual is copied over the golden, the
# test passes and says so; afterwards it passes without the switch.
Q3_UPDATE_GOLDENS=1 ctest --test-dir "$sample/copy-build" -V -R '^curves$' > "$sample/bless.log" 2>&1 ||
    { cat "$sample/bless.log"; exit 1; }
grep -q "Q3_UPDATE_GOLDENS=1: re-blessed" "$sample/bless.log"
cmp -s "$sample/copy-build/curves.png" "$sample/copy/golden/curves.png"
ctest --test-dir "$sample/copy-build" --output-on-failure > /dev/null
# A missing golden fails, saying how to create it; Q3_UPDATE_GOLDENS=1 creates it.
rm "$sample/copy/golden/lit_trimesh.png"
if ctest --test-dir "$sample/copy-build" --output-on-failure -R '^lit_trimesh$' > "$sample/missing.log" 2>&1; then
    echo "a missing golden passed"; exit 1
fi
grep -q "is missing" "$sample/missing.log"
Q3_UPDATE_GOLDENS=1 ctest --test-dir "$sample/copy-build" -R '^lit_trimesh$' > /dev/null
cmp -s "$sample/copy-build/lit_trimesh.png" "$sample/copy/golden/lit_trimesh.png"
# The committed golden was never touched.
"$prefix/bin/q3compare" "$source_dir/samples/golden-test/golden/curves.png" "$sample/build/curves.png"
echo "install check OK"
