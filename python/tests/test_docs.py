# docs/python.md's Python blocks, run in order in a fresh directory: the
# walk-through must work as written.
import re

from conftest import SOURCE_DIR


def test_the_walk_through_runs(tmp_path, capsys, monkeypatch):
    text = (SOURCE_DIR / "docs" / "python.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert len(blocks) >= 6
    monkeypatch.chdir(tmp_path)
    names = {}
    for block in blocks:
        exec(compile(block, "docs/python.md", "exec"), names)
    assert (tmp_path / "figure1.png").stat().st_size > 1000
    assert (tmp_path / "figure1.exr").stat().st_size > 1000
    printed = capsys.readouterr().out
    assert "['blobs', 'floor']" in printed
    assert "<expression> 2 2 expected an expression" in printed
