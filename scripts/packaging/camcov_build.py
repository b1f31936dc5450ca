"""The PEP 517 build backend of the camcov Python package (pyproject.toml names it).

In the source tree, with the standard library and CMake only: pip builds a package in an
isolated environment that hides the system's site-packages, so a backend from Debian
(setuptools, scikit-build) would have to come from a package index, and `pip install .` would
not work offline. This one builds the CMake target camcov_python, which makes the package in
<build>/python/camcov, and zips that folder into a wheel for the Python that runs it.

The CMake build folder: the config setting build-dir (`pip install . --config-settings
build-dir=PATH`, `python3 -m build --wheel --no-isolation -C build-dir=PATH`), else the
environment variable CAMCOV_BUILD_DIR, else build-python/<tag>-<hash> in the source tree, one
per Python; a relative path is taken from the source tree. A folder already configured (the
project's build/, say) is built, not configured again, so only what changed is compiled; it
must be configured for this Python.

The metadata: name, summary and dependencies from pyproject.toml's [project] table, the
version from the project() line of CMakeLists.txt (which the compiled core reports too).
No sdist: build_sdist is left out, so `python3 -m build` needs --wheel.
"""
import ast
import base64
import csv
import hashlib
import io
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import sysconfig
import zipfile

SOURCE = pathlib.Path(__file__).resolve().parents[2]
# The import package: <build>/python/camcov, camcov/ in the wheel.
PACKAGE = "camcov"
# Every entry of the wheel gets this date, so that the same files make the same wheel.
ZIP_DATE = (1980, 1, 1, 0, 0, 0)


class BuildError(RuntimeError):
    """What failed, and in which build folder."""


def _log(message):
    print(f"camcov_build: {message}", file=sys.stderr, flush=True)


# --- Metadata --------------------------------------------------------------------------------

def _cmake_project():
    """The version and description of the project() line of CMakeLists.txt."""
    text = (SOURCE / "CMakeLists.txt").read_text(encoding="utf-8")
    # The whole project(...) call, quoted strings and all (the description has parentheses).
    call = re.search(r'project\(\s*camcov\b(?:[^()"]|"[^"]*")*\)', text)
    version = call and re.search(r"\bVERSION\s+([0-9][0-9.]*)", call.group(0))
    description = call and re.search(r'\bDESCRIPTION\s+"([^"]*)"', call.group(0))
    if not (version and description):
        raise BuildError(f"no `project(camcov VERSION x.y.z ... DESCRIPTION \"...\")` in "
                         f"{SOURCE / 'CMakeLists.txt'}")
    return {"version": version.group(1), "description": description.group(1)}


def _project_table_without_tomllib(text):
    """[project] of pyproject.toml on Python < 3.11 (no tomllib): the TOML that table uses,
    keys set to strings or arrays of strings, which read as Python literals."""
    project, table, key, value = {}, None, None, ""
    for line in text.splitlines():
        stripped = line.strip()
        if key is None:
            if not stripped or stripped.startswith("#"):
                continue
            header = re.fullmatch(r"\[([^\[\]]+)\]\s*(#.*)?", stripped)
            if header:
                name = header.group(1).strip()
                if name == "project":
                    table = project
                elif name.startswith("project."):
                    table = project.setdefault(name[len("project."):], {})
                else:
                    table = None
                continue
            key, _, value = stripped.partition("=")
            key = key.strip()
        else:
            value += "\n" + line
        try:
            parsed = ast.literal_eval(value.strip())
        except SyntaxError:
            continue  # an array over several lines: read on
        except ValueError:
            if table is not None:
                raise BuildError(f"pyproject.toml: [project] {key}: not a string or an array "
                                 "of strings (read without tomllib on this Python)")
            parsed = None  # another table's value, not ours
        if table is not None:
            table[key] = parsed
        key = None
    return project


def _project():
    """pyproject.toml's [project], with what it leaves to CMakeLists.txt (its `dynamic`)."""
    text = (SOURCE / "pyproject.toml").read_text(encoding="utf-8")
    try:
        import tomllib
    except ImportError:
        project = _project_table_without_tomllib(text)
    else:
        project = tomllib.loads(text)["project"]
    return {**project, **_cmake_project()}


def _metadata():
    """The METADATA file (core metadata 2.1)."""
    project = _project()
    lines = ["Metadata-Version: 2.1", f"Name: {project['name']}",
             f"Version: {project['version']}", f"Summary: {project['description']}",
             f"Requires-Python: {project['requires-python']}"]
    lines += [f"Requires-Dist: {requirement}" for requirement in project["dependencies"]]
    for extra, requirements in sorted(project.get("optional-dependencies", {}).items()):
        lines.append(f"Provides-Extra: {extra}")
        lines += [f'Requires-Dist: {requirement}; extra == "{extra}"'
                  for requirement in requirements]
    return "\n".join(lines) + "\n"


