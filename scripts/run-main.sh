#!/usr/bin/env bash
# The main job, end to end on a fresh Debian bookworm machine (as root):
# install what is missing, build, capture the built-in scene, then print a
# summary. Outputs go to $TRIWALK_OUT (default: out/builtin).
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh build
cmake --preset release >/dev/null
cmake --build --preset release --target triwalk

triwalk=build/release/app/triwalk
out="${TRIWALK_OUT:-out/builtin}"
mkdir -p "$out"

if [[ -f "$out/dataset/manifest.json" && -z "${TRIWALK_RECAPTURE:-}" ]]; then
  echo "== capture: reusing $out/dataset (set TRIWALK_RECAPTURE=1 to capture again)"
else
  echo "== capture: built-in scene, 30 paths x 15 samples + 20 probes at 1024x512"
  "$triwalk" capture --scene builtin --out "$out/dataset" --probes 20
fi
"$triwalk" export-png --dataset "$out/dataset" --views 0,224,p0 --out "$out/png"
echo "== done: data set in $out/dataset, panoramas as PNG in $out/png"
