#!/usr/bin/env bash
# The main job, end to end on a fresh Debian bookworm machine (as root):
# install what is missing, build, capture the built-in scene, decimate it
# with the paper's threshold (then refine that selection), print the Table
# 1 report, then open the
# viewer when there is a display, or render headless walkthrough frames
# (the paper's Fig. 7 and 8) when there is none. Outputs go to
# $TRIWALK_OUT (default: out/builtin).
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
  echo "== capture: built-in scene, 30 paths x 15 samples + 200 probes at 1024x512"
  "$triwalk" capture --scene builtin --out "$out/dataset" --probes 200
fi
"$triwalk" export-png --dataset "$out/dataset" --views 0,224,p0 --out "$out/png" >/dev/null

echo "== decimate: edge collapse to the paper's error threshold 1.85, then the refinement at that count"
"$triwalk" decimate --dataset "$out/dataset" --out "$out/selection.json" --max-error 1.85

echo "== eval: Table 1"
"$triwalk" eval --dataset "$out/dataset" --selection "$out/selection.json" --json "$out/table1.json" | tee "$out/report.txt"

if [[ -n "${DISPLAY:-}" ]]; then
  echo "== view: walk with W A S D / arrows, drag to look; the panels step the decimation"
  "$triwalk" view --dataset "$out/dataset" --selection "$out/selection.json"
else
  echo "== render: no display, so headless frames (rotate at a point, translate along a line)"
  "$triwalk" render --dataset "$out/dataset" --selection "$out/selection.json" --path rotate --frames 12 --out "$out/frames_rotate"
  "$triwalk" render --dataset "$out/dataset" --selection "$out/selection.json" --path translate --frames 12 --out "$out/frames_translate"
fi
echo "== done: data set $out/dataset, selection $out/selection.json, report $out/report.txt, frames in $out/frames_*"