def _tag():
    """This Python's wheel tag, e.g. cp311-cp311-linux_x86_64: the extension is for it only."""
    implementation = sys.implementation.name
    python = {"cpython": "cp", "pypy": "pp"}.get(implementation, implementation)
    python += f"{sys.version_info[0]}{sys.version_info[1]}"
    soabi = sysconfig.get_config_var("SOABI").split("-")  # cpython-311-x86_64-linux-gnu
    abi = f"cp{soabi[1]}" if implementation == "cpython" else "_".join(soabi[:2])
    platform = re.sub(r"[-.]", "_", sysconfig.get_platform())
    return f"{python}-{abi.replace('.', '_')}-{platform}"


def _distribution():
    """The wheel's name and version, as in its file names: camcov-0.1.0."""
    project = _project()
    return f"{re.sub(r'[-_.]+', '_', project['name'])}-{project['version']}"


def _dist_info():
    return f"{_distribution()}.dist-info"


def _wheel_file():
    return ("Wheel-Version: 1.0\nGenerator: camcov_build (scripts/packaging/camcov_build.py)\n"
            f"Root-Is-Purelib: false\nTag: {_tag()}\n")


# --- The CMake build -------------------------------------------------------------------------

# What makes an extension right for an interpreter: its installation (a virtual environment
# has its base Python's), its version X.Y and its EXT_SUFFIX.
IDENTITY = ("import json, os, sys, sysconfig; print(json.dumps([os.path.realpath(sys.base_prefix), "
            "'%d.%d' % sys.version_info[:2], sysconfig.get_config_var('EXT_SUFFIX')]))")


def _python_identity(python):
    """The IDENTITY of the interpreter `python`, None if it does not run."""
    try:
        out = subprocess.run([python, "-c", IDENTITY], capture_output=True, text=True,
                             check=True)
    except (OSError, subprocess.CalledProcessError):
        return None
    return json.loads(out.stdout)


def _read_cache(folder):
    entries = {}
    for line in (folder / "CMakeCache.txt").read_text(encoding="utf-8").splitlines():
        match = re.match(r"([A-Za-z_][\w.-]*):[A-Z]+=(.*)", line)
        if match:
            entries[match.group(1)] = match.group(2)
    return entries


def _cmake_true(value):
    return value.upper() not in ("", "0", "OFF", "NO", "FALSE", "N", "IGNORE", "NOTFOUND")


def _check_configured(folder):
    """Refuses a configured folder that would not build the package for this Python; says
    whether its configuration has found a Python."""
    cache = _read_cache(folder)
    source = cache.get("CMAKE_HOME_DIRECTORY")
    if source and os.path.realpath(source) != str(SOURCE):
        raise BuildError(f"the build folder {folder} is configured for the sources in {source}, "
                         f"not {SOURCE}")
    if not _cmake_true(cache.get("CAMCOV_BUILD_PYTHON", "ON")) or \
            _cmake_true(cache.get("CAMCOV_SANITIZE", "OFF")):
        raise BuildError(f"the build folder {folder} does not build the Python module "
                         "(CAMCOV_BUILD_PYTHON=OFF or CAMCOV_SANITIZE=ON)")
    # What FindPython found (_Python3_EXECUTABLE), else what it was told to use.
    theirs = cache.get("_Python3_EXECUTABLE") or cache.get("Python3_EXECUTABLE")
    if not theirs:
        return False  # a configuration that stopped before it looked for Python
    if os.path.realpath(theirs) == os.path.realpath(sys.executable):
        return True
    ours, their_identity = _python_identity(sys.executable), _python_identity(theirs)
    if their_identity != ours:
        described = ", ".join(their_identity) if their_identity else "does not run"
        raise BuildError(
            f"the build folder {folder} is configured for the Python {theirs} ({described}), "
            f"not for {sys.executable} ({', '.join(ours)}) that runs this build. Choose another "
            "folder (--config-settings build-dir=PATH or CAMCOV_BUILD_DIR=PATH), or neither: "
            "build-python/ in the sources has one for each Python")
    return True


def _build_folder(config_settings):
    chosen = (config_settings or {}).get("build-dir") or os.environ.get("CAMCOV_BUILD_DIR")
    if chosen:
        return SOURCE / os.path.expanduser(chosen)  # an absolute path stays itself
    # One folder per interpreter: two Pythons 3.11 (Debian's, pyenv's) have the same tag.
    interpreter = os.path.realpath(sys.executable)
    key = hashlib.sha256(interpreter.encode()).hexdigest()[:8]
    return SOURCE / "build-python" / f"{_tag().split('-')[0]}-{key}"


