"""docs/python.md's `python run` example runs as printed (with the published scenes where they
are) and shows what it says: the targets' polygons, the obstacles, and who sees what."""
import re

from conftest import REPO


def test_the_python_doc_example_runs(published, tmp_path, monkeypatch, capsys):
    doc = (REPO / "docs" / "python.md").read_text()
    blocks = re.findall(r"```python run\n(.*?)```", doc, re.S)
    assert len(blocks) == 1
    code = blocks[0].replace('"../shared/coverage_scenes/dynamic9.json"',
                             repr(published("dynamic9")))
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "docs/python.md", "exec"), {})
    out = capsys.readouterr().out
    assert "<camcov.Scene dynamic9: " in out
    assert re.search(r"^target 0: \d+ vertices, first at \[", out, re.M)
    assert re.search(r"seen by \[\d", out)
    assert "'coverage':" in out
