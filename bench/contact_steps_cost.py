#!/usr/bin/python3
"""What contacts integrated inside the step cost against MuJoCo's own contact.

For each scene, alternately in the same minutes: `contactlaws run SCENE --timestep 2e-3
--integrator euler --contact-steps auto` (tagged) and the same scene with its contactlaw tags
removed (MuJoCo's own contact on every pair) at the same step and integrator; whole process,
wall time, the median of --repeats runs each. Prints one line per scene: both medians and their
ratio (target: <= 2). Friction can be overridden (--friction none): friction is not
integrated inside the step (docs/timestep.md, "Contact steps").

  /usr/bin/python3 bench/contact_steps_cost.py build/contactlaws [--repeats 5] [--duration 5]
      [--friction none] [--scenes mjcf/die_throw.xml ...] [--throws N] [--instructions]

--throws N also measures, for each scene with a keyframe (die_throw.xml), N copies of it whose
start is perturbed (seeded: the orientation turned by up to 0.3 rad about a random axis, each
velocity scaled by 1 +- 0.2), each against its own untagged copy, and prints their mean ratio and
range: a thrown die's path is chaotic, and one throw's cost rides on rounding.
--instructions counts instructions (valgrind --tool=callgrind, one run each) instead of wall
time: repeatable on a loaded machine.
"""
import argparse
import math
import os
import random
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


def perturbed_copies(scene, directory, count):
    """count copies of scene with its keyframe's start perturbed (seeded), or none without one."""
    with open(scene) as f:
        text = f.read()
    key = re.search(r'<key qpos="([^"]*)" qvel="([^"]*)"/>', text)
    if not key or count <= 0:
        return []
    qpos = [float(x) for x in key.group(1).split()]
    qvel = [float(x) for x in key.group(2).split()]
    paths = []
    for k in range(count):
        r = random.Random(k)
        axis = [r.uniform(-1, 1) for _ in range(3)]
        norm = math.sqrt(sum(a * a for a in axis))
        angle = r.uniform(0, 0.3)
        w1 = math.cos(angle / 2)
        x1, y1, z1 = (math.sin(angle / 2) * a / norm for a in axis)
        w2, x2, y2, z2 = qpos[3:7]
        q = qpos[:3] + [w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
                        w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2]
        q += qpos[7:]
        v = [x * (1 + r.uniform(-0.2, 0.2)) for x in qvel]
        copy = text.replace(key.group(0), '<key qpos="%s" qvel="%s"/>' % (
            " ".join("%.6g" % x for x in q), " ".join("%.6g" % x for x in v)))
        path = os.path.join(directory, f"throw{k}_" + os.path.basename(scene))
        with open(path, "w") as f:
            f.write(copy)
        paths.append(path)
    return paths


def instructions(command):
    """The instructions a run executes (callgrind's total)."""
    done = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null"] + command,
                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    found = re.search(r"Collected : (\d+)", done.stderr)
    if not found:
        print(f"  note: no count: {' '.join(command)}")
        return float("nan")
    return float(found.group(1))


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
    parser.add_argument("--throws", type=int, default=0,
                        help="perturbed copies of each scene with a keyframe")
    parser.add_argument("--instructions", action="store_true",
                        help="count instructions (callgrind) instead of wall time")
    args = parser.parse_args()
    step = ["--timestep", "2e-3", "--integrator", "euler", "--duration", args.duration]
    if args.instructions:
        print("instructions (callgrind), one run each")
        print(f"{'scene':28} {'contact steps (M)':>18} {'MuJoCo (M)':>11} {'ratio':>7}")
    else:
        print(f"load average {os.getloadavg()[0]:.2f}; {args.repeats} runs each, alternated")
        print(f"{'scene':28} {'contact steps (s)':>18} {'MuJoCo (s)':>11} {'ratio':>7}")
    scale = 1e-6 if args.instructions else 1.0
    width = 0 if args.instructions else 3
    with tempfile.TemporaryDirectory() as directory:
        for scene in args.scenes:
            ratios = []
            copies = perturbed_copies(scene, directory, args.throws)
            for path in [scene] + copies:
                tagged = [args.contactlaws, "run", path] + step + ["--contact-steps", "auto"]
                if args.friction:
                    tagged += ["--friction", args.friction]
                mujoco = [args.contactlaws, "run", untagged_copy(path, directory)] + step
                if args.instructions:
                    a, b = instructions(tagged), instructions(mujoco)
                else:
                    times = {"tagged": [], "mujoco": []}
                    for _ in range(args.repeats):
                        times["tagged"].append(wall_time(tagged))
                        times["mujoco"].append(wall_time(mujoco))
                    a = statistics.median(times["tagged"])
                    b = statistics.median(times["mujoco"])
                ratios.append(a / b)
                print(f"{os.path.basename(path):28} {a * scale:18.{width}f} {b * scale:11.{width}f} "
                      f"{a / b:7.2f}")
            if copies:
                print(f"{os.path.basename(scene) + ', all throws':28} mean ratio "
                      f"{statistics.mean(ratios):.2f}, from {min(ratios):.2f} to {max(ratios):.2f} "
                      f"({len(ratios)} throws)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
