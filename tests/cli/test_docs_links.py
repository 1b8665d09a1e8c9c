"""Every relative link of the README and of docs/ leads to a file of the repository, and a link to a heading
(`page.md#heading`) to a heading of that page (GitHub's anchors: lower case, punctuation dropped, spaces to -).
Links in code blocks and to other sites are not links of the documentation and are left alone."""
import re
from pathlib import Path

import pytest

SOURCE = Path(__file__).resolve().parents[2]
PAGES = [SOURCE / "README.md", *sorted((SOURCE / "docs").glob("**/*.md"))]
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")


def prose(text):
    """The Markdown text without its fenced code blocks."""
    return re.sub(r"```.*?```", "", text, flags=re.S)


def anchors(page):
    """GitHub's anchor of each heading of a Markdown page."""
    headings = re.findall(r"^#+\s+(.*)$", prose(page.read_text(encoding="utf-8")), re.M)
    return {re.sub(r"[^\w\- ]", "", h.strip().lower()).replace(" ", "-") for h in headings}


def relative_links(page):
    for match in LINK.finditer(prose(page.read_text(encoding="utf-8"))):
        target = match.group(1)
        if not re.match(r"[a-z][a-z0-9+.-]*:", target):
            yield target


def test_the_docs_have_links():
    assert sum(1 for page in PAGES for _ in relative_links(page)) >= 100


@pytest.mark.parametrize("page", PAGES, ids=[str(p.relative_to(SOURCE)) for p in PAGES])
def test_every_relative_link_resolves(page):
    broken = []
    for target in relative_links(page):
        path, _, fragment = target.partition("#")
        dest = (page.parent / path).resolve() if path else page
        if not dest.exists():
            broken.append(f"{target}: no such file")
        elif fragment and dest.suffix == ".md" and fragment not in anchors(dest):
            broken.append(f"{target}: no heading with that anchor")
    assert not broken, f"{page.relative_to(SOURCE)}: " + "; ".join(broken)
