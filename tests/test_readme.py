"""The README's promises: the two commands head it, .ci/run runs the second, snippets run."""

from __future__ import annotations

import re
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
README = (REPO / "README.md").read_text(encoding="utf-8")


def test_readme_opens_with_the_two_commands():
    first_block = re.search(r"```bash\n(.*?)```", README, re.S).group(1).strip().splitlines()
    assert len(first_block) == 2
    assert "conrod run examples/" in first_block[0]
    assert (REPO / first_block[0].split("conrod run ")[1].split()[0]).exists()
    assert "pytest" in first_block[1]


def test_ci_runs_exactly_the_readme_test_command():
    test_command = re.search(r"```bash\n.*?\n(.*?)\n```", README, re.S).group(1).strip()
    assert test_command in (REPO / ".ci" / "run").read_text(encoding="utf-8")


def test_python_snippets_run(monkeypatch):
    monkeypatch.chdir(REPO)
    for block in re.findall(r"```python\n(.*?)```", README, re.S):
        exec(compile(block, "README.md", "exec"), {})
