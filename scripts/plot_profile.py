#!/usr/bin/python3
"""The figure of `contactlaws fit --profile`'s profile.csv.

    scripts/plot_profile.py DIR/profile.csv OUT.png

One panel per parameter: the mean score at each point with its 95% bootstrap
interval as a band; the best point, the points that score the same as it
(their paired 95% interval of the per-trajectory difference contains 0) and
the others marked apart; the span of the indistinguishable points around the
best shaded, and the fitted value drawn as a line. A log parameter on a log
axis. The numbers are profile.csv's: nothing is recomputed here.
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_profiles(path):
    """{key: [row, ...]} in the file's order (increasing value per key)."""
    profiles = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            profiles.setdefault(row["key"], []).append(row)
    return profiles


def panel(ax, key, rows):
    value = [float(r["value"]) for r in rows]
    mean = [float(r["mean"]) for r in rows]
    # fit --trim: the best and the span are of the trimmed mean, drawn beside the mean's band
    trimmed = [float(r["trimmed_mean"]) for r in rows] if "trimmed_mean" in rows[0] else None
    lo = [float(r["mean_lo"]) for r in rows]
    hi = [float(r["mean_hi"]) for r in rows]
    log = rows[0]["scale"] == "log"
    span = float(rows[0]["span_lo"]), float(rows[0]["span_hi"])
    determined = rows[0]["determined"] == "yes"
    ax.axvspan(*span, color="tab:gray", alpha=0.2, label="span: scores the same as the best")
    ax.fill_between(value, lo, hi, color="tab:blue", alpha=0.2, label="mean, 95% interval")
    ax.plot(value, mean, color="tab:blue", lw=1)
    if trimmed:
        ax.plot(value, trimmed, color="tab:green", lw=1, label="trimmed mean (what the fit minimises)")
        mean = trimmed
    for kind, style in (("no", dict(marker="o", mfc="white", mec="tab:blue", label="worse")),
                        ("yes", dict(marker="o", color="tab:blue", label="indistinguishable")),
                        ("best", dict(marker="*", color="tab:red", ms=12, label="best"))):
        xs = [v for v, r in zip(value, rows) if r["indistinguishable"] == kind]
        ys = [m for m, r in zip(mean, rows) if r["indistinguishable"] == kind]
        if xs:
            ax.plot(xs, ys, ls="none", **style)
    for v, r in zip(value, rows):
        if r["fitted"] == "yes":
            ax.axvline(v, color="k", ls=":", lw=1, label="fitted")
    if log:
        ax.set_xscale("log")
    # a score whose worst points are far above the rest: the mean on a log axis
    positive = all(x > 0 for x in lo)
    if positive and max(hi) > 30 * min(mean):
        ax.set_yscale("log")
    width = (f"{math.log10(span[1] / span[0]):.1f} decades" if log
             else f"{100 * (span[1] - span[0]) / (value[-1] - value[0]):.0f}% of the range")
    verdict = "determined" if determined else f"not determined ({width})"
    ax.set_title(f"{key}: {verdict}", fontsize=10)
    ax.set_xlabel(key)
    ax.set_ylabel("mean score")
    ax.grid(alpha=0.3)


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    profiles = read_profiles(argv[1])
    if not profiles:
        sys.exit(f"{argv[1]}: no profile in it")
    fig, axes = plt.subplots(1, len(profiles), figsize=(4.2 * len(profiles), 3.6), squeeze=False)
    for ax, (key, rows) in zip(axes[0], profiles.items()):
        panel(ax, key, rows)
    handles, labels = axes[0][0].get_legend_handles_labels()
    seen = dict(zip(labels, handles))
    for ax in axes[0][1:]:
        for h, label in zip(*ax.get_legend_handles_labels()):
            seen.setdefault(label, h)
    fig.legend(seen.values(), seen.keys(), loc="lower center", ncol=len(seen), fontsize=8,
               frameon=False)
    fig.tight_layout(rect=(0, 0.08, 1, 1))
    fig.savefig(argv[2], dpi=110)
    print(f"wrote {argv[2]}")


if __name__ == "__main__":
    main(sys.argv)
