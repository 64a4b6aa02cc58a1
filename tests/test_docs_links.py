"""Every relative link of the README, the changelog and docs/*.md leads somewhere: the file it
names exists in the repository, and a ``#section`` names a heading of that file (as GitHub
makes the anchor of a heading). A reader who follows a link from the README into the reference
pages, or from one page to another, never lands on nothing."""

from __future__ import annotations

import re
from pathlib import Path
from urllib.parse import unquote

import pytest

ROOT = Path(__file__).resolve().parents[1]
PAGES = [ROOT / "README.md", ROOT / "CHANGELOG.md", ROOT / "examples" / "README.md", *sorted(ROOT.glob("docs/*.md"))]

_FENCE = re.compile(r"^\s*(```|~~~)")
_CODE_SPAN = re.compile(r"`[^`]*`")
_LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
_HEADING = re.compile(r"^#{1,6}\s+(.*?)\s*#*\s*$")


def _prose(text: str) -> list[str]:
    """The lines of a Markdown text outside fenced code blocks, with code spans taken out."""
    lines, fenced = [], False
    for line in text.splitlines():
        if _FENCE.match(line):
            fenced = not fenced
            continue
        if not fenced:
            lines.append(_CODE_SPAN.sub("", line))
    return lines


def anchors(text: str) -> set[str]:
    """The anchors GitHub gives the headings of a Markdown text: lower case, punctuation but
    ``-`` and ``_`` dropped, spaces made ``-``, a repeated one numbered ``-1``, ``-2``, ..."""
    seen: dict[str, int] = {}
    out = set()
    fenced = False
    for line in text.splitlines():
        if _FENCE.match(line):
            fenced = not fenced
            continue
        heading = None if fenced else _HEADING.match(line)
        if heading is None:
            continue
        slug = re.sub(r"[^\w\- ]", "", heading.group(1).replace("`", "").lower()).replace(" ", "-")
        count = seen.get(slug, 0)
        seen[slug] = count + 1
        out.add(slug if count == 0 else f"{slug}-{count}")
    return out


def relative_links(page: Path) -> list[str]:
    """The link and image targets of a page that point into the repository."""
    found = []
    for line in _prose(page.read_text(encoding="utf-8")):
        for target in _LINK.findall(line):
            if not re.match(r"[a-z][a-z0-9+.-]*:", target, re.I):
                found.append(target)
    return found


def test_the_anchors_are_githubs() -> None:
    text = (
        "# Debugging: `cncmacro dap`\n## The machine file (`.cncmacro.toml`)\n"
        "```\n# not a heading\n```\n## Speed\n## Speed\n"
    )
    assert anchors(text) == {"debugging-cncmacro-dap", "the-machine-file-cncmacrotoml", "speed", "speed-1"}


def test_the_readme_links_the_reference_pages() -> None:
    linked = {Path(t.split("#")[0]).as_posix() for t in relative_links(ROOT / "README.md")}
    for page in ("cli", "machine-file", "debugging", "robustness", "benchmarks", "editor"):
        assert f"docs/{page}.md" in linked, f"the README does not link docs/{page}.md"


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.relative_to(ROOT).as_posix())
def test_every_relative_link_resolves(page: Path) -> None:
    broken = []
    for target in relative_links(page):
        path, _, anchor = unquote(target).partition("#")
        file = (page.parent / path).resolve() if path else page
        if not file.exists() or ROOT not in file.parents:
            broken.append(f"{target}: no such file")
        elif anchor and file.suffix == ".md" and anchor not in anchors(file.read_text(encoding="utf-8")):
            broken.append(f"{target}: {file.name} has no heading #{anchor}")
    assert broken == []
