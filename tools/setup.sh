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
libcli11-dev nlohmann-json3-dev libgtest-dev libbenchmark-dev"
missing=""
for p in $packages; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
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
  exec ctest --test-dir build --output-on-failure -j"$jobs"
fi

# Main job. Until the table baker lands, the most useful output is each
# model's curves at the default roughness: D, Lambda, G1 along mu, and the
# BRDF and visible-normal pdf for a 60-degree view.
mkdir -p out
tool=build/bin/brdfbake
emit() {  # emit FILE ARGS...: write through a temporary, never a partial file
  file="$1"; shift
  "$tool" "$@" > "out/.$file.tmp" && mv "out/.$file.tmp" "out/$file"
  echo "wrote out/$file"
}
for model in ggx beckmann; do
  emit "${model}_r0.5.csv" eval --model "$model" --roughness 0.5 \
    --quantity D,Lambda,G1,G2,brdf,pdf --mu-o 0.5 --count 101
done
emit "std_gamma3_r0.5.csv" eval --model std --gamma 3 --roughness 0.5 \
  --quantity D,Lambda,G1,G2,brdf,pdf --mu-o 0.5 --count 101
emit "ellipsoid_r0.5_tilted.csv" eval --model ellipsoid --roughness 0.5 --theta-x 15 \
  --quantity D,Lambda,G1,G2,brdf,pdf --mu-o 0.5 --count 101
emit "sel_0.3x0.6.csv" eval --model sel --alpha-x 0.3 --alpha-y 0.6 --quantity K --count 101
"$tool" --version
