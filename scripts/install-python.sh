#!/bin/sh
# Installs the Python module `ede` into one interpreter: `scripts/install-python.sh [PYTHON]` (default: the
# python3 first on the PATH) runs `PYTHON -m pip install --no-build-isolation .` from the repository
# (docs/python.md, "Installing into your environment"): CMake builds the extension for that interpreter and
# libede from these sources. An interpreter that lacks numpy (the module needs it) or pip, or that Debian
# manages (its python3 gets the module from `cmake --install`), is left alone with the one line that says
# what to do; the exit status is then 1. scripts/build.sh runs this for the PATH's python3 when that is
# not Debian's.
set -eu
cd "$(dirname "$0")/.."
PYTHON=${1:-python3}
if ! exe=$("$PYTHON" -c 'import sys; print(sys.executable)' 2>/dev/null); then
  echo "install-python: '$PYTHON' is not a Python interpreter that runs"
  exit 1
fi
if ! "$exe" -c 'import numpy' 2>/dev/null; then
  echo "install-python: $exe has no numpy, which ede needs: \`$exe -m pip install numpy\`, then scripts/install-python.sh $exe"
  exit 1
fi
if ! "$exe" -m pip --version >/dev/null 2>&1; then
  echo "install-python: $exe has no pip: \`$exe -m ensurepip\`, then scripts/install-python.sh $exe"
  exit 1
fi
if "$exe" -c 'import os, sys, sysconfig; sys.exit(not os.path.exists(os.path.join(sysconfig.get_path("stdlib"), "EXTERNALLY-MANAGED")) or sys.prefix != sys.base_prefix)'; then
  echo "install-python: $exe is managed by the system (scripts/build.sh installs ede for it with cmake --install); for your own environment: $exe -m venv --system-site-packages VENV, then scripts/install-python.sh VENV/bin/python"
  exit 1
fi
# Without setuptools in the environment pip fetches it for the build (build isolation), as from an index.
isolation=--no-build-isolation
"$exe" -c 'import setuptools' 2>/dev/null || isolation=
"$exe" -m pip install $isolation .
echo "install-python: ede installed for $exe"
