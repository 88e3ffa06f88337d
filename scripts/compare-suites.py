#!/usr/bin/python3
"""Edge collapse's probe errors in two `triwalk suite` runs, paired probe by probe.

Usage: compare-suites.py BEFORE/suite.json AFTER/suite.json [BEFORE_LABEL AFTER_LABEL]

Prints a Markdown table: per scene and count, both probe means, the mean of
the per-probe differences relative to the first run's mean with its standard
error, and how many probes the second run serves better. Rows present in only
one run are skipped. Both runs must have scored the same probes (the same
captures), which the suite's JSON records but cannot prove; the probe counts
are checked.
"""
import json
import math
import sys


def rows_by_key(path):
    with open(path) as file:
        rows = json.load(file)["rows"]
    return {(row["scene"], row["samples"]): row for row in rows}


def main():
    if len(sys.argv) not in (3, 5):
        sys.exit(__doc__.strip().splitlines()[2])
    before, after = rows_by_key(sys.argv[1]), rows_by_key(sys.argv[2])
    before_label, after_label = sys.argv[3:5] if len(sys.argv) == 5 else ("before", "after")
    print(f"| scene | samples | {before_label} | {after_label} | {after_label} vs {before_label} | probes better |")
    print("|---|---|---|---|---|---|")
    relative_changes = []
    for key, row in before.items():
        if key not in after:
            continue
        x = row["probe_errors"]["edge_collapse"]
        y = after[key]["probe_errors"]["edge_collapse"]
        if len(x) != len(y) or len(x) < 2:
            sys.exit(f"{sys.argv[2]}: {key[0]} at {key[1]} has {len(y)} probes, {sys.argv[1]} {len(x)}")
        n = len(x)
        differences = [b - a for a, b in zip(x, y)]
        mean_difference = sum(differences) / n
        deviation = math.sqrt(sum((d - mean_difference) ** 2 for d in differences) / (n - 1))
        mean_before, mean_after = sum(x) / n, sum(y) / n
        better = sum(1 for d in differences if d < 0)
        relative_changes.append(mean_difference / mean_before)
        print(f"| {key[0]} | {key[1]} | {mean_before:.4f} | {mean_after:.4f} | "
              f"{100 * mean_difference / mean_before:+.1f}% +- {100 * deviation / math.sqrt(n) / mean_before:.1f}% | "
              f"{better} of {n} |")
    if relative_changes:
        print(f"\nmean over {len(relative_changes)} rows: {100 * sum(relative_changes) / len(relative_changes):+.1f}%")


if __name__ == "__main__":
    main()
