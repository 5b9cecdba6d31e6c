#!/usr/bin/python3
"""Issue 35's accuracy goals for contacts integrated inside MuJoCo's 2 ms step.

Runs mjcf/die_throw.xml and mjcf/box_stack.xml for 5 s at a fixed 2 ms step
(Euler, --contact-steps auto) and again under --timestep auto --accuracy 1e-6
(the reference), and prints each goal beside what was measured:
  - the die at rest at the reference's height within 0.1 mm, its mechanical
    energy (kinetic + potential + the laws' elastic) never rising by more than
    1e-5 J between two samples;
  - each box of the stack at the reference's final height within 0.1 mm and
    its horizontal position within 2 mm.
Also the ledgers' totals (start and end) and each run's first e_post line.

  /usr/bin/python3 bench/contact_steps_accuracy.py [build/contactlaws]

The reference runs take about a minute and a half of CPU; nothing is timed.
"""

import os
import subprocess
import sys
import tempfile

import numpy as np
import pandas as pd

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STEPS = ["--timestep", "2e-3", "--integrator", "euler", "--contact-steps", "auto"]
FINE = ["--timestep", "auto", "--accuracy", "1e-6"]


def run(program, scene, options, path):
    """The trajectory of a 5 s run (its CSV, read exactly) and its summary."""
    done = subprocess.run([program, "run", os.path.join(ROOT, "mjcf", scene), "--duration", "5",
                           *options, "--output", path], capture_output=True, text=True, check=True)
    return pd.read_csv(path, float_precision="round_trip"), done.stdout


def mechanical(frame):
    """kinetic + potential + the laws' elastic energy, J"""
    return (frame["energy.kinetic"] + frame["energy.potential"]
            + frame["energy.elastic"]).to_numpy()


def main():
    program = os.path.abspath(
        sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "contactlaws"))
    runs = {}
    with tempfile.TemporaryDirectory(prefix="contact_steps_accuracy.") as work:
        for scene in ("die_throw.xml", "box_stack.xml"):
            for name, options in (("steps", STEPS), ("fine", FINE)):
                path = os.path.join(work, f"{scene}.{name}.csv")
                runs[scene, name] = run(program, scene, options, path)

    steps, fine = runs["die_throw.xml", "steps"][0], runs["die_throw.xml", "fine"][0]
    off = abs(steps["die.z"].iloc[-1] - fine["die.z"].iloc[-1])
    rises = np.diff(mechanical(steps))
    worst = int(np.argmax(rises))
    print(f"die at rest: height off the reference's {off:.2e} m (goal <= 1e-4 m)")
    print(f"die: largest rise of its mechanical energy between samples {rises[worst]:.2e} J "
          f"at t = {steps['time'].iloc[worst + 1]:.3f} s (goal <= 1e-5 J)")

    steps, fine = runs["box_stack.xml", "steps"][0], runs["box_stack.xml", "fine"][0]
    for box in ("bottom", "middle", "top"):
        height = abs(steps[f"{box}.z"].iloc[-1] - fine[f"{box}.z"].iloc[-1])
        across = np.hypot(steps[f"{box}.x"].iloc[-1] - fine[f"{box}.x"].iloc[-1],
                          steps[f"{box}.y"].iloc[-1] - fine[f"{box}.y"].iloc[-1])
        print(f"box_stack {box}: height off {1e3 * height:.5f} mm (goal <= 0.1), "
              f"horizontal off {1e3 * across:.2f} mm (goal <= 2)")
    print(f"box_stack: largest rise of its mechanical energy "
          f"{np.diff(mechanical(steps)).max():.2e} J, "
          f"kinetic at the end {steps['energy.kinetic'].iloc[-1]:.1e} J")

    for (scene, name), (frame, summary) in runs.items():
        total = frame["energy.total"]
        print(f"{scene} {name}: the ledger's total {total.iloc[0]:.5f} -> {total.iloc[-1]:.5f} J")
        for line in summary.splitlines()[1:]:
            print(f"  {line}")


if __name__ == "__main__":
    main()
