#!/usr/bin/python3
# Plots the CSVs of essential_paper_synthetic (bench/paper_synthetic.cpp) as the paper's
# synthetic figures. Uses Debian's python3-matplotlib (hence /usr/bin/python3).
#
#   scripts/plot_paper_synthetic.py --csv DIR --figures DIR [--merge RUN_DIR ...]
#
# --merge joins the part-A CSVs (synthetic_figA.csv, synthetic_levels_A.csv) of several runs of
# essential_paper_synthetic, e.g. one per --n, into DIR first (rows in the order of the runs), so
# that a long sweep can be run in pieces.
#
# Writes synthetic_figA.png (time to 99% reliability against the inlier ratio, a panel per number
# of matches), synthetic_figA_points.png (the same per solver, a
# line per number of matches) and synthetic_figB.png (reliability against time at very few inliers,
# and at 60% inliers for several block sizes), when the CSVs they need exist.
# Licensed under the Apache License, Version 2.0.

import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# One colour per method, fixed across figures; the module's solvers first, OpenCV's last.
COLOURS = {
    "lm": "tab:red",
    "gn": "tab:green",
    "nister": "tab:blue",
    "robust": "tab:purple",
    "ours-adaptive": "tab:orange",
    "cv-RANSAC": "tab:gray",
    "cv-USAC_MAGSAC": "black",
}
LABELS = {
    "lm": "LM (Alg. 1), preemptive",
    "gn": "GN (Alg. 2), preemptive",
    "nister": "5-point (Alg. 4), preemptive",
    "robust": "Robust (Alg. 3), preemptive",
    "ours-adaptive": "findEssentialMatIter default (adaptive)",
    "cv-RANSAC": "cv::findEssentialMat RANSAC",
    "cv-USAC_MAGSAC": "cv::findEssentialMat USAC_MAGSAC",
}
MARKERS = {100: "o", 250: "s", 500: "^", 1000: "D"}
# Figure A's methods differ by marker as well as colour.
METHOD_MARKERS = {"lm": "o", "gn": "s", "nister": "^", "robust": "x", "ours-adaptive": "D",
                  "cv-RANSAC": "v", "cv-USAC_MAGSAC": "P"}


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def num(x):
    try:
        v = float(x)
    except (TypeError, ValueError):
        return math.nan
    return v


