"""The Python module's overhead: a 5 s run of mjcf/bouncing_ball.xml at a fixed 1e-5 s
through Python (its trajectory as a DataFrame) against the command line
writing the same trajectory as CSV. Runs each REPEAT times (default 3),
alternating, prints every wall time, and the ratio of the fastest of each:
on a shared machine the fastest run is the one least slowed by the others.

PYTHONPATH=build/python python3 bench/python_run_overhead.py build/contactlaws mjcf/bouncing_ball.xml [REPEAT]
"""

import os
import subprocess
import sys
import tempfile
import time

import contactlaws

cli, scene = sys.argv[1], sys.argv[2]
repeat = int(sys.argv[3]) if len(sys.argv) > 3 else 3
command_line, python = [], []
with tempfile.TemporaryDirectory() as tmp:
    for _ in range(repeat):
        start = time.perf_counter()
        subprocess.run([cli, "run", scene, "--duration=5", "--timestep=1e-5",
                        "--output", os.path.join(tmp, "t.csv")], check=True, capture_output=True)
        command_line.append(time.perf_counter() - start)
        start = time.perf_counter()
        trajectory = contactlaws.run(scene, duration=5, timestep=1e-5).trajectory
        python.append(time.perf_counter() - start)
print("command line", " ".join(f"{t:.2f}" for t in command_line), "s")
print(f"python       {' '.join(f'{t:.2f}' for t in python)} s ({len(trajectory)} rows)")
print(f"fastest: command line {min(command_line):.2f} s, python {min(python):.2f} s, "
      f"ratio {min(python) / min(command_line):.3f}")
