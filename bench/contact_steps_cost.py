#!/usr/bin/python3
"""What contacts integrated inside the step cost against MuJoCo's own contact.

For each scene, alternately in the same minutes: `contactlaws run SCENE --timestep 2e-3
--integrator euler --contact-steps auto` (tagged) and the same scene with its contactlaw tags
removed (MuJoCo's own contact on every pair) at the same step and integrator; whole process,
wall time, the median of --repeats runs each. Prints one line per scene: both medians and their
ratio (target: <= 2). Friction can be overridden (--friction none): friction is not
integrated inside the step (docs/timestep.md, "Contact steps").

  /usr/bin/python3 bench/contact_steps_cost.py build/contactlaws [--repeats 5] [--duration 5]
      [--friction none] [--scenes mjcf/die_throw.xml ...]
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

SCENES = ["mjcf/bouncing_ball.xml", "mjcf/die_throw.xml", "mjcf/box_stack.xml",
          "mjcf/ball_box_64.xml"]


def untagged_copy(scene, directory):
    """The scene with its <custom> contactlaw tags removed, written into directory."""
    with open(scene) as f:
        text = f.read()
    text = re.sub(r"<text\s+name=\"contactlaw:.*?/>", "", text, flags=re.S)
    path = os.path.join(directory, "untagged_" + os.path.basename(scene))
    with open(path, "w") as f:
        f.write(text)
    return path


def wall_time(command):
    start = time.perf_counter()
    status = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode
    if status != 0:
        print(f"  note: exit status {status}: {' '.join(command)}")
    return time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("contactlaws")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--duration", default="5")
    parser.add_argument("--friction", default=None, help="override every tag's friction")
    parser.add_argument("--scenes", nargs="+", default=SCENES)
    args = parser.parse_args()
    step = ["--timestep", "2e-3", "--integrator", "euler", "--duration", args.duration]
    print(f"load average {os.getloadavg()[0]:.2f}; {args.repeats} runs each, alternated")
    print(f"{'scene':28} {'contact steps (s)':>18} {'MuJoCo (s)':>11} {'ratio':>7}")
    with tempfile.TemporaryDirectory() as directory:
        for scene in args.scenes:
            tagged = [args.contactlaws, "run", scene] + step + ["--contact-steps", "auto"]
            if args.friction:
                tagged += ["--friction", args.friction]
            mujoco = [args.contactlaws, "run", untagged_copy(scene, directory)] + step
            times = {"tagged": [], "mujoco": []}
            for _ in range(args.repeats):
                times["tagged"].append(wall_time(tagged))
                times["mujoco"].append(wall_time(mujoco))
            a = statistics.median(times["tagged"])
            b = statistics.median(times["mujoco"])
            print(f"{os.path.basename(scene):28} {a:18.3f} {b:11.3f} {a / b:7.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