def _cmake(arguments, what, folder):
    command = ["cmake", *arguments]
    _log(" ".join(command))
    try:
        status = subprocess.run(command).returncode
    except OSError as error:
        raise BuildError(f"{what} in {folder}: cannot run cmake ({error})") from None
    if status != 0:
        raise BuildError(f"{what} failed in {folder} (cmake exited with {status}; "
                         "its output is above)")


def _build(config_settings):
    """Builds the package; returns the folder that holds it (<build>/python/camcov)."""
    folder = _build_folder(config_settings)
    # The realpath rather than sys.executable: a virtual environment (pip's, a test's) may be
    # gone at the next build, and its base Python builds the same extension.
    python = f"-DPython3_EXECUTABLE={os.path.realpath(sys.executable)}"
    if (folder / "CMakeCache.txt").exists():
        if _check_configured(folder):
            _log(f"building the target camcov_python in {folder} (configured already)")
        else:  # with its own options, but for this Python, not the one CMakeLists.txt picks
            _cmake(["-S", str(SOURCE), "-B", str(folder), python], "configuring", folder)
    else:
        _log(f"configuring {folder} for {sys.executable}")
        options = [python, "-DCMAKE_BUILD_TYPE=Release", "-DCAMCOV_BUILD_PYTHON=ON",
                   "-DCAMCOV_SANITIZE=OFF", "-DCAMCOV_BUILD_TESTS=OFF",
                   "-DCAMCOV_BUILD_BENCHMARKS=OFF", "-DCAMCOV_BUILD_FUZZERS=OFF"]
        generator = ["-G", "Ninja"] if shutil.which("ninja") else []  # else CMake's default
        _cmake(["-S", str(SOURCE), "-B", str(folder), *generator, *options],
               "configuring", folder)
    _cmake(["--build", str(folder), "--target", "camcov_python"], "building camcov_python",
           folder)
    return folder / "python" / PACKAGE


# --- The wheel -------------------------------------------------------------------------------

def _package_files(package):
    """(name in the wheel, path): the package's Python files and this Python's extension."""
    core = package / f"_core{sysconfig.get_config_var('EXT_SUFFIX')}"
    if not core.exists():
        raise BuildError(f"no {core.name} in {package}: the build made no extension for "
                         f"{sys.executable}")
    # The build folder's copy of each file of src/python/camcov: one deleted from the sources
    # stays in an old build folder, and must not come back.
    sources = sorted(path.name for path in (SOURCE / "src" / "python" / PACKAGE).glob("*.py"))
    missing = [name for name in sources if not (package / name).exists()]
    if missing:
        raise BuildError(f"{', '.join(missing)} missing in {package}")
    return [(f"{PACKAGE}/{name}", package / name) for name in sorted(sources + [core.name])]


def _record_line(name, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return [name, f"sha256={digest}", str(len(data))]


def _write_wheel(path, files, dist_info):
    record = []
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as wheel:
        def add(name, data, mode=0o644):
            entry = zipfile.ZipInfo(name, ZIP_DATE)
            entry.external_attr = (0o100000 | mode) << 16
            entry.compress_type = zipfile.ZIP_DEFLATED
            wheel.writestr(entry, data)
            record.append(_record_line(name, data))

        for name, source in files:
            add(name, source.read_bytes(), 0o755 if source.suffix == ".so" else 0o644)
        add(f"{dist_info}/METADATA", _metadata().encode())
        add(f"{dist_info}/WHEEL", _wheel_file().encode())
        lines = io.StringIO()
        record.append([f"{dist_info}/RECORD", "", ""])  # a file cannot hold its own digest
        csv.writer(lines, lineterminator="\n").writerows(record)
        add(f"{dist_info}/RECORD", lines.getvalue().encode())


# --- The PEP 517 hooks -----------------------------------------------------------------------

def get_requires_for_build_wheel(config_settings=None):
    return []  # the standard library and CMake (not a Python package)


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    """The metadata without building: pip reads it before it builds."""
    folder = pathlib.Path(metadata_directory) / _dist_info()
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "METADATA").write_text(_metadata(), encoding="utf-8")
    (folder / "WHEEL").write_text(_wheel_file(), encoding="utf-8")
    return folder.name


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    files = _package_files(_build(config_settings))
    name = f"{_distribution()}-{_tag()}.whl"
    path = pathlib.Path(wheel_directory) / name
    path.parent.mkdir(parents=True, exist_ok=True)
    _write_wheel(path, files, _dist_info())
    _log(f"wrote {path}")
    return name
