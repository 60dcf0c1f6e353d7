#!/bin/sh
# Configures and builds ede (Release, the default) into build/. With no argument it builds everything and
# installs it into the default prefix (/usr/local: the tools on the PATH, the library for find_package(ede)
# and pkg-config, the manual pages); installing again copies only what changed; without the rights to write
# there, says so and leaves the build as it is. With targets (scripts/build.sh ede-sim ede-replay) it builds
# only those and installs nothing: scripts/demo.sh does that, and a later full build reuses their objects.
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
