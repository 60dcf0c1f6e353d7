"""Builds the extension ede._ede with CMake for the interpreter running pip (pyproject.toml holds the rest).

setuptools drives CMake: build_ext configures this repository's CMakeLists.txt with Python_EXECUTABLE set to
the interpreter running the build (its headers; numpy is needed only at run time), builds the target _ede,
which builds libede from these same sources (so the extension and the library are one version, checked
again at import), and copies the extension into the wheel, or beside the sources in python/ede for
`pip install -e`. The CMake build lives in build-python-<interpreter>/ at the repository's root, one per
interpreter: a second `pip install` rebuilds only what changed, and the objects are those of the developer's
build/ (same flags, same depth: a compiler cache shares them). The version is CMakeLists.txt's.
Environment: CMAKE_ARGS adds CMake options (e.g. "-DCMAKE_CXX_COMPILER=clang++"), CMAKE_BUILD_PARALLEL_LEVEL
sets the jobs (default: every core).
Rejected: a second build description for setuptools (the flags that keep ede deterministic live in CMake)
and linking a libede installed elsewhere (its version may differ from these sources).
"""
import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent
TAG = sysconfig.get_config_var("SOABI") or "py%d%d" % sys.version_info[:2]
CMAKE_DIR = ROOT / ("build-python-" + TAG)


def project_version():
    """The version in CMakeLists.txt's project(ede VERSION x.y.z): the one number of the library, the tools
    and the module."""
    found = re.search(r"^project\(ede VERSION ([0-9][0-9.]*)", (ROOT / "CMakeLists.txt").read_text(), re.M)
    if not found:
        sys.exit("setup.py: no `project(ede VERSION x.y.z ...)` line in %s" % (ROOT / "CMakeLists.txt"))
    return found.group(1)


def cmake(*args):
    print("setup.py: cmake " + " ".join(shlex.quote(str(a)) for a in args), flush=True)
    try:
        subprocess.run(["cmake", *map(str, args)], check=True)
    except FileNotFoundError:
        sys.exit("setup.py: cmake (>= 3.25) is needed to build ede's extension; on Debian: scripts/install-deps.sh")
    except subprocess.CalledProcessError as e:
        sys.exit("setup.py: cmake failed (exit %d) in %s; its messages are above (a missing library? on Debian, "
                 "scripts/install-deps.sh installs them all)" % (e.returncode, CMAKE_DIR))


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        configure = ["-S", ROOT, "-B", CMAKE_DIR, "-DCMAKE_BUILD_TYPE=Release", "-DEDE_PYTHON=ON",
                     "-DEDE_BUILD_TESTS=OFF", "-DPython_EXECUTABLE=" + sys.executable]
        try:  # pybind11 from pip or conda brings its CMake files; else CMake finds the system's (pybind11-dev)
            import pybind11
            configure.append("-Dpybind11_DIR=" + pybind11.get_cmake_dir())
        except ImportError:
            pass
        configure += shlex.split(os.environ.get("CMAKE_ARGS", ""))
        cmake(*configure)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        cmake("--build", CMAKE_DIR, "--target", "_ede", "-j", jobs)
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = CMAKE_DIR / "python" / "ede" / ("_ede" + suffix)
        if not built.exists():
            sys.exit("setup.py: CMake built no %s (was it configured for another Python?)" % built)
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(
    version=project_version(),
    ext_modules=[Extension("ede._ede", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": str(CMAKE_DIR / "setuptools")}},
)
