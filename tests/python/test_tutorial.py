"""docs/tutorial.md runs as written: in a fresh folder, with the camcov just built on PATH, its
files are written and its `sh run` blocks run in order; each succeeds, says what the tutorial
says it says, and makes the files it promises; its C++ method, built by the build as the reader
builds it (tests/python/CMakeLists.txt), runs the C++ section's commands; and nothing is left
behind (the folder is removed, and no program wrote to TMPDIR)."""
import os
import pathlib
import re
import subprocess
import sys
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


def camcov_environment(folder):
    env = dict(os.environ)
    # `camcov` is the program just built, and `python3` the Python running this test.
    env["PATH"] = os.pathsep.join([str(pathlib.Path(os.environ["CAMCOV_BINARY"]).parent),
                                   str(pathlib.Path(sys.executable).parent), env["PATH"]])
    env["TMPDIR"] = str(folder / "tmp")
    return env


# The C++ section's build steps, which the build has already taken for the test.
BUILD_STEPS = ["cp ~/camcov-tutorial/look_at_nearest_controller.cpp examples/",
               "scripts/build.sh release camcov", "cd ~/camcov-tutorial"]


def test_the_tutorial_marks_what_it_runs():
    found = blocks(TUTORIAL.read_text())
    marked = [marker for _, marker, _ in found if marker]
    assert marked.count("run") >= 5
    assert all(m in ("run", "after-build") or m.startswith("file=") for m in marked), marked
    assert marked.count("after-build") == 1
    text = flat(TUTORIAL.read_text())
    for name in PROMISED_FILES:
        assert name in text, f"the tutorial does not name {name}"


def test_the_tutorial_runs_as_written():
    text = TUTORIAL.read_text()
    with tempfile.TemporaryDirectory(prefix="camcov-tutorial-") as name:
        folder = pathlib.Path(name)
        (folder / "tmp").mkdir()
        env = camcov_environment(folder)
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

        # Its C++ method, built as a file of examples/ is, runs the commands it gives.
        body = next(body for _, marker, body in blocks(text) if marker == "after-build")
        lines = body.splitlines()
        assert lines[:len(BUILD_STEPS)] == BUILD_STEPS, lines
        built = dict(env)
        built["PATH"] = os.pathsep.join(
            [str(pathlib.Path(os.environ["CAMCOV_TUTORIAL_BINARY"]).parent), env["PATH"]])
        done = subprocess.run(["bash", "-euo", "pipefail", "-c",
                               "\n".join(lines[len(BUILD_STEPS):])],
                              cwd=folder, env=built, capture_output=True, text=True, timeout=120)
        assert done.returncode == 0, f"{body}\n{done.stdout}\n{done.stderr}"
        assert (folder / "results/first-look-at-nearest-cpp-seed1.json").is_file()
        assert "look-at-nearest-cpp" in (folder / "compare-cpp/summary.json").read_text()

        assert list((folder / "tmp").iterdir()) == [], "a program left files in TMPDIR"
    assert not folder.exists()
