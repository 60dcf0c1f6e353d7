"""`pip install` of the Python module into fresh environments, as docs/python.md tells a user (slow: it builds
the extension and libede in each interpreter's own CMake tree; ctest label `slow`).

For the interpreter ctest runs (Debian's python3, numpy from Debian) and for the python3 first on the PATH
when that is another interpreter with numpy (else skipped, saying why), from a copy of the repository:
  - `python -m venv --system-site-packages`, then `pip install --no-build-isolation .` with no package index
    (PIP_NO_INDEX: nothing may be downloaded); the module imports from another folder, from the venv, with
    the project's version, and the module's pytest suite passes against it;
  - `pip wheel .` makes a wheel that installs into a second venv of the same interpreter and reads a log;
  - `pip install -e .` (editable) imports the sources: an edit of a .py file is seen without reinstalling;
  - scripts/install-python.sh leaves an interpreter without numpy alone, saying how to add numpy.
Also: the package's Python parses in every CPython >= 3.9 found on the machine (requires-python).

Environment: EDE_SOURCE_DIR (the repository), EDE_BUILD_DIR (the CMake build: its tools), EDE_PIP_WORK (a
scratch folder; its copies' CMake trees are kept between runs, so a rerun rebuilds only what changed).
"""
import glob
import os
import pathlib
import re
import shutil
import subprocess
import sys

import pytest

