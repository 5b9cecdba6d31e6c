"""pip install's backend on the wrong Python: one line, before any build."""

import os
import subprocess
import sys

BACKEND = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def test_a_python_without_debians_numpy_is_told_which_python_it_needs():
    # -S: no site-packages, as a pyenv or conda python3 has no Debian numpy
    stopped = subprocess.run(
        [sys.executable, "-S", "-c", "import build_backend; build_backend.build_wheel('.')"],
        cwd=BACKEND, capture_output=True, text=True)
    assert stopped.returncode == 1
    lines = stopped.stderr.splitlines()
    assert len(lines) == 1
    assert lines[0].startswith(f"contactlaws: {sys.executable} has no numpy or pandas: ")
    assert "/usr/bin/python3 -m venv --system-site-packages" in lines[0]


def test_debians_python_passes_the_check():
    passed = subprocess.run(
        [sys.executable, "-c", "import build_backend; build_backend.require_debian_python()"],
        cwd=BACKEND, capture_output=True, text=True)
    assert passed.returncode == 0, passed.stderr
