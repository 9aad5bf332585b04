"""Every command of the how-to guides runs as shown: each ``$ govopt ...`` line of a
``console`` block is run (in one folder per guide, in order, so that a file one writes is
there for the next), and every other line of the block up to the next command, but ``...``,
is a line of what it printed."""

import shlex
from pathlib import Path

import pytest
from clirun import invoke

DOCS = Path(__file__).resolve().parent.parent / "docs" / "how-to"


def _commands(text: str) -> list[tuple[str, list[str]]]:
    """``(command, lines shown after it)`` of every console block."""
    out, block = [], False
    for line in text.splitlines():
        if line.startswith("```"):
            block = line.strip() == "```console"
            continue
        if not block:
            continue
        if line.startswith("$ "):
            out.append((line[2:], []))
        elif out and line != "...":
            out[-1][1].append(line)
    return out


#: the guides written as console sessions (studies.md runs in tests/test_study_docs.py)
GUIDES = [p for p in sorted(DOCS.glob("*.md")) if "```console" in p.read_text(encoding="utf-8")]


@pytest.mark.parametrize("guide", GUIDES, ids=lambda p: p.name)
def test_every_command_of_the_guide_runs_as_shown(guide, tmp_path):
    commands = _commands(guide.read_text(encoding="utf-8"))
    assert commands, f"{guide.name}: no commands"
    for command, shown in commands:
        words = shlex.split(command)
        assert words[0] == "govopt", command
        result = invoke(words[1:], cwd=tmp_path)
        assert result.exit_code in (0, 1), (command, result.output)
        printed = result.stdout.splitlines()
        for line in shown:
            assert line in printed, (command, line)
