"""The study how-to and the database's reference run as written: every command of their
``sh`` blocks (govopt in this process, the sqlite3 shell), their Python, and DuckDB's query
where DuckDB is installed, in one folder, in order; the reference's schema is the store's."""

import shlex
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
HOWTO = ROOT / "docs" / "how-to" / "studies.md"
REFERENCE = ROOT / "docs" / "reference" / "study-database.md"


def blocks(path: Path) -> list[tuple[str, str]]:
    """The fenced blocks of a Markdown file: ``(language, text)``."""
    out, lang, lines = [], None, []
    for line in path.read_text(encoding="utf-8").splitlines():
        if line.startswith("```"):
            if lang is None:
                lang, lines = line[3:].strip(), []
            else:
                out.append((lang, "\n".join(lines)))
                lang = None
        elif lang is not None:
            lines.append(line)
    return out


def test_the_reference_schema_is_the_stores():
    from govopt.study import FORMAT_VERSION
    from govopt.study.store import SCHEMA

    text = REFERENCE.read_text(encoding="utf-8")
    sql = next(b for lang, b in blocks(REFERENCE) if lang == "sql" and "CREATE TABLE" in b)
    assert sql.splitlines() == list(SCHEMA)
    assert f"format version {FORMAT_VERSION}" in text


def test_the_studies_how_to_and_reference_run(tmp_path):
    from clirun import invoke

    ran = []
    for path in (HOWTO, REFERENCE):
        for lang, text in blocks(path):
            if lang == "sh":
                for line in text.splitlines():
                    words = shlex.split(line)
                    if words[0] == "govopt":
                        r = invoke(words[1:], cwd=tmp_path)
                        assert r.exit_code == 0, (line, r.output)
                    elif words[0] == "sqlite3" and shutil.which("sqlite3"):
                        subprocess.run(words, cwd=tmp_path, check=True, capture_output=True)
                    ran.append(words[0])
            elif lang == "python":
                with pytest.MonkeyPatch.context() as mp:
                    mp.chdir(tmp_path)
                    exec(compile(text, str(path), "exec"), {})
                ran.append("python")
            elif lang == "sql" and "sqlite_scan" in text:
                duckdb = _duckdb()  # not a dependency: run where it is installed
                if duckdb is not None:
                    con = duckdb.connect()
                    for statement in filter(str.strip, text.split(";")):
                        con.execute(statement.replace("'weights.db'",
                                                      repr(str(tmp_path / "weights.db"))))
                    ran.append("duckdb")
    assert ran.count("govopt") >= 12 and "python" in ran
    assert not list(tmp_path.glob("*-wal")) and not list(tmp_path.glob("*-shm"))


def _duckdb():
    try:
        import duckdb
    except ImportError:
        return None
    return duckdb
