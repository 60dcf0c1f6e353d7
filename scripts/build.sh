#!/bin/sh
# Configures and builds ede (Release, the default) into build/. With no argument it builds everything and
# installs it into the default prefix (/usr/local: the tools on the PATH, the library for find_package(ede)
# and pkg-config, the manual pages, the Python module for Debian's python3); installing again copies only what changed; without the rights to write
# there, says so and leaves the build as it is. With targets (scripts/build.sh ede-sim ede-replay) it builds
# only those and installs nothing: scripts/demo.sh does that, and a later full build reuses their objects.
# When the python3 first on the PATH is another interpreter (a venv, pyenv or conda one), a full build also
# installs the module for it (scripts/install-python.sh), or prints the line that says how to.
set -eu
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
if [ $# -gt 0 ]; then
  exec cmake --build build -j "$(nproc)" --target "$@"
fi
cmake --build build -j "$(nproc)"
if ! cmake --install build >build/install.log 2>&1; then
  echo "build.sh: built in build/, but could not install (see build/install.log); as root: cmake --install build"
fi
path_python=$(command -v python3 || true)
if [ -n "$path_python" ] && [ -x /usr/bin/python3 ] &&
   [ "$("$path_python" -c 'import sys; print(sys.prefix)' 2>/dev/null)" != "$(/usr/bin/python3 -c 'import sys; print(sys.prefix)')" ]; then
  scripts/install-python.sh "$path_python" || echo "build.sh: ede's Python module is installed for /usr/bin/python3, not for $path_python (above)"
fi
