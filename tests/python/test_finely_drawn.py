"""scripts/finely_drawn.py: finely drawn copies of scenes that camcov still loads, every ring
(and every deformation keyframe of it) cut the same number of times, and bad input refused."""
import json
import pathlib
import subprocess
import sys

from conftest import REPO

SCRIPT = REPO / "scripts" / "finely_drawn.py"


def vertices(wkt):
    return len(wkt.split(","))


def draw(*args):
    return subprocess.run([sys.executable, str(SCRIPT), *map(str, args)], capture_output=True,
                          text=True)


def test_every_ring_and_keyframe_gets_2_to_the_rounds_times_its_vertices(cli, tmp_path):
    coarse, fine = tmp_path / "coarse", tmp_path / "fine"
    made = cli("generate", "--family", "deforming_targets", "--count", "3", "--seed", "1",
               "-o", coarse)
    assert made.returncode == 0, made.stderr
    result = draw(coarse, fine, "--rounds", "4")
    assert result.returncode == 0, result.stderr
    keyframes = 0
    for path in sorted(coarse.glob("*.json")):
        before = json.loads(path.read_text())
        after = json.loads((fine / path.name).read_text())
        assert after["description"].startswith("finely drawn (4 rounds of corner cutting): ")
        assert after["boundary"] == before["boundary"]
        for kind in ("targets", "obstacles"):
            for old, new in zip(before[kind], after[kind]):
                assert vertices(new["shape"]) == 16 * vertices(old["shape"])
                for k_old, k_new in zip(old.get("deformation", {}).get("keyframes", []),
                                        new.get("deformation", {}).get("keyframes", [])):
                    assert vertices(k_new["shape"]) == vertices(new["shape"])
                    keyframes += 1
        checked = cli("validate", fine / path.name)
        assert checked.returncode == 0, checked.stdout + checked.stderr
    assert keyframes > 0, "the family's targets deform: their keyframes were cut too"


def test_a_folder_that_is_not_there_or_a_scene_that_is_not_one_is_refused(tmp_path):
    assert draw(tmp_path / "missing", tmp_path / "out").returncode == 2
    bad = tmp_path / "bad"
    bad.mkdir()
    (bad / "scene.json").write_text(json.dumps({"targets": [{"shape": "POINT(1 2)"}]}))
    result = draw(bad, tmp_path / "out")
    assert result.returncode == 2
    assert "not a polygon" in result.stderr
