"""`pip install .` into a fresh virtual environment, offline, and the wheel the in-tree backend
(scripts/packaging/camcov_build.py) writes.

ctest runs this file with the Python that its build folder is configured for, the module of
that folder on PYTHONPATH: pip builds the package in that folder (or in CAMCOV_BUILD_DIR), which
compiles nothing again. pip's and the virtual environment's temporary files go under tmp_path
too (TMPDIR), not into /tmp.
"""
import base64
import csv
import hashlib
import importlib.util
import io
import json
import os
import pathlib
import re
import subprocess
import sys
import sysconfig
import zipfile

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
SCENE = REPO / "scenes" / "fig1_example.json"  # the cameras see part of it from the start

# Run by the virtual environment's Python: where camcov comes from, and a short run with it.
CHECK = """
import importlib.metadata, json, sys, sysconfig
import camcov
run = camcov.run(sys.argv[1], "local", seed=1, params={"sim.duration": 1})
print(json.dumps({"file": camcov.__file__, "site": sysconfig.get_paths()["platlib"],
                  "version": camcov.__version__, "installed": importlib.metadata.version("camcov"),
                  "coverage": run.summary["averageCoverage"]}))
"""


@pytest.fixture(scope="module")
def backend():
    """The backend, imported as pip does, without writing __pycache__ into the sources."""
    spec = importlib.util.spec_from_file_location(
        "camcov_build", REPO / "scripts" / "packaging" / "camcov_build.py")
    module = importlib.util.module_from_spec(spec)
    writes, sys.dont_write_bytecode = sys.dont_write_bytecode, True
    try:
        spec.loader.exec_module(module)
    finally:
        sys.dont_write_bytecode = writes
    return module


@pytest.fixture
def build_dir():
    """CAMCOV_BUILD_DIR, else the build folder whose camcov ctest puts on PYTHONPATH
    (<build>/python/camcov): pip builds there, so nothing is compiled again."""
    folder = os.environ.get("CAMCOV_BUILD_DIR")
    if not folder:
        spec = importlib.util.find_spec("camcov")  # found, not imported
        folder = spec and spec.origin and pathlib.Path(spec.origin).parents[2]
    if not folder or not (pathlib.Path(folder) / "CMakeCache.txt").exists():
        pytest.fail("no build folder: set CAMCOV_BUILD_DIR or put <build>/python on PYTHONPATH "
                    "(ctest does), else pip would compile the whole module in build-python/")
    return str(folder)


def environment(tmp_path, **extra):
    """Offline; no PYTHONPATH (it may hold build/python, a camcov of its own); temporary files,
    bytecode and caches kept out of /tmp, the sources and the home folder."""
    temporary = tmp_path / "tmp"
    temporary.mkdir(exist_ok=True)
    env = {key: value for key, value in os.environ.items() if key != "PYTHONPATH"}
    env.update(TMPDIR=str(temporary), PIP_NO_INDEX="1", PIP_NO_CACHE_DIR="1",
               PIP_DISABLE_PIP_VERSION_CHECK="1", PYTHONDONTWRITEBYTECODE="1", **extra)
    return env


def run(command, **kwargs):
    result = subprocess.run([str(part) for part in command], capture_output=True, text=True,
                            **kwargs)
    assert result.returncode == 0, f"{command}:\n{result.stdout}\n{result.stderr}"
    return result


def test_pip_install_puts_a_working_camcov_into_a_virtual_environment(tmp_path, build_dir):
    venv = tmp_path / "venv"
    env = environment(tmp_path, CAMCOV_BUILD_DIR=build_dir)
    # --system-site-packages for numpy, which pip cannot fetch offline.
    run([sys.executable, "-m", "venv", "--system-site-packages", venv], env=env)
    python = venv / "bin" / "python"
    run([python, "-m", "pip", "install", REPO], env=env, cwd=tmp_path)
    # From a folder with no camcov in it: the one found must be the virtual environment's.
    found = json.loads(run([python, "-c", CHECK, SCENE], env=env, cwd=tmp_path).stdout)
    installed = pathlib.Path(found["file"]).resolve()
    assert installed.parent == pathlib.Path(found["site"]).resolve() / "camcov"
    assert installed.is_relative_to(venv.resolve())
    assert found["installed"] == found["version"]  # the wheel's and the core's, from CMake
    assert 0 < found["coverage"] <= 1


def test_the_wheel_records_every_file_with_its_digest_and_is_the_same_twice(tmp_path,
                                                                           build_dir):
    env = environment(tmp_path)
    env.pop("CAMCOV_BUILD_DIR", None)  # the folder comes from the config setting here
    if subprocess.run([sys.executable, "-m", "build", "--version"], capture_output=True,
                      env=env, cwd=tmp_path).returncode != 0:
        pytest.skip("no `python3 -m build` (Debian: python3-build)")
    wheels = []
    for out in (tmp_path / "first", tmp_path / "second"):
        run([sys.executable, "-m", "build", "--wheel", "--no-isolation",
             "-C", f"build-dir={build_dir}", "--outdir", out, REPO], env=env, cwd=tmp_path)
        wheels += list(out.glob("*.whl"))
    assert len(wheels) == 2 and wheels[0].read_bytes() == wheels[1].read_bytes()
    tag = re.fullmatch(r"camcov-([0-9.]+)-(\w+)-(\w+)-(\w+)\.whl", wheels[0].name)
    assert tag and tag.group(2) == f"cp{sys.version_info[0]}{sys.version_info[1]}"

    with zipfile.ZipFile(wheels[0]) as wheel:
        names = wheel.namelist()
        record = f"camcov-{tag.group(1)}.dist-info/RECORD"
        rows = list(csv.reader(io.StringIO(wheel.read(record).decode())))
        assert sorted(row[0] for row in rows) == sorted(names)
        for name, digest, size in rows:
            if name == record:
                assert digest == size == ""
                continue
            data = wheel.read(name)
            sha256 = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=")
            assert (digest, int(size)) == (f"sha256={sha256.decode()}", len(data)), name
    package = {f"camcov/{path.name}" for path in (REPO / "src" / "python" / "camcov").glob("*.py")}
    package.add(f"camcov/_core{sysconfig.get_config_var('EXT_SUFFIX')}")
    assert {name for name in names if name.startswith("camcov/")} == package


def test_a_build_folder_for_another_python_is_refused(tmp_path, backend):
    folder = tmp_path / "other"
    folder.mkdir()
    (folder / "CMakeCache.txt").write_text(f"CMAKE_HOME_DIRECTORY:INTERNAL={REPO}\n"
                                           "CAMCOV_BUILD_PYTHON:BOOL=ON\n"
                                           "Python3_EXECUTABLE:FILEPATH=/nonexistent/python\n")
    with pytest.raises(backend.BuildError) as refusal:
        backend.build_wheel(str(tmp_path / "wheels"), {"build-dir": str(folder)})
    assert str(folder) in str(refusal.value) and "/nonexistent/python" in str(refusal.value)
    assert sorted(path.name for path in tmp_path.iterdir()) == ["other"]  # nothing built


def test_the_project_table_reads_the_same_without_tomllib(backend):
    tomllib = pytest.importorskip("tomllib")
    text = (REPO / "pyproject.toml").read_text(encoding="utf-8")
    assert backend._project_table_without_tomllib(text) == tomllib.loads(text)["project"]
