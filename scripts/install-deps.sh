#!/bin/sh
# Installs what ede needs from Debian 12's packages, skipping apt entirely when everything is present.
# Run as root (or with sudo). Used by the README's two commands and by CI.
set -eu

# libxxhash-dev: content digests; zlib1g-dev: the log's CRC-32; nlohmann-json3-dev: the JSON summary;
# python3-matplotlib: the figures (tools/plot); libcairo2-dev: ede-render; libclang-rt-14-dev: sanitizers and
# libFuzzer for Clang (CI). ffmpeg is optional (movies). pybind11-dev, python3-dev, python3-numpy: the Python
# module (python/); python3-pytest runs its tests; python3-gsd and python3-ase read its exports back (GSD is
# also written through python3-gsd). libopenmpi-dev and openmpi-bin: ede-sweep on MPI ranks (mpirun -n K; the
# build works without them, ede-sweep then runs local processes only). python3-ipykernel, python3-nbclient,
# python3-nbformat: Jupyter's kernel and headless notebook execution (the notebook example's test; the
# test skips without them). help2man: the tools' manual pages, made from their --help at build time (the
# build skips them without it). python3-venv, python3-pip, python3-setuptools, python3-wheel: `pip install .`
# of the Python module into a venv (pyproject.toml): setuptools drives CMake because every Python environment
# has it (scikit-build-core is not in Debian 12, classic scikit-build is deprecated and only Debian's python3
# would see it); wheel for `pip wheel`.
PACKAGES="build-essential cmake clang pkg-config capnproto libcapnp-dev libzstd-dev libcli11-dev \
catch2 libtomlplusplus-dev libxxhash-dev zlib1g-dev nlohmann-json3-dev python3-matplotlib libcairo2-dev \
libclang-rt-14-dev pybind11-dev python3-dev python3-numpy python3-pytest python3-gsd python3-ase \
ffmpeg libcpp-httplib-dev chromium python3-websocket libopenmpi-dev openmpi-bin python3-ipykernel \
python3-nbclient python3-nbformat help2man python3-venv python3-pip python3-setuptools python3-wheel"

missing=""
for p in $PACKAGES; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done

if [ -n "$missing" ]; then
  echo "install-deps: installing:$missing"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $missing
else
  echo "install-deps: all packages present"
fi
