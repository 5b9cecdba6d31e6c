"""A PEP 517 build backend that builds the module with the project's CMake.

pip install --no-build-isolation . calls build_wheel: CMake configures the
project in build/pip for the running Python, builds the target _contactlaws,
and the package directory it fills (contactlaws/) becomes the wheel. Nothing
is downloaded: CMake, pybind11 and the libraries are Debian's.
"""

import base64
import hashlib
import importlib.util
import os
import subprocess
import sys
import sysconfig
import zipfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NAME, VERSION = "contactlaws", "0.1.0"


def get_requires_for_build_wheel(config_settings=None):
    return []


def _tag():
    python = f"cp{sys.version_info.major}{sys.version_info.minor}"
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{python}-{python}-{platform}"


def require_debian_python():
    """Stops in one line, before anything is built, on a Python that lacks
    the Debian packages the module runs with (a pyenv or conda python3,
    or a venv made without --system-site-packages): pip could only fetch
    them from an index, after the whole build."""
    missing = [name for name in ("numpy", "pandas") if importlib.util.find_spec(name) is None]
    if missing:
        sys.exit(f"contactlaws: {sys.executable} has no {' or '.join(missing)}: install into a "
                 "venv of Debian's python3 (/usr/bin/python3 -m venv --system-site-packages "
                 "DIR; apt-get install python3-numpy python3-pandas)")


def _build():
    """Builds the module; returns the package directory."""
    require_debian_python()
    build = os.path.join(ROOT, "build", "pip")
    subprocess.run(["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                    f"-DPython3_EXECUTABLE={sys.executable}", "-DCONTACTLAWS_PYTHON=ON",
                    # the module binds the library, not the command line
                    "-DCONTACTLAWS_BUILD_CLI=OFF",
                    "-DCONTACTLAWS_BUILD_TESTS=OFF", "-DCONTACTLAWS_BUILD_PLUGIN=OFF"],
                   check=True)
    jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", "2")
    subprocess.run(["cmake", "--build", build, "--target", "_contactlaws", "-j", jobs],
                   check=True)
    return os.path.join(build, "python", NAME)


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    package = _build()
    dist_info = f"{NAME}-{VERSION}.dist-info"
    files = {}
    for name in sorted(os.listdir(package)):
        if name.endswith((".py", ".so", ".pyi")) or name == "py.typed":
            with open(os.path.join(package, name), "rb") as f:
                files[f"{NAME}/{name}"] = f.read()
    files[f"{dist_info}/METADATA"] = (
        f"Metadata-Version: 2.1\nName: {NAME}\nVersion: {VERSION}\n"
        "Requires-Dist: numpy\nRequires-Dist: pandas\n").encode()
    files[f"{dist_info}/WHEEL"] = (
        f"Wheel-Version: 1.0\nGenerator: contactlaws build_backend\n"
        f"Root-Is-Purelib: false\nTag: {_tag()}\n").encode()
    record = []
    for path, data in files.items():
        digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
        record.append(f"{path},sha256={digest},{len(data)}")
    record.append(f"{dist_info}/RECORD,,")
    files[f"{dist_info}/RECORD"] = ("\n".join(record) + "\n").encode()
    wheel = f"{NAME}-{VERSION}-{_tag()}.whl"
    with zipfile.ZipFile(os.path.join(wheel_directory, wheel), "w", zipfile.ZIP_DEFLATED) as z:
        for path, data in files.items():
            z.writestr(path, data)
    return wheel
