#!/usr/bin/env python3
# Tables and figures of the rail experiment (docs/experiments/rail.md) in the layout of the paper's
# results figure, from the per-estimate CSV of bench/paper_rail.cpp:
#   rail_reliability_time.csv   per sequence, variant, solver, budget: reliability over the pairs
#                               with at least MIN_MOTION px of motion, wall-clock and CPU time,
#                               hypotheses, inlier rate
#   rail_reliability_motion.csv per sequence, variant, solver, budget, motion bin: reliability and
#                               the mean inlier rate of the matches
#   rail_<variant>.png          rows: sequences; left: reliability against time (pairs with at
#                               least MIN_MOTION px; x: mean CPU time of the calls, one point
#                               per budget); centre and right: reliability against
#                               average pixel motion at the largest and at the 10 ms budget, with
#                               the inlier rate on a second axis and the pairs per bin (n)
# Uses matplotlib (Debian python3-matplotlib). Licensed under the Apache License, Version 2.0.
import argparse
import csv
import gzip
import math
import os
import statistics
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import FixedLocator, NullFormatter, ScalarFormatter  # noqa: E402

MIN_MOTION = 10.0  # px: the paper's left panels aggregate the pairs with at least this motion
BIN_EDGES = [0, 5, 10, 20, 40, 80, 160, math.inf]  # px of average motion
# The paper's key: LM red solid, GN green dashed with x, robust magenta dotted with squares,
# 5-point blue dashed with circles, inlier ratio teal; our default and OpenCV added.
STYLE = {
    "lm": dict(color="red", linestyle="-", marker="|", label="lm (LM)"),
    "gn": dict(color=(0.0, 0.4, 0.0), linestyle="--", marker="x", label="gn (GN)"),
    "robust": dict(color=(0.75, 0.0, 0.75), linestyle=":", marker="s", mfc="none",
                   label="robust"),
    "nister": dict(color="blue", linestyle="--", marker="o", mfc="none", label="nister (5-point)"),
    "gn+nister": dict(color="darkorange", linestyle="-.", marker="^", mfc="none",
                      label="gn+nister (default)"),
    "opencv": dict(color="grey", linestyle="none", marker="D", label="cv::findEssentialMat"),
}
INLIER_COLOR = (0.0, 0.56, 0.56)


def plain_log_axis(ax, ticks):
    """Log-scale x axis labelled with plain numbers (1, 2, 5, 10, ...) instead of powers of ten."""
    ax.set_xscale("log")
    ax.xaxis.set_major_locator(FixedLocator(ticks))
    ax.xaxis.set_major_formatter(ScalarFormatter())
    ax.xaxis.set_minor_formatter(NullFormatter())


def read_rows(path):
    opener = gzip.open if path.endswith(".gz") else open
    with opener(path, "rt", newline="") as f:
        return list(csv.DictReader(f))


def bin_of(motion):
    for k in range(len(BIN_EDGES) - 1):
        if BIN_EDGES[k] <= motion < BIN_EDGES[k + 1]:
            return k
    return len(BIN_EDGES) - 2


def bin_label(k):
    lo, hi = BIN_EDGES[k], BIN_EDGES[k + 1]
    return f">= {lo:g}" if hi == math.inf else f"{lo:g}-{hi:g}"


def ordered(values, order):
    return sorted(set(values), key=lambda v: (order.index(v) if v in order else len(order), v))


