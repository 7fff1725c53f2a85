#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
#
# Installs the Debian 12 packages Q3 needs to build, test and benchmark, and
# nothing when they are all present already (so it is safe to run every time).
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  libosmesa6-dev      # offscreen rasterizing (llvmpipe)
  libglm-dev          # vectors and matrices
  libgtest-dev        # tests
  libpng-dev          # golden images and the figures
  libbenchmark-dev    # benchmarks
  libglu1-mesa-dev    # the GLU NURBS tessellator, a benchmark peer (own process)
  clang libclang-rt-14-dev  # libFuzzer and the sanitizer runtimes
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
