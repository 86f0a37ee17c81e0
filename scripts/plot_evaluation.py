#!/usr/bin/python3
"""Plots the evaluation written by `vdc evaluate` (paper figure 4 and its extensions).
Usage: plot_evaluation.py DIR/summary.json OUT_DIR

Writes OUT_DIR/evaluation_<planner>.png for each planner: the median MAP error over the
sequences after each view, one line per visibility setting, with the single-view baselines'
median error of each setting as horizontal lines of the same colour (PPF dashed, PPF followed by
ICP dotted). When several planners
were run, OUT_DIR/evaluation_planners.png compares them, one panel per visibility setting.
With camera streams (`--stream-rate`), OUT_DIR/evaluation_<stream>.png shows, per visibility
setting, each sequence's MAP error against the stream's time (a step at every fused frame, from
OUT_DIR/errors.csv beside the summary) with the median at each view's end, and the median at each
view's end against the random planner's one cloud per view.
The y axis is logarithmic (errors span from ~1 to 180 degrees) with plain degree tick labels.
"""
import csv
import json
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker as mticker  # noqa: E402

DEGREE_TICKS = [1, 2, 5, 10, 20, 50, 100, 180]


def setting_label(setting):
    if setting["visibility"] == "all":
        return "all (100 %)"
    radius_cm = float(setting["visibility"]) * 100
    return f"r_vis {radius_cm:g} cm ({100 * setting['visible_fraction']:.1f} %)"


def degree_axis(ax, views):
    ax.set_yscale("log")
    ax.set_ylim(0.5, 200)
    ax.yaxis.set_major_locator(mticker.FixedLocator(DEGREE_TICKS))
    ax.yaxis.set_major_formatter(mticker.FixedFormatter([str(t) for t in DEGREE_TICKS]))
    ax.yaxis.set_minor_formatter(mticker.NullFormatter())
    ax.set_xlim(0.8, views + 0.2)
    ax.xaxis.set_major_locator(mticker.MaxNLocator(integer=True))
    ax.set_xlabel("number of views")
    ax.set_ylabel("median MAP error [deg]")
    ax.grid(True, which="major", alpha=0.3)


def floor(values):
    # A perfect estimate (0 degrees) has no place on a log axis: show it at the axis floor.
    return [max(v, 0.5) for v in values]


# Line styles of the single-view baselines in summary.json, in the order drawn.
BASELINE_STYLES = [("baseline", "--"), ("baseline_icp", ":")]


def plot_planner(summary, planner, out_path):
    views = summary["views"]
    figure, ax = plt.subplots(figsize=(7.5, 5))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    baselines = [(summary[key], style) for key, style in BASELINE_STYLES if summary.get(key)]
    for k, setting in enumerate(planner["settings"]):
        colour = colours[k % len(colours)]
        x = list(range(1, len(setting["median_error_deg"]) + 1))
        ax.plot(x, floor(setting["median_error_deg"]), marker="o", markersize=3, color=colour,
                label=setting_label(setting))
        for baseline, style in baselines:
            for s in baseline["settings"]:
                if s["visibility"] == setting["visibility"]:
                    ax.axhline(max(s["median_error_deg"], 0.5), color=colour, linestyle=style,
                               linewidth=1, alpha=0.7)
    degree_axis(ax, views)
    title = (f"Median MAP error, planner '{planner['planner']}' "
             f"({summary['sequences']} sequences, {planner['ms_per_view']:.0f} ms/view)")
    for baseline, style in baselines:
        ax.plot([], [], color="grey", linestyle=style,
                label=f"{baseline['name']}, single view ({baseline['ms_per_view']:.0f} ms/view)")
    ax.set_title(title, fontsize=10)
    ax.legend(fontsize=8, loc="best", framealpha=0.8)
    figure.tight_layout()
    figure.savefig(out_path, dpi=110)
    plt.close(figure)


