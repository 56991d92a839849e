#!/bin/sh
# Copyright 2026 the brdfbake authors.
# SPDX-License-Identifier: Apache-2.0
#
# One-stop set-up on Debian 12: installs the missing build dependencies,
# builds brdfbake (Release) and then either runs the main job or the tests.
#   sh tools/setup.sh run    # install, build, write the default outputs to out/
#   sh tools/setup.sh test   # install, build, run the whole test suite
set -eu

mode="${1:-run}"
case "$mode" in run|test) ;; *) echo "usage: sh tools/setup.sh run|test" >&2; exit 2 ;; esac
cd "$(dirname "$0")/.."

packages="build-essential cmake libhwy-dev libopenexr-dev libtbb-dev libboost-dev \
libcli11-dev nlohmann-json3-dev libtomlplusplus-dev libzstd-dev libpng-dev libgtest-dev libbenchmark-dev"
# The tests also read files back with OpenImageIO, compile the generated
# shaders with glslang, run the GLSL and WGSL lookups in headless Chromium
# (WebGL2, and WebGPU on its SwiftShader Vulkan), import the three.js and
# KTX2 files with node and the pinned readers of tests/js/package.json,
# build the installed package with pkg-config and trace the scene fuzz's
# file system calls with strace.
if [ "$mode" = test ]; then
  packages="$packages openimageio-tools glslang-tools chromium libvulkan1 pkgconf strace"
fi
missing=""
for p in $packages; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
# node and npm from Debian, unless a node with npm is already installed
# (another distribution of node would conflict with Debian's npm).
if [ "$mode" = test ] && ! command -v npm >/dev/null 2>&1; then
  missing="$missing nodejs npm"
fi
if [ -n "$missing" ]; then
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  echo "brdfbake setup: installing$missing"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends $missing
fi

jobs="$(nproc 2>/dev/null || echo 2)"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$jobs"

if [ "$mode" = test ]; then
  # The JS readers, at the versions and hashes package-lock.json pins,
  # trusting the system's certificate authorities (as apt and curl do, so
  # that a proxy's CA installed on the machine is trusted by npm too).
  ca=""
  [ -f /etc/ssl/certs/ca-certificates.crt ] && ca="--cafile=/etc/ssl/certs/ca-certificates.crt"
  npm ci --prefix tests/js --no-audit --no-fund --loglevel=error $ca
  exec ctest --test-dir build --output-on-failure -j"$jobs"
fi

# Main job: bake the default engine set (GGX, height-correlated, 32x32 over
# mu x roughness, alpha = roughness^2) into out/, on texel centres so that a
# GPU's bilinear texture(lut, vec2(NoV, roughness)) reads it without a
# remap. Each file is written to a temporary and renamed, never left partial.
mkdir -p out
tool=build/bin/brdfbake
"$tool" bake --table E --model ggx --size 32x32 --placement centers -o out/ggx_E.exr
"$tool" bake --table E_avg --model ggx --size 32 --placement centers -o out/ggx_E_avg.exr
"$tool" bake --table dfg --model ggx --size 32x32 --placement centers -o out/ggx_dfg.exr
"$tool" --version
