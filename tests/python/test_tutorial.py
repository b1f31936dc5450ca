"""docs/tutorial.md runs as written: in a fresh folder, with the camcov just built on PATH, its
files are written and its `sh run` blocks run in order; each succeeds, says what the tutorial
says it says, and makes the files it promises; its C++ section runs as written in a copy of the
clone, the file copied into examples/ beside every method there and a second user method of the
same shape, and `scripts/build.sh release camcov` built; and nothing is left behind (the folder
is removed, and no program wrote to TMPDIR)."""
import os
import pathlib
import re
import shutil
import subprocess
import tempfile

from conftest import REPO

TUTORIAL = REPO / "docs" / "tutorial.md"
# ```lang [run | file=NAME]  ...  ```
BLOCK = re.compile(r"^```(\w*)[ \t]*([^\n]*)\n(.*?)^```[ \t]*$", re.S | re.M)

# What the tutorial promises, each named in its text.
PROMISED_FILES = ["first.png", "state.json", "results/first-paper-seed1.json",
                  "results/first-paper.mp4", "first.html", "results/first-look-at-nearest-seed1.json",
                  "both.html", "compare/report.html", "compare/summary.json",
                  "compare/explore/first.html"]
PROMISED_OUTPUT = ["ok    first.json: 3 target(s), 1 obstacle(s), 2 camera(s)", "[10.0, 11.0]",
                   "average coverage", "against paper:"]


def blocks(text):
    """(language, marker, body) of every fenced block, in order."""
    return [(m.group(1), m.group(2).strip(), m.group(3)) for m in BLOCK.finditer(text)]


def flat(text):
    return " ".join(text.split())


# Step 0's PATH: the build's `camcov` and the build's `python3`, in front of the reader's own.
STEP_0_PATH = 'export PATH="$PWD/build/src/cli:$PWD/build/python/bin:$PATH"'


def camcov_environment(root):
    """Step 0's environment, on a PATH whose own python3 has no numpy (as pyenv's or conda's
    may not): the build's comes first, so that one takes none of the steps. The reader's home
    is ours, so `~/camcov-tutorial` is the tutorial's folder."""
    env = dict(os.environ)
    build = pathlib.Path(os.environ["CAMCOV_BINARY"]).parents[2]
    other = root / "other-python"
    other.mkdir()
    (other / "python3").write_text(
        "#!/bin/sh\necho \"ModuleNotFoundError: No module named 'numpy'\" >&2\nexit 1\n")
    (other / "python3").chmod(0o755)
    env["PATH"] = os.pathsep.join([str(build / "src" / "cli"), str(build / "python" / "bin"),
                                   str(other), env["PATH"]])
    env["TMPDIR"] = str(root / "tmp")
    env["HOME"] = str(root / "home")
    return env


def compiler_cache():
    """Where ccache keeps the clone's objects (scripts/build.sh compiles through it where it is
    installed), found before HOME moves: a reader's second tree shares their one cache, and so
    the copy below builds from the clone's objects rather than from nothing."""
    if shutil.which("ccache") is None:
        return None
    found = subprocess.run(["ccache", "--get-config", "cache_dir"], capture_output=True,
                           text=True)
    return found.stdout.strip() if found.returncode == 0 and found.stdout.strip() else None


def copy_of_the_clone(to):
    """The clone as its reader has it: its files, without build folders or what runs wrote."""
    outputs = {".git", "bench-results", "results", "out", "tour", "__pycache__"}

    def left_out(folder, names):
        at_root = pathlib.Path(folder) == REPO
        return [n for n in names if n in outputs or (at_root and n.startswith("build"))]

    shutil.copytree(REPO, to, ignore=left_out)
    return to


# A second user method beside the tutorial's, written the same way: its own file in examples/,
# the same registration constant and the same file-local class name.
SECOND_METHOD = """#include <cstdint>
#include <memory>

#include "control/controller.h"
#include "control/methods.h"

namespace camcov::examples {
namespace {

class LookAtNearestController final : public control::Controller {
 public:
  void control(const control::Observation&, std::span<scene::CameraCommand> commands) override {
    for (scene::CameraCommand& c : commands)
      c = {};
  }
  std::optional<geometry::Pose> goal(std::size_t) const override { return std::nullopt; }
  void takeEvents(std::vector<control::ControlEvent>&) override {}
};

}  // namespace

const bool kRegistered = control::registerMethod(
    {"hold-still", "every camera holds still", "#17becf", control::Role::example,
     [](const scene::Scene&, const params::Parameters&,
        std::uint64_t) -> std::unique_ptr<control::Controller> {
       return std::make_unique<LookAtNearestController>();
     }});

}  // namespace camcov::examples
"""


