#!/usr/bin/env python3
"""Ratios from one run of contactlaws_bench (Google Benchmark JSON).

    python3 bench/bench_report.py BENCH.json [--markdown] [--command TEXT]
                                               [--update-doc FILE]

Every ratio compares two benchmarks of the same run (the machine is shared and
noisy: absolute times drift between runs, ratios much less). Times are CPU
time (per step for the simulations, per call for the law kernels, per run for
the sweep); with --benchmark_repetitions the median of the repetitions is used.

--update-doc FILE replaces the text between the lines
<!-- bench:begin --> and <!-- bench:end --> of FILE with the markdown report
(docs/performance.md).

Standard library only.
"""

import argparse
import json
import os
import platform
import sys

# the targets of the hooks' cost, as ratios
GOAL_BOUNCING = 0.80    # bouncing ball, 3 s: hooks / MuJoCo's own contact
GOAL_BOX_64 = 1.00      # 64 balls: hooks / MuJoCo's own contact
GOAL_SWEEP_AUTO = 0.10  # sweep: auto timestep / fixed 1e-5 s
# the targets of friction's cost: the cost of coulomb friction on the 64-ball box
GOAL_FRICTION_OVER_FRICTIONLESS = 1.30  # hooks with coulomb / hooks without friction
GOAL_FRICTION_OVER_MUJOCO = 0.50        # hooks with coulomb / MuJoCo's own, condim 3

BEGIN = "<!-- bench:begin -->"
END = "<!-- bench:end -->"

TIME_SCALE = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}


def load(path):
    """The run's context, and benchmark name -> entry (the median when repeated)."""
    with open(path) as f:
        report = json.load(f)
    entries = {}
    medians = {}
    for b in report["benchmarks"]:
        if b.get("error_occurred"):
            raise SystemExit(f"bench_report: {b['name']}: {b.get('error_message', 'error')}")
        name = b.get("run_name", b["name"])
        if b.get("run_type") == "aggregate":
            if b.get("aggregate_name") == "median":
                medians[name] = b
        else:
            entries.setdefault(name, b)
    entries.update(medians)
    return report["context"], entries


def seconds(entry):
    """CPU seconds per iteration."""
    return entry["cpu_time"] * TIME_SCALE[entry.get("time_unit", "ns")]


def per(entries, name, counter):
    """CPU seconds per `counter` (steps, runs) of benchmark `name`, or None."""
    e = entries.get(name)
    return None if e is None else seconds(e) / e[counter]


def ratio(a, b):
    return None if a is None or b is None else a / b


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def fmt_ratio(r):
    return "-" if r is None else f"{r:.3f}"


def fmt_time(t):
    if t is None:
        return "-"
    for unit, scale in (("s", 1.0), ("ms", 1e-3), ("us", 1e-6)):
        if t >= scale:
            return f"{t / scale:.3g} {unit}"
    return f"{t / 1e-9:.3g} ns"


def verdict(r, goal):
    if r is None:
        return "not measured"
    return "met" if r <= goal else "NOT met"