def figure_a(rows, column, target, path):
    ns = sorted({int(r["n"]) for r in rows})
    methods = [m for m in COLOURS if any(r["method"] == m for r in rows)]
    cols = 2 if len(ns) > 1 else 1
    nrows = (len(ns) + cols - 1) // cols
    fig, axes = plt.subplots(nrows, cols, figsize=(6 * cols, 4.2 * nrows), squeeze=False)
    for k, n in enumerate(ns):
        ax = axes[k // cols][k % cols]
        for m in methods:
            pts = sorted(
                (num(r["inlier_ratio"]), num(r[column]))
                for r in rows
                if r["method"] == m and int(r["n"]) == n
            )
            xs = [p[0] for p in pts if not math.isnan(p[1])]
            ys = [p[1] for p in pts if not math.isnan(p[1])]
            if not xs:
                continue
            ax.plot(xs, ys, marker=METHOD_MARKERS.get(m, "o"), ms=5, mfc="none",
                    color=COLOURS[m], label=LABELS[m],
                    linestyle="--" if m.startswith("cv-") else "-")
        ax.set_yscale("log")
        ax.set_title(f"N = {n} matches")
        ax.set_xlabel("inlier fraction")
        ax.set_ylabel(f"mean CPU time for {target:.0%} reliability [ms]")
        ax.grid(True, which="both", alpha=0.3)
    for k in range(len(ns), nrows * cols):
        axes[k // cols][k % cols].axis("off")
    handles, labels = axes[0][0].get_legend_handles_labels()
    for ax in axes.flat:
        for h, lab in zip(*ax.get_legend_handles_labels()):
            if lab not in labels:
                handles.append(h)
                labels.append(lab)
    fig.legend(handles, labels, loc="lower center", ncol=min(4, len(labels)), fontsize=8)
    fig.suptitle(f"Time to reach {target:.0%} reliability (RMS < 0.003; missing point: not "
                 "reached within the time cap)", fontsize=10)
    fig.tight_layout(rect=(0, 0.07 + 0.02 * (len(labels) > 4), 1, 0.96))
    fig.savefig(path, dpi=110)
    plt.close(fig)


def figure_a_points(rows, path):
    solvers = [m for m in ("lm", "gn", "nister") if any(r["method"] == m for r in rows)]
    if not solvers:
        return
    fig, axes = plt.subplots(1, len(solvers), figsize=(5 * len(solvers), 4), squeeze=False)
    for k, m in enumerate(solvers):
        ax = axes[0][k]
        for n in sorted({int(r["n"]) for r in rows}):
            pts = sorted(
                (num(r["inlier_ratio"]), num(r["time_to_099_ms"]))
                for r in rows
                if r["method"] == m and int(r["n"]) == n
            )
            xs = [p[0] for p in pts if not math.isnan(p[1])]
            ys = [p[1] for p in pts if not math.isnan(p[1])]
            if xs:
                ax.plot(xs, ys, marker=MARKERS.get(n, "o"), ms=4, color=COLOURS[m],
                        alpha=0.35 + 0.65 * n / 1000, label=f"N = {n}")
        ax.set_yscale("log")
        ax.set_title(LABELS[m])
        ax.set_xlabel("inlier fraction")
        ax.set_ylabel("mean CPU time for 99% reliability [ms]")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


# Figure B tells its curves apart by marker and line style as well as colour, and names each
# curve next to it (direct labels), so that it reads in grey too.
SOLVER_MARKERS = {"lm": "o", "gn": "s", "nister": "^", "robust": "x"}
BLOCK_MARKERS = {10: "o", 25: "s", 50: "^", 100: "D", 200: "v"}
BLOCK_STYLES = {10: ":", 25: "-.", 50: "--", 100: "-", 200: (0, (6, 1, 1, 1, 1, 1))}


def spread_labels(ax, items, min_gap=0.055):
    """Writes each (x, y, text, colour) to the right of its point, moving labels vertically just
    enough (min_gap in axes fraction) that none overlaps another. Call it after the panel's scales
    and limits are set: it places the labels in the panel's current coordinates."""
    to_axes = ax.transAxes.inverted()
    placed = []
    for x, y, text, colour in items:
        fy = to_axes.transform(ax.transData.transform((x, y)))[1]
        placed.append([fy, fy, x, y, text, colour])
    placed.sort(key=lambda p: p[0])
    for k in range(1, len(placed)):
        placed[k][1] = max(placed[k][1], placed[k - 1][1] + min_gap)
    height_points = ax.get_window_extent().height * 72.0 / ax.figure.dpi
    for fy, fy_label, x, y, text, colour in placed:
        ax.annotate(text, (x, y), xytext=(8, (fy_label - fy) * height_points),
                    textcoords="offset points", fontsize=7.5, color=colour, va="center",
                    ha="left", annotation_clip=False,
                    arrowprops=None if fy_label == fy else dict(arrowstyle="-", color=colour,
                                                                lw=0.5, alpha=0.6))


def label_column(ax, items, x_text, y_low, y_high):
    """Writes the (x, y, text, colour) labels in a column at x_text (data), spaced evenly from
    y_low to y_high in the order of their points' y, each with a leader line to its point."""
    items = sorted(items, key=lambda i: i[1])
    step = (y_high - y_low) / max(1, len(items) - 1)
    for k, (x, y, text, colour) in enumerate(items):
        ax.annotate(text, (x, y), xytext=(x_text, y_low + k * step), textcoords="data",
                    fontsize=7.5, color=colour, va="center", ha="left",
                    arrowprops=dict(arrowstyle="-", color=colour, lw=0.6, alpha=0.7))


def m_arrow(ax, pts, text="M doubles"):
    """An arrow along a stretch of a curve saying in which direction M grows."""
    if len(pts) < 3:
        return
    (x0, y0), (x1, y1) = pts[0], pts[2]
    ax.annotate("", xy=(x1, y1), xytext=(x0, y0),
                arrowprops=dict(arrowstyle="-|>", color="black", lw=1.3, alpha=0.8))
    ax.annotate(text, (x0, y0), xytext=(-4, 6), textcoords="offset points", ha="right",
                fontsize=8)


def figure_b(rows, path):
    hard = [r for r in rows if r["part"] == "B-hard"]
    b60 = [r for r in rows if r["part"] == "B-60"]
    fig = plt.figure(figsize=(17, 9.5))
    grid = fig.add_gridspec(2, 6)
    hard_axes = [fig.add_subplot(grid[0, 0:3]), fig.add_subplot(grid[0, 3:6])]
    ratios = sorted({num(r["inlier_ratio"]) for r in hard}, reverse=True)
    n_hard = sorted({int(r["n"]) for r in hard})
    problems_hard = max((int(r["problems"]) for r in hard), default=0)
    for k, ratio in enumerate(ratios[:2]):
        ax = hard_axes[k]
        ends = []
        for m in [m for m in COLOURS if any(r["method"] == m for r in hard)]:
            # The curve is parameterised by M: points in the order of M.
            sel = sorted((r for r in hard if r["method"] == m
                          and num(r["inlier_ratio"]) == ratio), key=lambda r: int(r["knob"]))
            pts = [(num(r["mean_ms"]), num(r["reliability"])) for r in sel]
            if not pts:
                continue
            ax.plot([p[0] for p in pts], [p[1] for p in pts],
                    marker=SOLVER_MARKERS.get(m, "o"), ms=5, mfc="none", color=COLOURS[m],
                    linestyle="-", label=LABELS[m].split(",")[0])
            ends.append((pts[-1][0], pts[-1][1],
                         f"{m} (M up to {int(sel[-1]['knob'])})", COLOURS[m]))
            if m == "nister":
                m_arrow(ax, pts[-5:])
        ax.set_xscale("log")
        ax.set_xlabel("mean CPU time per estimate [ms]")
        ax.set_ylabel(f"reliability (RMS < 0.003), {problems_hard} problems")
        ax.set_title(f"N = {n_hard[0] if n_hard else '?'}, {ratio:.0%} inliers, block 100: one "
                     "curve per solver, M doubling along it (arrow)", fontsize=10)
        ax.set_ylim(-0.03, 1.03)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8, loc="upper left")
        xs = [e[0] for e in ends]
        if xs:
            ax.set_xlim(min(num(r["mean_ms"]) for r in hard) * 0.8, max(xs) * 12)
        spread_labels(ax, ends)

    solvers60 = [m for m in ("gn", "lm") if any(r["method"] == m for r in b60)]
    blocks = sorted({int(r["block"]) for r in b60})
    n60 = sorted({int(r["n"]) for r in b60})
    problems60 = max((int(r["problems"]) for r in b60), default=0)
    lo = min((num(r["mean_ms"]) for r in b60), default=1.0)
    b_axes = [fig.add_subplot(grid[1, 2 * k:2 * k + 2]) for k in range(len(solvers60))]
    for ax, m in zip(b_axes, solvers60):
        starts = []
        for b in blocks:
            pts = sorted(((num(r["mean_ms"]), num(r["reliability"]), int(r["knob"])) for r in b60
                          if r["method"] == m and int(r["block"]) == b), key=lambda p: p[2])
            if not pts:
                continue
            ax.plot([p[0] for p in pts], [p[1] for p in pts], marker=BLOCK_MARKERS.get(b, "o"),
                    ms=4.5, mfc="none", color=COLOURS[m], linestyle=BLOCK_STYLES.get(b, "-"),
                    label=f"B = {b}")
            starts.append((pts[0][0], pts[0][1], f"B = {b} (M = {pts[0][2]})", COLOURS[m]))
            if b == blocks[-1]:
                m_arrow(ax, [(p[0], p[1]) for p in pts[2:6]])
        ax.set_xscale("log")
        # The interesting part is the hook at small M (fewer hypotheses, slower refinement).
        ax.set_xlim(lo * 0.85, lo * 12)
        ax.set_ylim(0.0, 1.03)
        label_column(ax, starts, lo * 2.3, 0.12, 0.55)
        ax.set_xlabel("mean CPU time per estimate [ms]")
        ax.set_ylabel(f"reliability (RMS < 0.003), {problems60} problems")
        ax.set_title(f"{m}, N = {n60[0] if n60 else '?'}, 60% inliers: a curve per block size B,\n"
                     "labelled at its smallest M; M doubles along it (arrow)", fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8, loc="lower right")

    ax = fig.add_subplot(grid[1, 4:6])
    iterations = ax.twinx()
    b_mid = blocks[len(blocks) // 2] if blocks else 0
    for m in solvers60:
        pts = sorted(((int(r["knob"]), num(r["mean_ms"]), num(r["mean_refine_iterations"]))
                      for r in b60 if r["method"] == m and int(r["block"]) == b_mid))
        if not pts:
            continue
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker=SOLVER_MARKERS[m], ms=4.5,
                mfc="none", color=COLOURS[m], linestyle="-", label=f"{m}: CPU time")
        iterations.plot([p[0] for p in pts], [p[2] for p in pts], marker=SOLVER_MARKERS[m],
                        ms=4.5, color=COLOURS[m], linestyle=":",
                        label=f"{m}: final IRLS iterations (right axis)")
        ax.annotate(f"{m}: time", (pts[-1][0], pts[-1][1]), xytext=(-6, 4),
                    textcoords="offset points", ha="right", fontsize=7.5, color=COLOURS[m])
        iterations.annotate(f"{m}: iterations", (pts[0][0], pts[0][2]), xytext=(6, 2),
                            textcoords="offset points", fontsize=7.5, color=COLOURS[m])
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("hypotheses M")
    ax.set_ylabel("mean CPU time [ms] (solid)")
    ax.set_title(f"60% inliers, B = {b_mid}: where the time goes", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    iterations.set_ylabel("final IRLS iterations, mean (dotted)")
    h1, l1 = ax.get_legend_handles_labels()
    h2, l2 = iterations.get_legend_handles_labels()
    ax.legend(h1 + h2, l1 + l2, fontsize=7, loc="upper center")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def merge_part_a(runs, out):
    """Concatenates the part-A CSVs of the run folders into out (one header each)."""
    os.makedirs(out, exist_ok=True)
    for name in ("synthetic_figA.csv", "synthetic_levels_A.csv"):
        header, lines = None, []
        for run in runs:
            with open(os.path.join(run, name), newline="") as f:
                rows = f.read().splitlines()
            if not rows:
                continue
            if header is None:
                header = rows[0]
            elif rows[0] != header:
                sys.exit(f"plot_paper_synthetic.py: {run}/{name} has other columns")
            lines += rows[1:]
        with open(os.path.join(out, name), "w", newline="") as f:
            f.write("\n".join([header] + lines) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--csv", required=True, help="folder with the bench's CSVs")
    ap.add_argument("--figures", required=True, help="folder for the PNGs")
    ap.add_argument("--merge", nargs="+", metavar="RUN_DIR",
                    help="join the part-A CSVs of these runs into --csv first")
    a = ap.parse_args()
    if a.merge:
        merge_part_a(a.merge, a.csv)
    os.makedirs(a.figures, exist_ok=True)
    written = []
    fig_a = os.path.join(a.csv, "synthetic_figA.csv")
    if os.path.exists(fig_a):
        rows = read(fig_a)
        figure_a(rows, "time_to_099_ms", 0.99, os.path.join(a.figures, "synthetic_figA.png"))
        written.append("synthetic_figA.png")
        figure_a_points(rows, os.path.join(a.figures, "synthetic_figA_points.png"))
        written.append("synthetic_figA_points.png")
    levels_b = os.path.join(a.csv, "synthetic_levels_B.csv")
    if os.path.exists(levels_b):
        figure_b(read(levels_b), os.path.join(a.figures, "synthetic_figB.png"))
        written.append("synthetic_figB.png")
    if not written:
        sys.exit("plot_paper_synthetic.py: no CSV found in " + a.csv)
    print("plot_paper_synthetic.py: wrote " + ", ".join(written))


if __name__ == "__main__":
    main()
