"""The examples of README.md and docs/**/*.md, as the tests run them and as one command updates
their stored outputs.

A page's fenced blocks run in order, in one folder (a file one command writes is there for the
next), with one namespace for its Python:

* ``console``: every ``$ govopt ...`` line runs (in this process, :func:`clirun.invoke`); the
  lines after it up to the next ``$`` are what it printed (stdout and stderr as a terminal shows
  them). The lines before the first ``...`` are the first lines printed, in order; each line
  after a ``...`` is printed later, in order. The exit code is 0 or 1 (a check failing), or the
  one a trailing comment states (``$ govopt ... # exit 2``);
* ``sh``, ``bash``: every ``govopt`` line runs (a ``\\`` continues a line; ``#`` starts a
  comment) with exit code 0 or 1 (a ``--dask`` line where Dask is installed); a ``sqlite3``
  line runs where the sqlite3 shell is installed; other lines (installing, making a venv) are
  the reader's to run;
* ``python``: executed;
* ``sql`` with DuckDB's ``sqlite_scan``: run where DuckDB is installed.

``python tests/docexamples.py --update [PAGE ...]`` runs the pages' console blocks and rewrites
the lines shown after each command from what it prints now (the first lines stay the first
lines, each later line is replaced by the printed line that starts alike), so that a change of
output is one command and a reviewed diff.
"""

from __future__ import annotations

import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(Path(__file__).resolve().parent))

from clirun import invoke  # noqa: E402


def pages() -> list[Path]:
    """README.md and every page under docs/."""
    return [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]


@dataclass
class Block:
    lang: str
    lines: list[str]
    start: int  # the line number (0-based) of the block's first line after the fence


@dataclass
class Command:
    words: list[str]
    shown: list[str] = field(default_factory=list)
    exit_code: int | None = None
    at: int = 0  # the line number of the command in the page
    shown_at: list[int] = field(default_factory=list)


def blocks(text: str) -> list[Block]:
    """The fenced blocks of a Markdown text."""
    out, lang, lines, start = [], None, [], 0
    for i, line in enumerate(text.splitlines()):
        if line.startswith("```"):
            if lang is None:
                lang, lines, start = line[3:].strip(), [], i + 1
            else:
                out.append(Block(lang, lines, start))
                lang = None
        elif lang is not None:
            lines.append(line)
    return out


def console_commands(block: Block) -> list[Command]:
    """The ``$ govopt ...`` commands of a console block with the lines shown after each."""
    out: list[Command] = []
    for i, line in enumerate(block.lines):
        if line.startswith("$ "):
            text = line[2:]
            code = re.search(r"#\s*exit\s+(\d+)\s*$", text)
            out.append(Command(shlex.split(text, comments=True),
                               exit_code=int(code.group(1)) if code else None,
                               at=block.start + i))
        elif out:
            out[-1].shown.append(line)
            out[-1].shown_at.append(block.start + i)
    return out


def shell_lines(block: Block) -> list[list[str]]:
    """The command lines of an sh block as words, continuation lines joined."""
    out, pending = [], ""
    for line in block.lines:
        if line.rstrip().endswith("\\"):
            pending += line.rstrip()[:-1] + " "
            continue
        words = shlex.split(pending + line, comments=True)
        pending = ""
        if words:
            out.append(words)
    return out


def matches(shown: list[str], printed: list[str]) -> str | None:
    """None when ``printed`` shows ``shown`` (see the module's docstring), else what differs."""
    if "..." in shown:
        head, rest = shown[:shown.index("...")], shown[shown.index("..."):]
    else:
        head, rest = shown, []
    if printed[:len(head)] != head:
        for k, line in enumerate(head):
            got = printed[k] if k < len(printed) else "<nothing>"
            if got != line:
                return f"line {k + 1}: shown {line!r}, printed {got!r}"
    at = len(head)
    for line in rest:
        if line == "...":
            continue
        try:
            at = printed.index(line, at) + 1
        except ValueError:
            return f"not printed (after line {at}): {line!r}"
    return None


def printed_lines(run, folder: Path) -> list[str]:
    """What a terminal shows of a run, the folder's path written as ``./``."""
    return run.output.replace(f"{folder}{os.sep}", "").splitlines()


