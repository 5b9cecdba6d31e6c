#!/usr/bin/env bash
# The README's install path, end to end: a venv of Debian's python3, the
# project pip installed into it (python/build_backend.py: a CMake build of
# the module), the venv's kernel registered in a temporary JUPYTER_DATA_DIR,
# and examples/quickstart.ipynb executed on that kernel by Debian's jupyter
# nbconvert (which fails on any cell's error). Without the kernel's name the
# notebook runs on Debian's python3, which has no contactlaws: checked too.
#
#   python/tests/pip_notebook.sh SOURCE_DIR
#
# The source is copied (tracked files, or all but build/ outside git) so
# that build/pip is the copy's. ccache, where installed, keeps the compiler's
# work between runs (CCACHE_BASEDIR: the copy's paths are relative).
set -euo pipefail
source_dir="$(cd "$1" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
unset PYTHONPATH  # the venv's own site-packages, not a build tree's

mkdir "$work/src"
if git -C "$source_dir" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  git -C "$source_dir" ls-files -z --cached --others --exclude-standard \
    | (cd "$source_dir" && xargs -0 cp --parents -t "$work/src" 2>/dev/null || true)
else
  tar -C "$source_dir" --exclude=./build --exclude='./build-*' -cf - . | tar -C "$work/src" -xf -
fi

start=$SECONDS
/usr/bin/python3 -m venv --system-site-packages "$work/venv"
if command -v ccache >/dev/null; then
  export CMAKE_CXX_COMPILER_LAUNCHER=ccache CCACHE_BASEDIR="$work"
fi
"$work/venv/bin/pip" install --quiet --no-build-isolation "$work/src"
echo "pip_notebook: venv and pip install: $((SECONDS - start)) s"

export JUPYTER_DATA_DIR="$work/jupyter" PYDEVD_DISABLE_FILE_VALIDATION=1
"$work/venv/bin/python" -m ipykernel install --user --name contactlaws >/dev/null
notebook="$work/src/examples/quickstart.ipynb"
# the default kernel (Debian's python3) cannot import the venv's package
if jupyter nbconvert --execute --to notebook --output-dir "$work" --output plain \
    "$notebook" >"$work/plain.log" 2>&1; then
  echo "pip_notebook: the notebook ran without the venv's kernel: is contactlaws installed for /usr/bin/python3?" >&2
  exit 1
fi
grep -q "No module named 'contactlaws'" "$work/plain.log" || {
  cat "$work/plain.log" >&2
  exit 1
}
start=$SECONDS
jupyter nbconvert --execute --to notebook --output-dir "$work" --output executed \
  --ExecutePreprocessor.kernel_name=contactlaws "$notebook"
echo "pip_notebook: the notebook on the venv's kernel: $((SECONDS - start)) s"
