#!/usr/bin/env bash
# Installs the Debian 12 packages gridcull needs, only those that are missing.
# Everything comes from apt: nothing is vendored or downloaded by the build.
# clang and its runtime (libFuzzer) build the fuzz targets scripts/test.sh runs;
# everything else builds with g++.
set -euo pipefail

packages=(cmake g++ make pkg-config libglfw3-dev libimgui-dev libglm-dev libstb-dev libcli11-dev
          nlohmann-json3-dev libtinyobjloader-dev libgtest-dev libbenchmark-dev libcgif-dev
          libembree-dev xvfb xauth libgl1-mesa-dri libegl-dev libgl-dev
          clang libclang-rt-14-dev)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "installing: ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
