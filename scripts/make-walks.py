#!/usr/bin/env python3
"""Seeded walk paths through a data set's samples, for judging frames
against the truth (render --truth, docs/RESULTS.md "Table 2").

Each walk is a straight segment between two samples 8.7 to 23.2 sample
spacings apart (3 to 8 m on the built-in scene; a level captured at 1.8 m
spacings gets walks of 16 to 43 m) that stays within 0.75 sample
spacings of some sample all the way (so it runs
where the capture was, not through walls or outside the region), walked
in FRAMES poses looking along the way and swinging 35 degrees to each
side, so that frames look past the references at every angle. Writes
OUT_PREFIX_1.txt ... in the camera path format (x y z yaw pitch).

usage: make-walks.py DATASET_DIR OUT_PREFIX [--walks 4] [--frames 30] [--seed 1] [--length 8.7 23.2]
"""
import argparse
import json
import math
import random
import sys


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dataset")
    parser.add_argument("out_prefix")
    parser.add_argument("--walks", type=int, default=4)
    parser.add_argument("--frames", type=int, default=30)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--length", type=float, nargs=2, default=[8.7, 23.2], metavar=("SHORTEST", "LONGEST"),
                        help="a walk's length in sample spacings")
    args = parser.parse_args()
    manifest_path = f"{args.dataset}/manifest.json"
    try:
        with open(manifest_path) as f:
            manifest = json.load(f)
        samples = [tuple(s["position"]) for s in manifest["samples"]]
    except (OSError, ValueError, KeyError, TypeError) as error:
        sys.exit(f"make-walks.py: {manifest_path}: {error}")
    if len(samples) < 2:
        sys.exit(f"make-walks.py: {manifest_path}: fewer than 2 samples")

    def nearest(x, y):
        return min(math.hypot(x - sx, y - sy) for sx, sy, _ in samples)

    # The sample spacing: the median distance to the nearest other sample.
    gaps = sorted(min(math.hypot(a[0] - b[0], a[1] - b[1]) for b in samples if b is not a) for a in samples)
    spacing = gaps[len(gaps) // 2]
    shortest, longest = args.length[0] * spacing, args.length[1] * spacing
    rng = random.Random(args.seed)
    for walk in range(1, args.walks + 1):
        for _ in range(10000):
            a, b = rng.sample(samples, 2)
            length = math.hypot(b[0] - a[0], b[1] - a[1])
            if not shortest <= length <= longest:
                continue
            steps = int(length / 0.1) + 1
            if all(nearest(a[0] + (b[0] - a[0]) * i / steps, a[1] + (b[1] - a[1]) * i / steps) <= 0.75 * spacing
                   for i in range(steps + 1)):
                break
        else:
            sys.exit(f"make-walks.py: {manifest_path}: no segment of {shortest:.1f} to {longest:.1f} m stays among the samples")
        heading = math.degrees(math.atan2(b[1] - a[1], b[0] - a[0]))
        phase = rng.uniform(0.0, 2.0 * math.pi)
        path = f"{args.out_prefix}_{walk}.txt"
        with open(path, "w") as out:
            out.write(f"# walk {walk} of {args.walks} through {args.dataset} (scene {manifest.get('scene', '?')}), "
                      f"seed {args.seed}: scripts/make-walks.py\n# x y z yaw pitch\n")
            for i in range(args.frames):
                t = i / (args.frames - 1)
                x, y = a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t
                yaw = heading + 35.0 * math.sin(2.0 * math.pi * t + phase)
                pitch = -5.0 + 5.0 * math.sin(4.0 * math.pi * t + phase)
                out.write(f"{x:.3f} {y:.3f} {a[2]:.3f} {yaw:.1f} {pitch:.1f}\n")
        print(f"wrote {path}: {length:.1f} m from ({a[0]:.2f}, {a[1]:.2f}) to ({b[0]:.2f}, {b[1]:.2f})")


if __name__ == "__main__":
    main()
