"""One version number: CMakeLists.txt's project(ede VERSION ...) is the library's (ede::version(), the tools'
--version), the module's (ede.__version__), and the one a module refuses to run with another of: a module
built for another version than the library it is linked with fails at import with ede.Error."""
import os
import pathlib
import re
import shutil
import subprocess
import sys

import pytest

import ede
from conftest import ROOT, tool

BUILD = pathlib.Path(os.environ.get("EDE_BUILD_DIR", ROOT / "build"))


def project_version():
    return re.search(r"^project\(ede VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text(), re.M).group(1)


def test_the_module_the_library_and_the_tools_say_the_project_version():
    assert ede.__version__ == project_version()
    assert ede._ede.version() == ede.__version__
    assert tool("ede-replay", "--version").stdout.split()[-1] == ede.__version__


def test_a_module_built_for_another_version_is_refused_at_import(tmp_path):
    built = BUILD / "python-other-version" / "ede"
    extension = sorted(built.glob("_ede*.so"))
    if not extension:
        pytest.skip("no module built for another version in %s (CMake target _ede_other_version)" % built)
    package = tmp_path / "ede"
    shutil.copytree(pathlib.Path(ede.__file__).parent, package, ignore=shutil.ignore_patterns("_ede*.so", "__pycache__"))
    shutil.copy(extension[0], package)
    code = ("import sys\n"
            "try:\n"
            "    import ede\n"
            "except Exception as e:\n"
            "    print(isinstance(e, sys.modules['ede._errors'].Error), e)\n")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=tmp_path,
                       env={**os.environ, "PYTHONPATH": str(tmp_path)})
    assert p.returncode == 0, p.stderr
    assert p.stdout.startswith("True ede's Python module was built for ede 0.0.0-other but is linked with ede's "
                               "library %s: build both from one tree" % ede.__version__), p.stdout
