#!/bin/sh
# Configures and builds ede (Release, the default) into build/, then installs it into the default prefix
# (/usr/local: the tools on the PATH, the library for find_package(ede) and pkg-config, the Python module for
# Debian's python3). Installing again copies only what changed; without the rights to write there, says so
# and leaves the build as it is. When the python3 first on the PATH is another interpreter (a venv, pyenv or
# conda one), the module is built for it too (scripts/install-python.sh), or a line says how to add it.
set -eu
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)"
if ! cmake --install build >build/install.log 2>&1; then
  echo "build.sh: built in build/, but could not install (see build/install.log); as root: cmake --install build"
fi
path_python=$(command -v python3 || true)
if [ -n "$path_python" ] && [ -x /usr/bin/python3 ] &&
   [ "$("$path_python" -c 'import sys; print(sys.prefix)' 2>/dev/null)" != "$(/usr/bin/python3 -c 'import sys; print(sys.prefix)')" ]; then
  scripts/install-python.sh "$path_python" || echo "build.sh: ede's Python module is installed for /usr/bin/python3, not for $path_python (above)"
fi