SOURCE = pathlib.Path(os.environ.get("EDE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
BUILD = pathlib.Path(os.environ.get("EDE_BUILD_DIR", SOURCE / "build"))
WORK = pathlib.Path(os.environ.get("EDE_PIP_WORK", BUILD / "tests" / "pip-install"))
VERSION = re.search(r"^project\(ede VERSION ([0-9.]+)", (SOURCE / "CMakeLists.txt").read_text(), re.M).group(1)
# Nothing is fetched from a package index; pip says so if it would need to.
PIP_ENV = {"PIP_NO_INDEX": "1", "PIP_DISABLE_PIP_VERSION_CHECK": "1", "PYTHONDONTWRITEBYTECODE": "1"}


def run(*args, cwd=None, env=None, check=True):
    environment = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}
    environment.update(PIP_ENV)
    environment.update(env or {})
    p = subprocess.run([str(a) for a in args], cwd=cwd, env=environment, capture_output=True, text=True)
    if check and p.returncode != 0:
        pytest.fail("%s exited %d\n--- stdout\n%s\n--- stderr\n%s" % (" ".join(map(str, args)), p.returncode,
                                                                       p.stdout[-6000:], p.stderr[-6000:]))
    return p


def copy_of_the_repository():
    """The repository as a user would have it (no build trees, no caches) in WORK/src; the CMake trees
    build-python-* of an earlier run stay, so that only what changed is rebuilt."""
    dest = WORK / "src"
    dest.mkdir(parents=True, exist_ok=True)
    for entry in dest.iterdir():
        if not entry.name.startswith("build-python-"):
            shutil.rmtree(entry) if entry.is_dir() and not entry.is_symlink() else entry.unlink()
    top = shutil.ignore_patterns(".git", "build*", "out")  # build trees and outputs at the root only
    skip = shutil.ignore_patterns("__pycache__", "*.egg-info", "_ede*.so")
    for entry in SOURCE.iterdir():
        if top(str(SOURCE), [entry.name]) or skip(str(SOURCE), [entry.name]):
            continue
        if entry.is_dir():
            shutil.copytree(entry, dest / entry.name, ignore=skip, symlinks=True)
        else:
            shutil.copy2(entry, dest / entry.name)
    return dest


def interpreter(python):
    """(sys.executable, version, has numpy) of an interpreter command, or None if it does not run."""
    p = subprocess.run([python, "-c", "import sys, importlib.util as u; print(sys.executable); "
                        "print('%d.%d.%d' % sys.version_info[:3]); print(u.find_spec('numpy') is not None)"],
                       capture_output=True, text=True)
    if p.returncode != 0:
        return None
    exe, version, numpy = p.stdout.split()
    return exe, version, numpy == "True"


def second_interpreter():
    """The python3 first on the PATH when it is not the interpreter running these tests."""
    found = shutil.which("python3")
    mine = interpreter(sys.executable)
    theirs = interpreter(found) if found else None
    if theirs is None or os.path.realpath(theirs[0]) == os.path.realpath(mine[0]) and theirs[1] == mine[1]:
        return None, "the python3 first on the PATH is the interpreter running these tests (%s)" % mine[0]
    if not theirs[2]:
        return None, ("the python3 first on the PATH (%s, Python %s) has no numpy; `%s -m pip install numpy` "
                      "would add it (no package index here)" % (theirs[0], theirs[1], theirs[0]))
    return theirs[0], ""


INTERPRETERS = ["tested", "PATH"]


@pytest.fixture(scope="module")
def source():
    return copy_of_the_repository()


@pytest.fixture(scope="module", params=INTERPRETERS)
def installed(request, source):
    """A venv of the interpreter with the module pip-installed from the copy: (venv's python, folder)."""
    if request.param == "tested":
        base = sys.executable
    else:
        base, why = second_interpreter()
        if base is None:
            pytest.skip(why)
    name = "venv-" + re.sub(r"[^A-Za-z0-9.]+", "-", interpreter(base)[1])
    venv = WORK / name
    shutil.rmtree(venv, ignore_errors=True)
    run(base, "-m", "venv", "--system-site-packages", venv)
    python = venv / "bin" / "python"
    run(python, "-m", "pip", "install", "--no-build-isolation", ".", cwd=source)  # docs/python.md's command
    return python, venv


def test_the_module_imports_from_the_venv_with_the_projects_version(installed, tmp_path):
    python, venv = installed
    p = run(python, "-c", "import ede, importlib.metadata as m; print(ede.__file__); print(ede.__version__); "
            "print(m.version('ede'))", cwd=tmp_path)
    where, version, metadata = p.stdout.split()
    assert where.startswith(str(venv)), where
    assert version == metadata == VERSION


def test_the_modules_test_suite_passes_against_the_installed_module(installed, source, tmp_path):
    python, venv = installed
    tests = sorted(glob.glob(str(source / "python" / "tests" / "test_*.py")))
    env = {"EDE_TOOLS_DIR": str(BUILD / "tools"), "EDE_BUILD_DIR": str(BUILD)}
    where = run(python, "-c", "import ede; print(ede.__file__)", cwd=tmp_path, env=env).stdout.strip()
    assert where.startswith(str(venv)), where  # the suite below tests the installed module
    run(python, "-m", "pytest", "-q", "-p", "no:cacheprovider", *tests, cwd=tmp_path, env=env)


def test_a_wheel_installs_into_another_venv_of_the_same_interpreter(installed, source, tmp_path):
    python, venv = installed
    wheels = WORK / ("wheels-" + venv.name)
    shutil.rmtree(wheels, ignore_errors=True)
    run(python, "-m", "pip", "wheel", "--no-build-isolation", "--no-deps", "-w", wheels, ".", cwd=source)
    wheel = sorted(wheels.glob("ede-%s-*.whl" % VERSION))
    assert len(wheel) == 1, list(wheels.iterdir())
    other = WORK / (venv.name + "-wheel")
    shutil.rmtree(other, ignore_errors=True)
    base = run(python, "-c", "import sys; print(sys._base_executable)").stdout.strip()
    run(base, "-m", "venv", "--system-site-packages", other)
    run(other / "bin" / "python", "-m", "pip", "install", wheel[0])
    code = ("import sys, ede; print(ede.__file__)\n"
            "ede.run(sys.argv[1], log='w.ede', progress=False, set={'stop.collisions_per_particle': 2})\n"
            "with ede.open('w.ede') as log: print(log.state().events == log.info['events'])\n")
    p = run(other / "bin" / "python", "-c", code, source / "examples" / "gas.toml", cwd=tmp_path)
    where, ok = p.stdout.split()
    assert where.startswith(str(other)) and ok == "True", p.stdout


def test_an_editable_install_imports_the_sources(installed, source, tmp_path):
    python, venv = installed
    edit = WORK / (venv.name + "-editable")
    shutil.rmtree(edit, ignore_errors=True)
    base = run(python, "-c", "import sys; print(sys._base_executable)").stdout.strip()
    run(base, "-m", "venv", "--system-site-packages", edit)
    run(edit / "bin" / "python", "-m", "pip", "install", "--no-build-isolation", "-e", ".", cwd=source)
    marker = source / "python" / "ede" / "_editable_marker.py"
    marker.write_text("SEEN = 'edited after the install'\n")
    try:
        p = run(edit / "bin" / "python", "-c", "import ede, ede._editable_marker as m; print(ede.__file__); "
                "print(m.SEEN == 'edited after the install'); print(ede.__version__)", cwd=tmp_path)
    finally:
        marker.unlink()
    where, seen, version = p.stdout.split()
    assert where == str(source / "python" / "ede" / "__init__.py") and seen == "True" and version == VERSION


def test_install_python_sh_says_how_to_add_numpy(source, tmp_path):
    bare = tmp_path / "bare"
    run(sys.executable, "-m", "venv", "--without-pip", bare)  # no system site: no numpy
    p = run("sh", source / "scripts" / "install-python.sh", bare / "bin" / "python", check=False)
    assert p.returncode == 1
    assert "has no numpy, which ede needs: `%s -m pip install numpy`" % (bare / "bin" / "python") in p.stdout, p.stdout
    assert not list(bare.rglob("_ede*.so"))


def test_the_package_parses_in_every_cpython_from_3_9(source):
    roots = [os.environ.get("PYENV_ROOT", os.path.expanduser("~/.pyenv"))]
    found = set(glob.glob(os.path.join(roots[0], "versions", "*", "bin", "python3")))
    found |= {shutil.which("python3.%d" % minor) for minor in range(9, 15)} - {None}
    checked = []
    for python in sorted(found):
        info = interpreter(python)
        if info is None or tuple(map(int, info[1].split(".")[:2])) < (3, 9):
            continue
        code = ("import ast, pathlib, sys\n"
                "for f in sorted(pathlib.Path(sys.argv[1]).glob('*.py')): ast.parse(f.read_text(), str(f))\n")
        run(python, "-c", code, source / "python" / "ede")
        checked.append(info[1])
    if not checked:
        pytest.skip("no CPython >= 3.9 besides the ones above on this machine")
    assert checked
