#!/usr/bin/env bash
# Install everything Sim Athletics needs on a fresh Debian/Ubuntu machine with Python 3.11:
# the Python packages (from pyproject.toml, with the test extras) and Debian's Blender binary
# (used by the end-to-end test and the batch bake). Safe to run again.
set -euo pipefail
cd "$(dirname "$0")/.."

if ! command -v blender >/dev/null 2>&1; then
  if command -v apt-get >/dev/null 2>&1 && [ "$(id -u)" = 0 ]; then
    echo "== installing Debian's blender (apt-get)"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends blender >/dev/null
  else
    echo "== blender not found and cannot apt-get install it here: the end-to-end test will be skipped" >&2
  fi
fi

echo "== installing Python packages"
python3 -m pip install --quiet --disable-pip-version-check -e ".[test]"
python3 -c "import mujoco, numpy, scipy; print('mujoco', mujoco.__version__, '| numpy', numpy.__version__)"
