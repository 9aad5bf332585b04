"""Every example of README.md and docs/ runs as shown: each page's fenced ``govopt`` commands
(console blocks with their printed lines compared, sh blocks by exit code), its Python and its
shell's sqlite3 lines, in one folder per page, in order (tests/docexamples.py says how each kind
of block is read). After a change of output, ``python tests/docexamples.py --update`` rewrites
the shown lines; review the diff."""

import pytest
from docexamples import ROOT, blocks, pages, run_page

RUN = ("console", "sh", "bash", "python")
PAGES = [p for p in pages() if any(b.lang in RUN for b in blocks(p.read_text(encoding="utf-8")))]


@pytest.mark.parametrize("page", PAGES, ids=lambda p: str(p.relative_to(ROOT)))
def test_every_example_of_the_page_runs_as_shown(page, tmp_path):
    failures = run_page(page, tmp_path)
    assert not failures, "\n".join(failures)
    assert not list(tmp_path.glob("*-wal")) and not list(tmp_path.glob("*-shm"))


def test_the_examples_cover_the_readme_and_the_guides():
    names = {str(p.relative_to(ROOT)) for p in PAGES}
    assert {"README.md", "docs/tutorial.md", "docs/how-to/spring.md",
            "docs/how-to/studies.md"} <= names
