#!/usr/bin/env bash
# Installs the Debian 12 packages VisemeLab needs; does nothing when all are present (idempotent).
set -euo pipefail
packages=(g++ make cmake pkg-config ninja-build libglfw3-dev libimgui-dev libstb-dev libglm-dev
  libopenmesh-dev nlohmann-json3-dev libespeak-ng-dev espeak-ng-data libgtest-dev libgmock-dev
  libbenchmark-dev libtbb-dev libcli11-dev libtinygltf-dev libepoxy-dev xvfb xauth
  libgl1-mesa-dri fonts-dejavu-core libtinyxml2-dev clang libclang-rt-dev libmeshoptimizer-dev libdraco-dev xdotool clang-format ccache
  portaudio19-dev coinor-libclp-dev chromium espeak-ng)
# lld: links visemelab-say (app/CMakeLists.txt): it drops the shared libraries only dead code calls.
packages+=(lld)
# libxxhash-dev: XXH3, compiled in (core/common/ContentHash.cpp), checks the speech cache's inputs.
packages+=(libxxhash-dev)
# The Python package (app/python, pybind11) and its cluster runs (scripts/dask-batch.py): Debian's
# python3 with numpy, setuptools (pip install ./app/python) and Dask distributed.
packages+=(pybind11-dev python3-dev python3-numpy python3-setuptools python3-dask python3-distributed)
# espeak-ng (the command): the say benchmarks measure its own synthesis as their floor.
# chromium: the say --html page test takes screenshots of it headless.
# npm runs the Khronos glTF validator in the tests; a nodejs that bundles npm already provides it.
command -v npm >/dev/null 2>&1 || packages+=(npm)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then exit 0; fi
echo "Installing: ${missing[*]}" >&2
sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