def test_the_tutorial_marks_what_it_runs():
    found = blocks(TUTORIAL.read_text())
    marked = [marker for _, marker, _ in found if marker]
    assert marked.count("run") >= 5
    assert all(m in ("run", "after-build") or m.startswith("file=") for m in marked), marked
    assert marked.count("after-build") == 1
    assert STEP_0_PATH in TUTORIAL.read_text(), "step 0 puts the build's python3 first"
    text = flat(TUTORIAL.read_text())
    for name in PROMISED_FILES:
        assert name in text, f"the tutorial does not name {name}"


def test_the_tutorial_runs_as_written():
    text = TUTORIAL.read_text()
    with tempfile.TemporaryDirectory(prefix="camcov-tutorial-") as name:
        root = pathlib.Path(name)
        folder = root / "home" / "camcov-tutorial"
        folder.mkdir(parents=True)
        (root / "tmp").mkdir()
        env = camcov_environment(root)
        said = ""
        for language, marker, body in blocks(text):
            if marker.startswith("file="):
                (folder / marker[len("file="):]).write_text(body)
            elif marker == "run":
                done = subprocess.run(["bash", "-euo", "pipefail", "-c", body], cwd=folder,
                                      env=env, capture_output=True, text=True, timeout=120)
                assert done.returncode == 0, f"{body}\n{done.stdout}\n{done.stderr}"
                said += done.stdout
        for line in PROMISED_OUTPUT:
            assert line in said, f"{line!r} not in:\n{said}"
            assert line in text, f"the tutorial does not say {line!r}"
        for file in PROMISED_FILES:
            assert (folder / file).is_file() and (folder / file).stat().st_size > 0, file

        # The mistake it shows is refused with the message it quotes.
        wrong = (folder / "first.json").read_text().replace("POINT(9 5)", "POINT(9)")
        (folder / "wrong.json").write_text(wrong)
        refused = subprocess.run(["camcov", "validate", "wrong.json"], cwd=folder, env=env,
                                 capture_output=True, text=True)
        assert refused.returncode == 2
        quoted = re.search(r"`(error first\.json: targets\[0\]\.path: [^`]*)`", text, re.S)
        assert quoted, "the tutorial quotes the error"
        assert flat(quoted.group(1)).replace("first.json", "wrong.json") in flat(refused.stdout)

        # Its C++ section, as written, from the root of a clone that holds a second user method.
        clone = copy_of_the_clone(root / "camcov")
        (clone / "examples" / "hold_still_controller.cpp").write_text(SECOND_METHOD)
        body = next(body for _, marker, body in blocks(text) if marker == "after-build")
        built = dict(env)  # as step 0 has it: the clone's camcov first on PATH
        if cache := compiler_cache():
            built["CCACHE_DIR"] = cache
        built["PATH"] = os.pathsep.join([str(clone / "build" / "src" / "cli"), env["PATH"]])
        done = subprocess.run(["bash", "-euo", "pipefail", "-c", body], cwd=clone, env=built,
                              capture_output=True, text=True, timeout=3600)
        assert done.returncode == 0, f"{body}\n{done.stdout}\n{done.stderr}"
        assert (folder / "results/first-look-at-nearest-cpp-seed1.json").is_file()
        assert "look-at-nearest-cpp" in (folder / "compare-cpp/summary.json").read_text()
        beside = subprocess.run(["camcov", "run", "first.json", "--method", "hold-still",
                                 "--duration", "1", "--out", "results"], cwd=folder, env=built,
                                capture_output=True, text=True)
        assert beside.returncode == 0, beside.stderr

        assert list((root / "tmp").iterdir()) == [], "a program left files in TMPDIR"
    assert not root.exists()