def write_markdown(path, time_table, motion_table, sequences, variants, solvers, budgets):
    """The tables behind the figures, as Markdown (docs/experiments/rail.md quotes them)."""
    fast = 10.0 if 10.0 in budgets else min(budgets)
    lines = []
    for s in sequences:
        for v in variants:
            sel = [t for t in time_table if t["sequence"] == s and t["variant"] == v]
            if not sel:
                continue
            rate = statistics.mean(float(t["mean_true_inlier_rate"]) for t in sel)
            lines.append(f"**{s}, {v}**: reliability over the {sel[0]['pairs']} pairs with >= "
                         f"{MIN_MOTION:g} px of motion (mean inlier rate {rate:.2f}); in brackets "
                         "the mean CPU ms per call\n")
            lines.append("| solver | " + " | ".join(f"{b:g} ms" for b in budgets) + " |")
            lines.append("|---|" + "---|" * len(budgets))
            for so in solvers:
                cells = []
                for b in ([0.0] if so == "opencv" else budgets):
                    t = [t for t in sel if t["solver"] == so and float(t["budget_ms"]) == b]
                    cells.append(f"{float(t[0]['reliability']):.3f} ({float(t[0]['mean_cpu_ms']):.1f})"
                                 if t else "-")
                if so == "opencv":
                    cells = [f"no budget: {cells[0]}"] + [""] * (len(budgets) - 1)
                lines.append(f"| {so} | " + " | ".join(cells) + " |")
            lines.append("")
    for s in sequences:
        for v in variants:
            sel = [t for t in motion_table if t["sequence"] == s and t["variant"] == v]
            if not sel:
                continue
            bins = sorted({t["motion_bin_px"] for t in sel},
                          key=lambda b: float(b.split("-")[0].replace(">= ", "")))
            lines.append(f"**{s}, {v}**: reliability by average pixel motion (pairs per bin in "
                         "the header; last row: mean inlier rate of the matches)\n")
            head = []
            for b in bins:
                n = max(t["pairs"] for t in sel if t["motion_bin_px"] == b)
                head.append(f"{b} px ({n})")
            lines.append("| solver | budget | " + " | ".join(head) + " |")
            lines.append("|---|---|" + "---|" * len(bins))
            for so in solvers:
                for b in ([0.0] if so == "opencv" else [max(budgets), fast]):
                    row = []
                    for bi in bins:
                        t = [t for t in sel if t["solver"] == so and float(t["budget_ms"]) == b
                             and t["motion_bin_px"] == bi]
                        row.append(f"{float(t[0]['reliability']):.2f}" if t else "-")
                    label = "none" if so == "opencv" else f"{b:g} ms"
                    lines.append(f"| {so} | {label} | " + " | ".join(row) + " |")
            rates = []
            for bi in bins:
                t = [t for t in sel if t["motion_bin_px"] == bi]
                rates.append(f"{float(t[0]['mean_true_inlier_rate']):.2f}")
            lines.append("| inlier rate | | " + " | ".join(rates) + " |")
            lines.append("")
    with open(path, "w") as f:
        f.write("\n".join(lines))


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("csv", help="per-estimate CSV of essential_paper_rail (.csv or .csv.gz)")
    ap.add_argument("--results", required=True, help="directory for the summary CSVs")
    ap.add_argument("--figures", required=True, help="directory for the PNG figures")
    ap.add_argument("--machine", default="", help="text added to the figure titles")
    args = ap.parse_args()

    rows = read_rows(args.csv)
    if not rows:
        sys.exit("plot_rail.py: no rows in " + args.csv)
    for r in rows:
        r["motion_px"] = float(r["motion_px"])
        r["true_inlier_rate"] = float(r["true_inlier_rate"])
        r["budget_ms"] = float(r["budget_ms"])
        r["time_ms"] = float(r["time_ms"])
        r["cpu_ms"] = float(r["cpu_ms"])
        r["hypotheses"] = int(r["hypotheses"])
        r["correct"] = int(r["correct"])
    sequences = ordered([r["sequence"] for r in rows], ["horizontal", "optic"])
    variants = ordered([r["variant"] for r in rows], ["best20", "random20"])
    solvers = ordered([r["solver"] for r in rows], list(STYLE))
    budgets = sorted({r["budget_ms"] for r in rows if r["solver"] != "opencv"})
    os.makedirs(args.results, exist_ok=True)
    os.makedirs(args.figures, exist_ok=True)

    # cell[(sequence, variant, solver, budget)] -> rows
    cells = defaultdict(list)
    for r in rows:
        cells[(r["sequence"], r["variant"], r["solver"], r["budget_ms"])].append(r)

    def configs(solver):
        return [0.0] if solver == "opencv" else budgets

    # Reliability against time, pairs with at least MIN_MOTION px.
    time_table = []
    for s in sequences:
        for v in variants:
            for so in solvers:
                for b in configs(so):
                    sel = [r for r in cells[(s, v, so, b)] if r["motion_px"] >= MIN_MOTION]
                    if not sel:
                        continue
                    time_table.append(dict(
                        sequence=s, variant=v, solver=so, budget_ms=f"{b:g}", pairs=len(sel),
                        correct=sum(r["correct"] for r in sel),
                        reliability=f"{sum(r['correct'] for r in sel) / len(sel):.3f}",
                        median_time_ms=f"{statistics.median(r['time_ms'] for r in sel):.2f}",
                        mean_time_ms=f"{statistics.mean(r['time_ms'] for r in sel):.2f}",
                        mean_cpu_ms=f"{statistics.mean(r['cpu_ms'] for r in sel):.2f}",
                        mean_hypotheses=f"{statistics.mean(r['hypotheses'] for r in sel):.0f}",
                        mean_true_inlier_rate=(
                            f"{statistics.mean(r['true_inlier_rate'] for r in sel):.3f}")))
    with open(os.path.join(args.results, "rail_reliability_time.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(time_table[0]) if time_table else
                           ["sequence", "variant", "solver", "budget_ms", "pairs", "correct",
                            "reliability", "median_time_ms", "mean_time_ms", "mean_cpu_ms",
                            "mean_hypotheses", "mean_true_inlier_rate"])
        w.writeheader()
        w.writerows(time_table)

    # Reliability against average pixel motion, per bin.
    motion_table = []
    for s in sequences:
        for v in variants:
            for so in solvers:
                for b in configs(so):
                    by_bin = defaultdict(list)
                    for r in cells[(s, v, so, b)]:
                        by_bin[bin_of(r["motion_px"])].append(r)
                    for k in sorted(by_bin):
                        sel = by_bin[k]
                        motion_table.append(dict(
                            sequence=s, variant=v, solver=so, budget_ms=f"{b:g}",
                            motion_bin_px=bin_label(k), pairs=len(sel),
                            mean_motion_px=f"{statistics.mean(r['motion_px'] for r in sel):.1f}",
                            correct=sum(r["correct"] for r in sel),
                            reliability=f"{sum(r['correct'] for r in sel) / len(sel):.3f}",
                            mean_true_inlier_rate=(
                                f"{statistics.mean(r['true_inlier_rate'] for r in sel):.3f}")))
    with open(os.path.join(args.results, "rail_reliability_motion.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["sequence", "variant", "solver", "budget_ms",
                                          "motion_bin_px", "pairs", "mean_motion_px", "correct",
                                          "reliability", "mean_true_inlier_rate"])
        w.writeheader()
        w.writerows(motion_table)

    write_markdown(os.path.join(args.results, "rail_tables.md"), time_table, motion_table,
                   sequences, variants, solvers, budgets)

    # Figures: one per variant, the paper's layout.
    slow = max(budgets)
    fast = 10.0 if 10.0 in budgets else min(budgets)
    for v in variants:
        fig, axes = plt.subplots(len(sequences), 3, figsize=(15, 4.2 * len(sequences)),
                                 squeeze=False)
        for row, s in enumerate(sequences):
            ax = axes[row][0]
            for so in solvers:
                pts = [t for t in time_table
                       if t["sequence"] == s and t["variant"] == v and t["solver"] == so]
                if not pts:
                    continue
                ax.plot([float(t["mean_cpu_ms"]) for t in pts],
                        [float(t["reliability"]) for t in pts], **STYLE.get(so, {"label": so}))
            sel = [t for t in time_table if t["sequence"] == s and t["variant"] == v]
            rate = statistics.mean(float(t["mean_true_inlier_rate"]) for t in sel) if sel else 0
            npairs = max((t["pairs"] for t in sel), default=0)
            plain_log_axis(ax, [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000])
            ax.set_xlabel("CPU time per frame pair (ms, mean over pairs; log scale)")
            ax.set_ylabel("reliability (t within 10 deg)")
            ax.set_title(f"{s}: {npairs} pairs with >= {MIN_MOTION:g} px motion, "
                         f"inlier rate {rate:.2f}", fontsize=10)
            ax.set_ylim(-0.02, 1.02)
            ax.grid(True, which="both", alpha=0.3)
            if row == 0 and ax.get_legend_handles_labels()[0]:
                ax.legend(fontsize=8, loc="lower right")

            for col, budget in ((1, slow), (2, fast)):
                ax = axes[row][col]
                inl = None
                for so in solvers:
                    b = 0.0 if so == "opencv" else budget
                    pts = [t for t in motion_table if t["sequence"] == s and t["variant"] == v
                           and t["solver"] == so and float(t["budget_ms"]) == b]
                    if not pts:
                        continue
                    if so != "opencv" or col == 1:
                        ax.plot([float(t["mean_motion_px"]) for t in pts],
                                [float(t["reliability"]) for t in pts],
                                **STYLE.get(so, {"label": so}))
                    inl = pts
                if inl:
                    # Pairs per bin (the same pairs for every solver): a bin of 4 pairs moves
                    # its reliability in steps of 0.25, so the count says how far to trust it.
                    for t in inl:
                        ax.annotate(f"n={t['pairs']}", (float(t["mean_motion_px"]), 1.0),
                                    xycoords=("data", "axes fraction"), xytext=(0, 2),
                                    textcoords="offset points", ha="center", va="bottom",
                                    fontsize=8, color="dimgrey")
                plain_log_axis(ax, [1, 2, 5, 10, 20, 50, 100, 200])
                ax.set_xlabel("average pixel motion of the pair (px, bin mean; log scale);\n"
                              "n = pairs in the bin")
                ax.set_ylabel("reliability (t within 10 deg)")
                ax.set_ylim(-0.02, 1.02)
                ax.grid(True, which="both", alpha=0.3)
                what = "OpenCV: no budget" if col == 1 else "OpenCV not shown"
                ax.set_title(f"{s}: budget {budget:g} ms per pair ({what})", fontsize=10,
                             pad=14)
                if inl:
                    ax2 = ax.twinx()
                    ax2.plot([float(t["mean_motion_px"]) for t in inl],
                             [float(t["mean_true_inlier_rate"]) for t in inl], color=INLIER_COLOR,
                             linewidth=2.5, alpha=0.6, label="inlier rate (right axis)")
                    ax2.set_ylim(-0.02, 1.02)
                    ax2.set_ylabel("inlier rate of the matches", color=INLIER_COLOR)
                    ax2.tick_params(axis="y", colors=INLIER_COLOR)
                    if row == 0 and col == 1:
                        ax2.legend(fontsize=8, loc="lower left")
        title = (f"Rail sequences, match set '{v}', preemptive RANSAC with a time budget"
                 + (f" ({args.machine})" if args.machine else ""))
        fig.suptitle(title, fontsize=12)
        fig.tight_layout(rect=(0, 0, 1, 0.97))
        out = os.path.join(args.figures, f"rail_{v}.png")
        fig.savefig(out, dpi=80)
        plt.close(fig)
        print("plot_rail.py: wrote " + out)


if __name__ == "__main__":
    main()
