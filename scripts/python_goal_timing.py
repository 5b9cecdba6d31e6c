"""The goal of issue 24: a 5 s run of mjcf/bouncing_ball.xml at a fixed 1e-5 s
through Python (its trajectory as a DataFrame) against the command line
writing the same trajectory as CSV. Prints both wall times and their ratio,
from one run each (a loaded machine makes one run noisy).

PYTHONPATH=build/python python3 scripts/python_goal_timing.py build/contactlaws mjcf/bouncing_ball.xml
"""

import os
import subprocess
import sys
import tempfile
import time

import contactlaws

cli, scene = sys.argv[1], sys.argv[2]
with tempfile.TemporaryDirectory() as tmp:
    start = time.perf_counter()
    subprocess.run([cli, "run", scene, "--duration=5", "--timestep=1e-5",
                    "--output", os.path.join(tmp, "t.csv")], check=True, capture_output=True)
    command_line = time.perf_counter() - start
start = time.perf_counter()
trajectory = contactlaws.run(scene, duration=5, timestep=1e-5).trajectory
python = time.perf_counter() - start
print(f"command line {command_line:.2f} s, python {python:.2f} s ({len(trajectory)} rows), "
      f"ratio {python / command_line:.3f}")
