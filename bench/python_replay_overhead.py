"""Python's replay against the command line's, on the 300 cube tosses (tosses 0-299 of
data/cube_tosses, start refit, the tosses' 1/1480 s step, 2 threads): the command line
reading the measured CSV and writing replay.csv and trajectories.csv, Python given the same
tosses as a DataFrame (read once, before the clock) and returning its DataFrames. Checks
that Python's scores are the command line's to the bit, then runs each REPEAT times
(default 3), alternating, prints every wall time and the ratio of the fastest of each: on a
shared machine the fastest run is the one least slowed by the others.

PYTHONPATH=build/python /usr/bin/python3 bench/python_replay_overhead.py build/contactlaws [REPEAT]
"""

import os
import subprocess
import sys
import tempfile
import time

import numpy as np
import pandas as pd

import contactlaws

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join(ROOT, "mjcf", "cube_toss.xml")
STEP = "6.756756756756757e-4"  # 1/1480 s, the tosses' sampling

cli = sys.argv[1]
repeat = int(sys.argv[2]) if len(sys.argv) > 2 else 3
with tempfile.TemporaryDirectory() as tmp:
    data = os.path.join(tmp, "tosses.csv")
    subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "cube_tosses_to_csv.py"),
                    os.path.join(ROOT, "data", "cube_tosses", "train.csv.gz"), data,
                    "--tosses", "0:300"], check=True)
    frame = pd.read_csv(data, float_precision="round_trip")
    flags = ["--start", "refit", "--timestep", STEP, "--jobs", "2"]
    command = [cli, "replay", SCENE, "--data", data, *flags, "--output", tmp]
    keywords = dict(start="refit", timestep=float(STEP), jobs=2)

    command_line, python = [], []
    for _ in range(repeat):
        start = time.perf_counter()
        subprocess.run(command, check=True, capture_output=True)
        command_line.append(time.perf_counter() - start)
        start = time.perf_counter()
        result = contactlaws.replay(SCENE, frame, **keywords)
        python.append(time.perf_counter() - start)
    written = pd.read_csv(os.path.join(tmp, "replay.csv"), float_precision="round_trip",
                          keep_default_na=False, na_values=[""], dtype={"trajectory": str})
    for column in ("e_q", "position_rms", "angle_rms"):
        if not np.array_equal(result.scores[column].to_numpy(), written[column].to_numpy()):
            sys.exit(f"python_replay_overhead: {column}: Python's scores are not the command "
                     "line's")
print(f"{len(result.scores)} tosses, {len(result.trajectories)} simulated samples; Python's "
      "scores are the command line's to the bit")
print("command line", " ".join(f"{t:.2f}" for t in command_line), "s")
print("python      ", " ".join(f"{t:.2f}" for t in python), "s")
print(f"fastest: command line {min(command_line):.2f} s, python {min(python):.2f} s, "
      f"ratio {min(python) / min(command_line):.3f}")
