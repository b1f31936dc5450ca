"""The README's Python example runs as printed (with the published scenes where they are)."""
import re

from conftest import REPO


def test_the_readme_example_runs(published, tmp_path, monkeypatch, capsys):
    readme = (REPO / "README.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", readme, re.S)
    assert len(blocks) == 1 and len(blocks[0].splitlines()) <= 15
    code = blocks[0].replace('"../shared/coverage_scenes/dynamic9.json"',
                             repr(published("dynamic9")))
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "README.md", "exec"), {})
    assert (tmp_path / "results" / "dynamic9-spin-seed1.json").exists()
    assert "coverage" in capsys.readouterr().out
