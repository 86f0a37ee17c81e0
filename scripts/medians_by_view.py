#!/usr/bin/python3
"""Median MAP error of every method in a `vdc evaluate` errors.csv, per visibility setting and
view index. Usage: medians_by_view.py DIR/errors.csv

summary.json gives each single-view baseline one median over all its views; this splits the
baselines' rows by view index like ours, so that the k-th view of every sequence is compared
with ours after k views on exactly the same clouds. Stream rows (event != "view") are left out.
"""
import collections
import csv
import statistics
import sys


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.strip())
    errors = collections.defaultdict(list)
    with open(sys.argv[1], newline="") as table:
        for row in csv.DictReader(table):
            if row.get("event", "view") not in ("view", ""):
                continue
            key = (row["visibility"], row["planner"], int(row["view"]))
            errors[key].append(float(row["map_error_deg"]))
    methods = sorted({(visibility, planner) for visibility, planner, _ in errors})
    for visibility, planner in methods:
        views = sorted(view for v, p, view in errors if (v, p) == (visibility, planner))
        medians = [statistics.median(errors[(visibility, planner, view)]) for view in views]
        print(f"{visibility}\t{planner}\t" + " / ".join(f"{m:.4f}" for m in medians))


if __name__ == "__main__":
    main()
