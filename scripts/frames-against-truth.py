#!/usr/bin/env python3
"""Table 2: the frames a walker sees, judged against the scene itself.

For one data set made by `triwalk capture` and its edge-collapse
selection: writes the baselines at the same count (`eval --baselines-out`),
renders every walk path with each selection and with the dense capture
(`render --truth`), and prints, per method, the mean PSNR and SSIM of its
frames against the truth, the mean of the worst 5% of frames, and the
difference from edge collapse with the standard error of the frame-by-frame
differences. Writes the table to OUT/table2.md and the numbers to
OUT/table2.json; the frames, truth frames and heatmaps stay in OUT/frames.

usage: frames-against-truth.py --dataset D --selection S --walks W1.txt W2.txt ... --out OUT
       [--triwalk build/release/app/triwalk] [--size 1280x720]
"""
import argparse
import json
import math
import os
import subprocess
import sys

METHODS = [("edge_collapse", "edge collapse"), ("uniform", "uniform"), ("kmedoids", "k-medoids"),
           ("geodesic_kmedoids", "k-medoids, walking"), ("farthest_point", "farthest point, walking"),
           ("dense", "dense (every sample)")]


def run(command):
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if result.returncode != 0:
        sys.exit(f"frames-against-truth.py: {' '.join(command)} failed:\n{result.stderr.strip()}")
    return result.stdout


def paired(candidate, baseline):
    """The mean of the frame-by-frame differences candidate - baseline, and its standard error."""
    diffs = [c - b for c, b in zip(candidate, baseline)]
    n = len(diffs)
    mean = sum(diffs) / n
    se = math.sqrt(sum((d - mean) ** 2 for d in diffs) / (n - 1) / n) if n > 1 else float("nan")
    return mean, se


def worst_share(values):
    worst = sorted(values)[:max(1, (len(values) + 19) // 20)]
    return sum(worst) / len(worst)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dataset", required=True)
    parser.add_argument("--selection", required=True)
    parser.add_argument("--walks", nargs="+", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--triwalk", default="build/release/app/triwalk")
    parser.add_argument("--size", default="1280x720")
    args = parser.parse_args()
    for path in [args.selection] + args.walks:
        if not os.path.isfile(path):
            sys.exit(f"frames-against-truth.py: {path}: no such file")
    os.makedirs(args.out, exist_ok=True)
    baselines = os.path.join(args.out, "baselines")
    run([args.triwalk, "eval", "--quiet", "--dataset", args.dataset, "--selection", args.selection,
         "--baselines-out", baselines, "--json", os.path.join(args.out, "table1.json")])
    with open(os.path.join(args.out, "table1.json")) as f:
        probe_means = {row["method"]: row["probe_mean_error"] for row in json.load(f)["rows"]}
    probe_means["dense"] = probe_means.get("initial")

    scores = {}
    for method, _ in METHODS:
        selection = {"edge_collapse": args.selection, "dense": None}.get(method, os.path.join(baselines, method + ".json"))
        if selection is not None and not os.path.isfile(selection):
            print(f"{method}: not built at this count (see eval), left out")
            continue
        psnr, ssim = [], []
        for walk in args.walks:
            name = f"{method}_{os.path.splitext(os.path.basename(walk))[0]}"
            stats = os.path.join(args.out, "stats", name + ".json")
            os.makedirs(os.path.dirname(stats), exist_ok=True)
            command = [args.triwalk, "render", "--truth", "--dataset", args.dataset, "--path", walk, "--size", args.size,
                       "--out", os.path.join(args.out, "frames", name), "--stats", stats]
            if selection is not None:
                command += ["--selection", selection]
            run(command)
            with open(stats) as f:
                frames = json.load(f)["frames"]
            psnr += [frame["psnr_truth"] for frame in frames]
            ssim += [frame["ssim_truth"] for frame in frames]
            print(f"{name}: {len(frames)} frames, mean PSNR {sum(psnr[-len(frames):]) / len(frames):.2f} dB", flush=True)
        scores[method] = {"psnr": psnr, "ssim": ssim}

    reference = scores["edge_collapse"]
    lines = [f"| method | probe mean error | mean PSNR (dB) | worst 5% PSNR | mean SSIM | worst 5% SSIM | "
             f"edge collapse PSNR better by | edge collapse SSIM better by |", "|---|---|---|---|---|---|---|---|"]
    summary = {}
    for method, label in METHODS:
        if method not in scores:
            continue
        s = scores[method]
        n = len(s["psnr"])
        row = {"frames": n, "mean_psnr": sum(s["psnr"]) / n, "worst_5_percent_psnr": worst_share(s["psnr"]),
               "mean_ssim": sum(s["ssim"]) / n, "worst_5_percent_ssim": worst_share(s["ssim"]),
               "probe_mean_error": probe_means.get(method)}
        if method == "edge_collapse":
            versus = ("", "")
        else:
            dp, sp = paired(reference["psnr"], s["psnr"])
            ds, ss = paired(reference["ssim"], s["ssim"])
            row.update({"collapse_minus_psnr": dp, "collapse_minus_psnr_se": sp,
                        "collapse_minus_ssim": ds, "collapse_minus_ssim_se": ss})
            versus = (f"{dp:+.2f} +- {sp:.2f} dB", f"{ds:+.4f} +- {ss:.4f}")
        summary[method] = row
        probe = f"{row['probe_mean_error']:.4f}" if row["probe_mean_error"] is not None else "-"
        lines.append(f"| {label} | {probe} | {row['mean_psnr']:.2f} | {row['worst_5_percent_psnr']:.2f} | "
                     f"{row['mean_ssim']:.4f} | {row['worst_5_percent_ssim']:.4f} | {versus[0]} | {versus[1]} |")
    table = "\n".join(lines)
    frames = len(reference["psnr"])
    header = (f"{frames} frames of {args.size} on {len(args.walks)} walks through {args.dataset}; "
              f"paired over frames, +- one standard error\n\n")
    with open(os.path.join(args.out, "table2.md"), "w") as f:
        f.write(header + table + "\n")
    with open(os.path.join(args.out, "table2.json"), "w") as f:
        json.dump({"walks": args.walks, "size": args.size, "methods": summary}, f, indent=1)
    print("\n" + header + table)


if __name__ == "__main__":
    main()