def run_page(page: Path, folder: Path, update: bool = False) -> list[str]:
    """Run every example of ``page`` in ``folder``; the failures, each one line. With
    ``update``, rewrite the console blocks' shown lines from what the commands print now."""
    text = page.read_text(encoding="utf-8")
    lines = text.splitlines()
    failures, namespace, edits = [], {"__name__": "__docs__"}, {}
    here = os.getcwd()
    for block in blocks(text):
        where = f"{page.relative_to(ROOT)}:{block.start}"
        if block.lang == "console":
            for cmd in console_commands(block):
                if not cmd.words or cmd.words[0] != "govopt":
                    failures.append(f"{where}: not a govopt command: {cmd.words}")
                    continue
                run = invoke(cmd.words[1:], cwd=folder)
                expected = (0, 1) if cmd.exit_code is None else (cmd.exit_code,)
                if run.exit_code not in expected or run.exception is not None:
                    failures.append(f"{page.name}:{cmd.at + 1}: {shlex.join(cmd.words)}: exit "
                                    f"{run.exit_code}: {run.output[-500:]}")
                    continue
                printed = printed_lines(run, folder)
                if update:
                    edits.update(_updated(cmd, printed))
                    continue
                why = matches(cmd.shown, printed)
                if why:
                    failures.append(f"{page.name}:{cmd.at + 1}: {shlex.join(cmd.words)}: {why}")
        elif block.lang in ("sh", "bash"):
            for words in shell_lines(block):
                if words[0] == "govopt" and not ("--dask" in words and not _has("distributed")):
                    run = invoke(words[1:], cwd=folder)
                    if run.exit_code not in (0, 1) or run.exception is not None:
                        failures.append(f"{where}: {shlex.join(words)}: exit {run.exit_code}: "
                                        f"{run.output[-500:]}")
                elif words[0] == "sqlite3" and shutil.which("sqlite3"):
                    p = subprocess.run(words, cwd=folder, capture_output=True, text=True)
                    if p.returncode:
                        failures.append(f"{where}: {shlex.join(words)}: {p.stderr}")
        elif block.lang == "python":
            os.chdir(folder)
            try:
                exec(compile("\n".join(block.lines), f"{page.name}:{block.start}", "exec"),
                     namespace)
            except Exception as exc:  # a failing example is a failure, with its line
                failures.append(f"{where}: python: {type(exc).__name__}: {exc}")
            finally:
                os.chdir(here)
        elif block.lang == "sql" and "sqlite_scan" in "\n".join(block.lines):
            _duckdb("\n".join(block.lines), folder, failures, where)
    if update and edits:
        new = [edits.get(i, line) for i, line in enumerate(lines)]
        page.write_text("\n".join(new) + "\n", encoding="utf-8")
    return failures


def _updated(cmd: Command, printed: list[str]) -> dict[int, str]:
    """The page's lines to rewrite for ``cmd`` (line number -> new text)."""
    edits: dict[int, str] = {}
    shown, at = cmd.shown, cmd.shown_at
    n_head = shown.index("...") if "..." in shown else len(shown)
    for k in range(n_head):
        edits[at[k]] = printed[k] if k < len(printed) else ""
    pos = n_head
    for k in range(n_head, len(shown)):
        line = shown[k]
        if line == "...":
            continue
        if line in printed[pos:]:
            pos = printed.index(line, pos) + 1
            continue
        best = max(printed[pos:], key=lambda p: len(os.path.commonprefix([p, line])),
                   default=None)
        if best is not None and len(os.path.commonprefix([best, line])) >= 8:
            edits[at[k]] = best
            pos = printed.index(best, pos) + 1
    return edits


def _has(module: str) -> bool:
    """Whether ``module`` imports (an optional dependency a line needs: Dask's cluster)."""
    import importlib.util

    return importlib.util.find_spec(module) is not None


def _duckdb(sql: str, folder: Path, failures: list[str], where: str) -> None:
    try:
        import duckdb
    except ImportError:  # not a dependency: run where it is installed
        return
    con = duckdb.connect()
    try:
        for statement in filter(str.strip, sql.split(";")):
            con.execute(re.sub(r"'(\w+\.db)'", lambda m: repr(str(folder / m.group(1))),
                               statement))
    except Exception as exc:
        failures.append(f"{where}: duckdb: {exc}")


def main(argv: list[str]) -> int:
    update = "--update" in argv
    chosen = [Path(a).resolve() for a in argv if not a.startswith("--")] or pages()
    bad = 0
    for page in chosen:
        with tempfile.TemporaryDirectory() as folder:
            failures = run_page(page, Path(folder), update=update)
        for f in failures:
            print(f)
        bad += len(failures)
        print(f"{'updated' if update else 'ran'} {page.relative_to(ROOT)}")
    return 1 if bad else 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
