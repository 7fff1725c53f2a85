#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
#
# Installs the build tree into a scratch prefix, then builds a C program from
# outside the tree twice: with pkg-config (as legacy makefiles do) and with
# find_package(Q3 CONFIG), and runs both.
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
