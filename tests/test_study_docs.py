"""The study database's reference states the store's schema and format version (its examples
run in tests/test_docs_examples.py, with every other page's)."""

from pathlib import Path

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
