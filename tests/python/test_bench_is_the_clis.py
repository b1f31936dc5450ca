"""camcov.bench is `camcov bench`: one stage behind both, so with the same options (and the
same defaults for the rest) they write the same summary and say the same lines, the plan,
the progress of every job and video, the table and what was written, only the folder's name
and the times differ."""
import pathlib
import re

import pytest

import camcov

OPTIONS = {"methods": ["local", "nearest-unseen"], "seeds": 2}
PARAMS = {"sim.duration": 2.0}


def normalized(text, folder):
    """The lines of `text` with the folder's name and the progress times taken out."""
    text = text.replace(str(folder), "OUT")
    text = re.sub(r"\] \d+:\d\d elapsed, ETA \d+:\d\d \|", "] ... |", text)
    return [line for line in text.splitlines() if line]


def test_python_and_the_cli_say_the_same_lines_and_write_the_same_summary(cli, tiny, tmp_path,
                                                                            capfd):
    scenes = [tiny("tiny_static"), tiny("tiny_dynamic")]
    cli_out = tmp_path / "cli"
    ran = cli("bench", "--scenes", *scenes, "--methods", ",".join(OPTIONS["methods"]),
              "--seeds", OPTIONS["seeds"], "--set", "sim.duration=2", "--jobs", 1,
              "--out", cli_out)
    assert ran.returncode == 0, ran.stderr
    py_out = tmp_path / "py"
    capfd.readouterr()
    summary = camcov.bench(scenes, params=PARAMS, jobs=1, out=str(py_out), **OPTIONS)
    said = capfd.readouterr()
    assert normalized(said.out, py_out) == normalized(ran.stdout, cli_out)
    assert normalized(said.err, py_out) == normalized(ran.stderr, cli_out)
    # The defaults are the CLI's: videos, explorer pages, the optimum of the still scene, the
    # report were all made, and said so in the lines compared above.
    assert any(line.startswith("wrote 4 videos") for line in said.out.splitlines()), said.out
    assert (py_out / "report.html").exists() and (py_out / "optimum" / "tiny_static.json").exists()
    assert (py_out / "summary.json").read_bytes() == (cli_out / "summary.json").read_bytes()
    assert summary["reference"] == "local"


def test_a_resumed_python_bench_says_what_it_reused_as_the_cli_does(tiny, tmp_path, capfd):
    options = dict(OPTIONS, params=PARAMS, out=str(tmp_path / "b"), videos="none",
                   explorer="none", report=False, optimum_budget=0)
    camcov.bench([tiny("tiny_dynamic")], **options)
    capfd.readouterr()
    camcov.bench([tiny("tiny_dynamic")], **options)
    err = capfd.readouterr().err
    assert re.search(r"^4 of 4 jobs already done in .*b \(written .* UTC\); running the other 0$",
                     err, re.M), err


def test_a_negative_optimum_budget_is_refused_as_the_cli_refuses_it(tiny, tmp_path):
    with pytest.raises(ValueError, match="--optimum-budget -5"):
        camcov.bench([tiny("tiny_static")], optimum_budget=-5, out=str(tmp_path / "b"))
    assert not (tmp_path / "b").exists()