def plot_planners(summary, out_path):
    planners = summary["planners"]
    settings = [s["visibility"] for s in planners[0]["settings"]]
    columns = min(4, len(settings))
    rows = (len(settings) + columns - 1) // columns
    figure, axes = plt.subplots(rows, columns, figsize=(4.2 * columns, 3.4 * rows), squeeze=False)
    for index, visibility in enumerate(settings):
        ax = axes[index // columns][index % columns]
        for planner in planners:
            setting = next(s for s in planner["settings"] if s["visibility"] == visibility)
            x = list(range(1, len(setting["median_error_deg"]) + 1))
            ax.plot(x, floor(setting["median_error_deg"]), marker="o", markersize=3,
                    label=planner["planner"])
        degree_axis(ax, summary["views"])
        ax.set_title(setting_label(setting), fontsize=9)
        ax.legend(fontsize=7)
    for index in range(len(settings), rows * columns):
        axes[index // columns][index % columns].axis("off")
    figure.suptitle(f"Median MAP error by planner ({summary['sequences']} sequences)", fontsize=11)
    figure.tight_layout()
    figure.savefig(out_path, dpi=110)
    plt.close(figure)


def stream_rows(errors_path, name, visibility):
    """The stream's rows of one setting (fusions and dwell ends), per sequence in time order, as
    (time, error, views fused)."""
    by_sequence = {}
    with open(errors_path, newline="") as handle:
        for row in csv.DictReader(handle):
            if row["planner"] == name and row["visibility"] == visibility and \
                    row["event"] in ("fused", "dwell_end"):
                by_sequence.setdefault(int(row["sequence"]), []).append(
                    (float(row["time_s"]), float(row["map_error_deg"]), int(row["views_fused"])))
    return {s: sorted(rows) for s, rows in by_sequence.items()}


def log_degree_axis(ax):
    ax.set_yscale("log")
    ax.set_ylim(0.5, 200)
    ax.yaxis.set_major_locator(mticker.FixedLocator(DEGREE_TICKS))
    ax.yaxis.set_major_formatter(mticker.FixedFormatter([str(t) for t in DEGREE_TICKS]))
    ax.yaxis.set_minor_formatter(mticker.NullFormatter())
    ax.set_ylabel("MAP error [deg]")
    ax.grid(True, which="major", alpha=0.3)


def plot_stream(summary, stream, errors_path, out_path):
    settings = stream["settings"]
    random = next((p for p in summary["planners"] if p["planner"] == "random"), None)
    figure, axes = plt.subplots(len(settings), 3, figsize=(16, 4 * len(settings)), squeeze=False)
    for row, setting in enumerate(settings):
        visibility = setting["visibility"]
        rows = stream_rows(errors_path, stream["name"], visibility)
        ax = axes[row][0]
        for samples in rows.values():
            ax.step([t for t, _, _ in samples], floor([e for _, e, _ in samples]), where="post",
                    linewidth=0.8, alpha=0.6)
        log_degree_axis(ax)
        ax.set_xlabel("stream time [s] (a step at every fused frame)")
        ax.set_title(f"{stream['name']}, {visibility}: each sequence's error over time "
                     f"({100 * setting['featurised_fraction']:.1f} % of frames featurised)",
                     fontsize=9)
        ax = axes[row][1]
        for samples in rows.values():
            ax.plot([n for _, _, n in samples], floor([e for _, e, _ in samples]), marker=".",
                    linewidth=0.8, alpha=0.6)
        log_degree_axis(ax)
        ax.set_xlabel("views fused")
        ax.xaxis.set_major_locator(mticker.MaxNLocator(integer=True))
        ax.set_title("each sequence's error against the views fused", fontsize=9)
        ax = axes[row][2]
        medians = setting["median_error_deg_at_view_ends"]
        x = list(range(1, len(medians) + 1))
        ax.plot(x, floor(medians), marker="o", markersize=3,
                label=f"{stream['name']} at each view's end")
        if random:
            one = next((s for s in random["settings"] if s["visibility"] == visibility), None)
            if one:
                ax.plot(x, floor(one["median_error_deg"][:len(x)]), marker="s", markersize=3,
                        label="random, one cloud per view")
        degree_axis(ax, len(x))
        ax.set_title(f"median over {summary['sequences']} sequences; truth inside cone90 at "
                     f"the end: {setting['final_inside_cone90_fraction']:.2f}", fontsize=9)
        ax.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(out_path, dpi=110)
    plt.close(figure)


def main(summary_path, out_dir):
    summary = json.loads(pathlib.Path(summary_path).read_text())
    out_dir = pathlib.Path(out_dir)
    written = []
    for planner in summary["planners"]:
        path = out_dir / f"evaluation_{planner['planner']}.png"
        plot_planner(summary, planner, path)
        written.append(path)
    if len(summary["planners"]) > 1:
        path = out_dir / "evaluation_planners.png"
        plot_planners(summary, path)
        written.append(path)
    errors_path = pathlib.Path(summary_path).parent / "errors.csv"
    for stream in summary.get("streams", []):
        path = out_dir / f"evaluation_{stream['name']}.png"
        plot_stream(summary, stream, errors_path, path)
        written.append(path)
    for path in written:
        print(f"wrote {path}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_evaluation.py SUMMARY.json OUT_DIR")
    main(sys.argv[1], sys.argv[2])
