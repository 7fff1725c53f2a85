#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
#
# Installs the Debian 12 packages Q3 needs to build, test and benchmark, and
# nothing when they are all present already (so it is safe to run every time).
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  libosmesa6-dev      # the OSMesa rendering backend (llvmpipe); its header, and the
                      # library the backend opens at run time
  libegl-dev          # the EGL rendering backend's headers (EGL/egl.h, eglext.h)
  libegl1             # libEGL.so.1, the EGL loader the backend opens at run time
  libegl-mesa0        # Mesa's EGL: the software device (llvmpipe) the EGL goldens run on
  libx11-dev          # Xlib's headers: QD3DDrawContext.h's X11 draw context includes them
                      # (libq3 opens libX11.so.6 with dlopen when a window is drawn into)
  xvfb                # a virtual X server: the X11 draw context tests start their own
  libxtst6            # XTEST's client library: the q3view test's mouse and key events
                      # (opened at run time; without it the test falls back to XSendEvent)
  libglm-dev          # vectors and matrices
  libgtest-dev        # tests
  libpng-dev          # golden images and the figures
  libbenchmark-dev    # benchmarks
  libglu1-mesa-dev    # the GLU NURBS tessellator, a benchmark peer (own process)
  clang libclang-rt-14-dev  # libFuzzer and the sanitizer runtimes
  libtinygltf-dev     # glTF 2.0 reading and writing (src/exchange, docs/exchange.md)
  libassimp-dev       # OBJ/MTL and STL reading and writing (src/exchange)
  nodejs              # runs the Khronos glTF validator in the exchange tests (Debian's
                      # nodejs wants its npm package too; NodeSource's carries npm)
)

# The Khronos glTF validator (npm's gltf-validator, a pinned version), into
# build-tools/node_modules (ignored by git), where scripts/gltf-validate.js
# and the exchange tests find it.
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi

install_validator() {
  local root
  root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
  if [ ! -f "$root/build-tools/node_modules/gltf-validator/package.json" ]; then
    if ! command -v npm >/dev/null; then
      "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends npm
    fi
    echo "setup: installing gltf-validator into build-tools/node_modules"
    mkdir -p "$root/build-tools"
    npm install --silent --no-save --no-package-lock --prefix "$root/build-tools" gltf-validator@2.0.0-dev.3.10
  fi
}

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  install_validator
  exit 0
fi

echo "setup: installing ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
install_validator
