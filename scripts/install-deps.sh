#!/usr/bin/env bash
# Installs the Debian bookworm packages triwalk needs, only those missing.
# Usage: scripts/install-deps.sh [build|test|fuzz]
#   build: compilers and libraries for the triwalk binary and its tests
#          (Xvfb, and xdotool to type keys into the viewer under it)
#   test:  build + the real scenes of the tests (the FZK house, OpenArena levels)
#   fuzz:  build + clang 16 and libFuzzer for the harnesses in fuzz/
set -euo pipefail

profile="${1:-build}"

packages=(
  build-essential cmake ninja-build pkg-config git
  libglm-dev libglfw3-dev libegl-dev libgl-dev libosmesa6-dev libgl1-mesa-dri libegl-mesa0
  libimgui-dev libstb-dev libpng-dev libopenexr-dev libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  libassimp-dev libmeshoptimizer-dev libminizip-dev libxxhash-dev libtbb-dev libcli11-dev nlohmann-json3-dev doctest-dev
  libopenmpi-dev openmpi-bin
  libavcodec-dev libavformat-dev libswscale-dev libavutil-dev
  xvfb xauth xdotool
)
if [[ "$profile" == "test" ]]; then
  packages+=(assimp-testmodels openarena-oacmp1)
fi
if [[ "$profile" == "fuzz" ]]; then
  packages+=(clang-16 libclang-rt-16-dev libfuzzer-16-dev)
fi

missing=()
for package in "${packages[@]}"; do
  status="$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)"
  [[ "$status" == "install ok installed" ]] || missing+=("$package")
done

if ((${#missing[@]} == 0)); then
  echo "triwalk: all ${#packages[@]} Debian packages present"
  exit 0
fi

echo "triwalk: installing ${#missing[@]} Debian packages: ${missing[*]}"
if [[ "$(id -u)" != "0" ]]; then
  echo "triwalk: error: installing packages needs root (run as root or with sudo)" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "triwalk: packages installed"
