"""The pages generated from the code are what it gives today: the commands (from the typer
app), the bibliography (govopt/references.py), each governor type's method on its theory
page (`python tools/doc_pages.py` regenerates them) and the validation tables
(`python tools/validation_docs.py docs/validation.md`)."""

import re
import sys
from pathlib import Path

from govopt.references import REFERENCES

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"
sys.path.insert(0, str(ROOT / "tools"))  # the docs' generators: developer tools, not govopt's

import doc_pages  # noqa: E402


def test_the_generated_pages_are_current():
    assert doc_pages.stale(DOCS) == [], "stale: run python tools/doc_pages.py"


def test_the_commands_page_names_every_command_and_option():
    page = (DOCS / "reference" / "commands.md").read_text(encoding="utf-8")
    for path in ("govopt evaluate", "govopt design", "govopt spring design",
                 "govopt spring check", "govopt study run", "govopt study show",
                 "govopt study export", "govopt init", "govopt examples", "govopt bench"):
        assert f"## {path}\n" in page or f"### {path}\n" in page, path
    assert "`--sweep <str>`" in page and "`--xlsx <path>`" in page


def test_every_cited_key_is_in_the_bibliography_and_every_theory_page_links_it():
    page = (DOCS / "references.md").read_text(encoding="utf-8")
    for key in REFERENCES:
        assert f'<a id="{key}"></a>' in page, key
    for t in doc_pages.theory_types():
        theory = (DOCS / "theory" / f"{t}.md").read_text(encoding="utf-8")
        assert doc_pages.BEGIN in theory and doc_pages.END in theory
        for link in set(re.findall(r"\(\.\./references\.md#([\w-]+)\)", theory)):
            assert link in REFERENCES, (t, link)


def test_the_validation_page_is_what_the_code_gives_today():
    from validation_docs import page

    assert (DOCS / "validation.md").read_text(encoding="utf-8") == page(), (
        "stale: run python tools/validation_docs.py docs/validation.md")