def tables(entries):
    """[(title, header, rows)]: the report, every cell a string."""
    out = []

    # the goals first
    bb = {v: per(entries, f"BouncingBall/{v}", "steps")
          for v in ("hooks", "mujoco", "free_flight_hooks", "free_flight_mujoco")}
    box64 = ratio(per(entries, "BallBox/hooks/64", "steps"),
                  per(entries, "BallBox/mujoco/64", "steps"))
    fixed = per(entries, "Sweep/fixed", "runs")
    auto = per(entries, "Sweep/auto", "runs")
    goals = [
        ("bouncing ball, hooks / MuJoCo's own contact", ratio(bb["hooks"], bb["mujoco"]),
         GOAL_BOUNCING),
        ("64 balls, hooks / MuJoCo's own contact", box64, GOAL_BOX_64),
        ("restitution sweep, auto / fixed 1e-5 s", ratio(auto, fixed), GOAL_SWEEP_AUTO),
    ]
    out.append(("Targets: the hooks' cost (ratios of CPU time)", ["quantity", "ratio", "goal", "status"],
                [[q, fmt_ratio(r), f"<= {g:.2f}", verdict(r, g)] for q, r, g in goals]))

    coulomb = per(entries, "BallBox/hooks/64", "steps")
    friction_goals = [
        ("64 balls, hooks with coulomb friction / the same hooks frictionless",
         ratio(coulomb, per(entries, "BallBox/hooks_frictionless/64", "steps")),
         GOAL_FRICTION_OVER_FRICTIONLESS),
        ("64 balls, hooks with coulomb friction / MuJoCo's own contact (condim 3)",
         box64, GOAL_FRICTION_OVER_MUJOCO),
    ]
    out.append(("Targets: friction's cost (ratios of CPU time)", ["quantity", "ratio", "goal", "status"],
                [[q, fmt_ratio(r), f"<= {g:.2f}", verdict(r, g)] for q, r, g in friction_goals]))

    laws = [[name.split("/", 1)[1], f"{seconds(e) * 1e9:.1f} ns"]
            for name, e in entries.items() if name.startswith("Law/")]
    out.append(("Law kernels: one EvaluateLaw call", ["law", "CPU time per call"], laws))

    steps = entries.get("BouncingBall/hooks", {}).get("steps")
    stretch = f"{steps * 1e-5:g} s" if steps else "?"
    rows = []
    for variant, label in (("hooks", "contact laws (hooks)"),
                           ("mujoco", "MuJoCo's own contact"),
                           ("free_flight_hooks", "free flight, hooks installed"),
                           ("free_flight_mujoco", "free flight, no hooks")):
        rows.append([label, fmt_time(bb[variant]), fmt_ratio(ratio(bb[variant], bb["mujoco"])),
                     fmt_ratio(ratio(bb[variant], bb["free_flight_mujoco"]))])
    episodes = entries.get("BouncingBall/hooks", {}).get("episodes")
    note = f", {int(episodes)} contact episodes" if episodes is not None else ""
    out.append((f"Bouncing ball (mjcf/bouncing_ball.xml, RK4, 1e-5 s, {stretch}{note})",
                ["variant", "CPU time per step", "/ MuJoCo's own", "/ free flight, no hooks"], rows))

    counts = sorted({int(name.rsplit("/", 1)[1]) for name in entries
                     if name.startswith("BallBox/")})
    rows = []
    previous = None
    box_steps = None
    for n in counts:
        h = per(entries, f"BallBox/hooks/{n}", "steps")
        m = per(entries, f"BallBox/mujoco/{n}", "steps")
        hooks_entry = entries.get(f"BallBox/hooks/{n}", {})
        mujoco_entry = entries.get(f"BallBox/mujoco/{n}", {})
        box_steps = hooks_entry.get("steps", box_steps)
        growth_h = growth_m = "-"
        if previous:
            pn, ph, pm = previous
            growth_h = f"{fmt_ratio(ratio(h, ph))} (x{n // pn} balls)"
            growth_m = f"{fmt_ratio(ratio(m, pm))} (x{n // pn} balls)"
        rows.append([str(n), fmt_time(h), fmt_time(m), fmt_ratio(ratio(h, m)), growth_h,
                     growth_m,
                     f"{hooks_entry['episodes']:.0f}" if "episodes" in hooks_entry else "-",
                     f"{mujoco_entry['mean_ncon']:.1f}" if "mean_ncon" in mujoco_entry
                     else "-"])
        previous = (n, h, m)
    stretch = f"the first {box_steps * 1e-5:g} s from the launch" if box_steps else "?"
    out.append((f"Balls in a box (tests/bench/ball_box.h, RK4, 1e-5 s, {stretch})",
                ["balls", "hooks, per step", "MuJoCo's own, per step", "hooks / MuJoCo",
                 "hooks' growth", "MuJoCo's growth", "contact episodes (hooks)",
                 "mean contacts (MuJoCo)"], rows))

    fixed_entry = entries.get("Sweep/fixed", {})
    runs = int(fixed_entry.get("runs", 0))
    rows = [["fixed 1e-5 s", fmt_time(fixed),
             f"{fixed_entry['steps'] / runs:.0f}" if runs else "-", "1"]]
    if auto is None:
        rows.append(["auto", "not measured (no Sweep/auto benchmark)", "-", "-"])
    else:
        auto_entry = entries["Sweep/auto"]
        rows.append(["auto", fmt_time(auto), f"{auto_entry['steps'] / auto_entry['runs']:.0f}",
                     fmt_ratio(ratio(auto, fixed))])
    out.append((f"Restitution sweep: the bouncing ball until its first contact ends "
                f"({runs} (law, e) runs per iteration)",
                ["timestep", "CPU time per run", "steps per run", "/ fixed"], rows))
    return out


def machine(context, command, revision):
    lines = []
    if command:
        lines.append(("command", command))
    if revision:
        lines.append(("source", revision))
    lines += [
        ("CPU", cpu_model()),
        ("nproc", str(os.cpu_count())),
        ("date", context.get("date", "?")),
        ("load average at the start", " ".join(f"{x:.2f}" for x in context.get("load_avg", []))),
    ]
    return lines


def text_report(context, sections, command, revision):
    lines = [f"{k}: {v}" for k, v in machine(context, command, revision)]
    for title, header, rows in sections:
        widths = [max(len(r[i]) for r in [header] + rows) for i in range(len(header))]
        lines.append("")
        lines.append(title)
        for r in [header] + rows:
            lines.append("  " + "  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip())
    return "\n".join(lines) + "\n"


def markdown_report(context, sections, command, revision):
    lines = []
    for k, v in machine(context, command, revision):
        lines.append(f"- {k}: `{v}`" if k == "command" else f"- {k}: {v}")
    for title, header, rows in sections:
        lines += ["", f"**{title}**", "", "| " + " | ".join(header) + " |",
                  "|" + "---|" * len(header)]
        lines += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(lines) + "\n"


def update_doc(path, block):
    with open(path) as f:
        text = f.read()
    begin = text.find(BEGIN)
    end = text.find(END)
    if begin < 0 or end < begin:
        raise SystemExit(f"bench_report: {path} has no {BEGIN} ... {END} block")
    text = text[:begin + len(BEGIN)] + "\n" + block + text[end:]
    with open(path + ".tmp", "w") as f:
        f.write(text)
    os.replace(path + ".tmp", path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("json")
    parser.add_argument("--markdown", action="store_true", help="markdown tables")
    parser.add_argument("--command", help="the command that made the JSON, to print")
    parser.add_argument("--revision", help="the source's revision (git describe), to print")
    parser.add_argument("--update-doc", metavar="FILE",
                        help="put the markdown report between the bench markers of FILE")
    args = parser.parse_args()
    context, entries = load(args.json)
    sections = tables(entries)
    if args.update_doc:
        update_doc(args.update_doc,
                   markdown_report(context, sections, args.command, args.revision))
        print(f"bench_report: updated {args.update_doc}")
    elif args.markdown:
        sys.stdout.write(markdown_report(context, sections, args.command, args.revision))
    else:
        sys.stdout.write(text_report(context, sections, args.command, args.revision))


if __name__ == "__main__":
    main()
