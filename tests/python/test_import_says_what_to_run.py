"""`import camcov` where it cannot work says why and what to run, instead of Python's own
words ("cannot import name '_core' ... circular import", "No module named 'numpy'"): a package
folder without its compiled core (after the main job, which builds only the program), a core
built for another Python, a Python without numpy. The Python it names imports camcov."""
import os
import pathlib
import re
import shutil
import subprocess
import sys

from conftest import REPO

BUILT_PACKAGE = pathlib.Path(os.environ["PYTHONPATH"].split(os.pathsep)[0]) / "camcov"


def import_camcov(python_path, *flags, python=sys.executable):
    env = dict(os.environ, PYTHONPATH=str(python_path))
    return subprocess.run([str(python), *flags, "-c", "import camcov"], env=env,
                          capture_output=True, text=True)


def package_without_core(folder):
    """The package's Python files as the build copies them, and no compiled core."""
    package = folder / "camcov"
    package.mkdir()
    for source in (REPO / "src" / "python" / "camcov").glob("*.py"):
        shutil.copy(source, package)
    return package


def test_a_package_without_its_core_says_what_builds_it(tmp_path):
    package_without_core(tmp_path)
    done = import_camcov(tmp_path)
    assert done.returncode != 0
    assert "circular import" not in done.stderr
    assert "ImportError: camcov: the compiled core (camcov._core) is not built" in done.stderr
    assert "scripts/build.sh release camcov_python" in done.stderr
    assert "pip install ." in done.stderr


def test_a_core_built_for_another_python_is_named_with_the_python_to_run(tmp_path):
    package = package_without_core(tmp_path)
    other = "_core.cpython-39-x86_64-linux-gnu.so"
    (package / other).write_bytes(b"")
    done = import_camcov(tmp_path)
    assert done.returncode != 0
    assert "circular import" not in done.stderr
    assert other in done.stderr
    assert f"is for another Python than {sys.executable}" in done.stderr


def test_a_python_without_numpy_is_told_which_python_has_it():
    # -S: without site-packages, where Debian's numpy is; the build's package is on PYTHONPATH.
    done = import_camcov(BUILT_PACKAGE.parent, "-S")
    assert done.returncode != 0
    assert "camcov needs numpy, which" in done.stderr
    named = re.search(r"run (\S+), the Python this build is for", done.stderr)
    assert named, done.stderr
    # The Python it names has numpy and the core.
    works = subprocess.run([named.group(1), "-c", "import numpy, camcov"],
                           env=dict(os.environ, PYTHONPATH=str(BUILT_PACKAGE.parent)),
                           capture_output=True, text=True)
    assert works.returncode == 0, works.stderr
