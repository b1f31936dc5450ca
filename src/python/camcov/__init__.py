"""camcov: dynamic multi-target coverage with robotic cameras (Hönig & Ayanian).

load_scene(file) -> Scene; Scene.world_at(t) -> World (targets, obstacles, boundary);
Visibility(world, scene) -> what the scene's cameras see at given poses, and the reward;
run(scene_file, method) and simulate(scene_file, controller) -> Run; bench(...) is
`camcov bench`; report(folder) is `camcov report`. camcov.env holds Gymnasium and PettingZoo
environments (imported on first use: the core needs neither). See docs/python.md.
"""
import importlib.util
import pathlib
import sys


def _what_to_run():
    """The Python this package was built for, where a build says so, and what else to run."""
    build_python = pathlib.Path(__file__).parent.parent / "bin" / "python3"
    if build_python.exists():  # a build folder's package (src/python/CMakeLists.txt)
        return (f"run {build_python}, the Python this build is for (or put "
                f"{build_python.parent} first on PATH), or `pip install .` into this one")
    return "run Debian's /usr/bin/python3, or `pip install .` into this one"


def _why_not_importable():
    """Why `import camcov` cannot work in this Python, as a reader can act on, or None."""
    this = f"{sys.executable} (Python {sys.version_info.major}.{sys.version_info.minor})"
    folder = pathlib.Path(__file__).parent
    if importlib.util.find_spec(__name__ + "._core") is None:
        built = sorted(p.name for p in folder.glob("_core.*"))
        if built:  # its file name says for which Python
            return (f"camcov: the compiled core in {folder} ({', '.join(built)}) is for another "
                    f"Python than {this}: {_what_to_run()}")
        return (f"camcov: the compiled core (camcov._core) is not built in {folder}: "
                "`bash scripts/main_job.sh` and `scripts/build.sh release camcov` build only "
                "the camcov program; from the clone's root run `scripts/build.sh release "
                "camcov_python` (or `scripts/build.sh`, which builds everything and installs "
                "the module for Debian's python3), or `pip install .`")
    if importlib.util.find_spec("numpy") is None:
        return f"camcov needs numpy, which {this} does not have: {_what_to_run()}"
    return None


_problem = _why_not_importable()
if _problem is not None:
    raise ImportError(_problem, name=__name__)

from camcov import _core  # noqa: E402
from camcov._core import *  # noqa: E402,F401,F403  (the compiled core is the package's API)

__version__ = _core.__version__

# The core's classes and functions present themselves as camcov's (camcov.Scene, not
# camcov._core.Scene), in reprs, errors and help().
for _name in dir(_core):
    _value = getattr(_core, _name)
    if not _name.startswith("_") and getattr(_value, "__module__", None) == "camcov._core":
        try:
            _value.__module__ = "camcov"
        except (AttributeError, TypeError):
            pass
del _name, _value, _problem, _what_to_run, _why_not_importable, importlib, pathlib, sys
