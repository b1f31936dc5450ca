"""camcov: dynamic multi-target coverage with robotic cameras (Hönig & Ayanian).

load_scene(file) -> Scene; Scene.world_at(t) -> World (targets, obstacles, boundary);
Visibility(world, scene) -> what the scene's cameras see at given poses, and the reward;
run(scene_file, method) and simulate(scene_file, controller) -> Run; bench(...) is
`camcov bench`; report(folder) is `camcov report`. camcov.env holds Gymnasium and PettingZoo
environments (imported on first use: the core needs neither). See docs/python.md.
"""
from camcov import _core
from camcov._core import *  # noqa: F401,F403  (the compiled core is the package's API)

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
del _name, _value
