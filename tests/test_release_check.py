"""The check a release runs before it publishes (client/scripts/release_check.py; make test runs it
on the real .vsix and Python package): a tag that is not the version, a .vsix of another version
or whose page could not show its pictures offline, are refused with the reason;
the release's notes are the version's changelog section."""

from __future__ import annotations

import json
import subprocess
import sys
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SCRIPT = ROOT / "client" / "scripts" / "release_check.py"
VERSION = json.loads((ROOT / "package.json").read_text(encoding="utf-8"))["version"]


def check(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, str(SCRIPT), *args], capture_output=True, text=True, timeout=120)


def test_a_tag_that_is_not_the_version_is_refused_naming_both() -> None:
    done = check("--tag", "v9.9.9")
    assert done.returncode == 1
    assert f"the tag v9.9.9 is not v{VERSION}" in done.stderr


def test_the_tag_of_the_version_passes_and_its_notes_are_its_changelog_section(tmp_path: Path) -> None:
    notes = tmp_path / "notes.md"
    done = check("--tag", f"v{VERSION}", "--notes", str(notes))
    assert done.returncode == 0, done.stderr
    changelog = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    head = next(line for line in changelog.splitlines() if line.startswith(f"## {VERSION} - "))
    section = changelog.split(head + "\n", 1)[1].split("\n## ", 1)[0].strip()
    assert notes.read_text(encoding="utf-8").strip() == section
    assert "\n## " not in notes.read_text(encoding="utf-8")  # no other version's section


def _vsix(path: Path, version: str, readme: str, files: dict[str, str]) -> Path:
    manifest = ('<?xml version="1.0" encoding="utf-8"?><PackageManifest Version="2.0.0" '
                'xmlns="http://schemas.microsoft.com/developer/vsx-schema/2011"><Metadata>'
                f'<Identity Language="en-US" Id="cncmacro" Version="{version}" Publisher="cncmacro" />'
                "</Metadata></PackageManifest>")  # fmt: skip
    with zipfile.ZipFile(path, "w") as z:
        z.writestr("extension.vsixmanifest", manifest)
        z.writestr("extension/package.json", json.dumps({"version": version, "publisher": "cncmacro"}))
        z.writestr("extension/readme.md", readme)
        for name, text in files.items():
            z.writestr(f"extension/{name}", text)
    return path


def test_a_vsix_of_another_version_is_refused(tmp_path: Path) -> None:
    done = check("--vsix", str(_vsix(tmp_path / "old.vsix", "0.0.1", "# cncmacro\n", {})))
    assert done.returncode == 1
    assert f"the manifest says version 0.0.1, package.json {VERSION}" in done.stderr
    assert f"its package.json says version 0.0.1, not {VERSION}" in done.stderr


def test_a_vsix_whose_page_cannot_show_a_picture_or_open_a_link_offline_is_refused(tmp_path: Path) -> None:
    # VS Code's extension page shows pictures from https: or data: only (the package's files are
    # out of its reach) and opens only http(s) links: offline, a picture must be inside the README
    readme = ("![inline](data:image/png;base64,iVBORw0KGgo=)\n"
              "![online](https://github.com/cncmacro/cncmacro/raw/HEAD/docs/images/problems.png)\n"
              "![in the package](docs/images/toolpath.png)\n"
              "See [the CLI](https://github.com/cncmacro/cncmacro/blob/HEAD/docs/cli.md#check), "
              "[the machine file](docs/machine-file.md) and [below](#limits).\n")  # fmt: skip
    done = check("--vsix", str(_vsix(tmp_path / "page.vsix", VERSION, readme, {"docs/images/toolpath.png": "png"})))
    assert done.returncode == 1
    problems = [line for line in done.stderr.splitlines() if "README" in line]
    assert len(problems) == 3, done.stderr  # the inline picture, the absolute link and the anchor pass
    assert "picture https://github.com/cncmacro/cncmacro/raw/HEAD/docs/images/problems.png is not inside" in problems[0]
    assert "picture docs/images/toolpath.png is not inside it" in problems[1]
    assert "links to docs/machine-file.md, which its page cannot open" in problems[2]
