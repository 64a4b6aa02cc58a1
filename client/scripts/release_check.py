"""What a release publishes, checked before it is published (the release workflow, and make test).

    python client/scripts/release_check.py [--tag v0.2.0] [--vsix cncmacro.vsix] [--dist DIR] [--notes FILE]

- The version: ``package.json`` (the extension), ``pyproject.toml`` (the Python package) and
  ``cncmacro.__version__`` carry the same one, ``CHANGELOG.md`` has a dated section for it
  (``## 0.2.0 - 2026-11-28``), and a tag, when given, names it (``v0.2.0``).
- ``--vsix``: the built extension carries that version and publisher, in its manifest and in its
  ``package.json``, and its README (``client/scripts/vsix-readme.mjs``'s) holds its pictures as
  data: URIs, the only pictures VS Code's extension page shows offline, and links only to
  addresses the page can open.
- ``--dist``: the Python package is built into DIR (an sdist and a wheel, from the set-up's
  packages only: no network) and ``twine check`` accepts both, as PyPI will; the wheel holds the
  package and its ``cncmacro`` command.
- ``--notes``: that version's changelog section is written to FILE, the release's notes.

Exit status 0 when everything holds; 1 with each problem on its own line.
"""

from __future__ import annotations

import argparse
import json
import re
import subprocess
import sys
import zipfile
from pathlib import Path
from xml.etree import ElementTree

ROOT = Path(__file__).resolve().parents[2]
DATED = re.compile(r"^## (?P<version>\d+\.\d+\.\d+\S*) - (?P<date>\d{4}-\d{2}-\d{2})\s*$", re.M)
LINK = re.compile(r"!?\[[^\]]*\]\((?P<target>[^)\s#]+)(?:#[^)\s]*)?\)")  # not a link to #a-heading
MANIFEST_NS = {"m": "http://schemas.microsoft.com/developer/vsx-schema/2011"}


def versions() -> tuple[str, str, str, str]:
    """The extension's version, its publisher, the Python package's version and the one the
    package says it is (``cncmacro.__version__``, which ``--version`` prints)."""
    manifest = json.loads((ROOT / "package.json").read_text(encoding="utf-8"))
    project = re.search(r'(?m)^version = "([^"]+)"', (ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    said = re.search(
        r'(?m)^__version__ = "([^"]+)"', (ROOT / "server/cncmacro/__init__.py").read_text(encoding="utf-8")
    )
    return (
        manifest["version"],
        manifest["publisher"],
        project.group(1) if project else "?",
        said.group(1) if said else "?",
    )


def changelog_section(version: str) -> str | None:
    """The text of ``version``'s dated section of CHANGELOG.md, None when it has none."""
    text = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    heads = list(re.finditer(r"^## .*$", text, re.M))
    for k, head in enumerate(heads):
        m = DATED.match(head.group(0))
        if m and m.group("version") == version:
            end = heads[k + 1].start() if k + 1 < len(heads) else len(text)
            return text[head.end() : end].strip() + "\n"
    return None


def check_vsix(path: Path, version: str, publisher: str) -> list[str]:
    problems: list[str] = []
    if not path.is_file():
        return [f"{path}: no such .vsix (make package builds it)"]
    with zipfile.ZipFile(path) as z:
        names = set(z.namelist())
        identity = ElementTree.fromstring(z.read("extension.vsixmanifest")).find(".//m:Identity", MANIFEST_NS)
        if identity is None:
            return [f"{path}: its extension.vsixmanifest has no Identity"]
        if identity.get("Version") != version:
            problems.append(f"{path}: the manifest says version {identity.get('Version')}, package.json {version}")
        if identity.get("Publisher") != publisher:
            problems.append(
                f"{path}: the manifest says publisher {identity.get('Publisher')}, package.json {publisher}"
            )
        inner = json.loads(z.read("extension/package.json"))
        if inner.get("version") != version:
            problems.append(f"{path}: its package.json says version {inner.get('version')}, not {version}")
        readme = next((n for n in names if n.lower() == "extension/readme.md"), None)
        if readme is None:
            return [*problems, f"{path}: no README"]
        for m in LINK.finditer(z.read(readme).decode("utf-8")):
            target, picture = m.group("target"), m.group(0).startswith("!")
            if picture and not target.startswith("data:image/"):
                problems.append(f"{path}: its README's picture {target[:80]} is not inside it (a data: URI)")
            elif not picture and "://" not in target and not target.startswith("mailto:"):
                problems.append(f"{path}: its README links to {target}, which its page cannot open")
    return problems


def check_dist(out: Path, version: str) -> list[str]:
    out.mkdir(parents=True, exist_ok=True)
    for old in out.glob("cncmacro-*"):
        old.unlink()
    built = subprocess.run([sys.executable, "-m", "build", "--no-isolation", "--outdir", str(out), str(ROOT)],
                           capture_output=True, text=True)  # fmt: skip
    if built.returncode != 0:
        return [f"python -m build failed:\n{built.stdout[-2000:]}{built.stderr[-2000:]}"]
    files = sorted(out.glob("cncmacro-*"))
    problems = []
    wheels = [f for f in files if f.name == f"cncmacro-{version}-py3-none-any.whl"]
    sdists = [f for f in files if f.name == f"cncmacro-{version}.tar.gz"]
    if not wheels or not sdists:
        problems.append(f"{out}: expected the wheel and the sdist of {version}, found {[f.name for f in files]}")
    for wheel in wheels:
        with zipfile.ZipFile(wheel) as z:
            names = set(z.namelist())
            points = z.read(f"cncmacro-{version}.dist-info/entry_points.txt").decode("utf-8")
        if "cncmacro/__init__.py" not in names or "cncmacro/syntax/block.lark" not in names:
            problems.append(f"{wheel.name}: the package or its grammar is missing")
        if "cncmacro = cncmacro.cli.main:main" not in points:
            problems.append(f"{wheel.name}: no cncmacro command among its entry points")
    twine = subprocess.run([sys.executable, "-m", "twine", "check", "--strict", *map(str, files)],
                           capture_output=True, text=True)  # fmt: skip
    if twine.returncode != 0:
        problems.append(f"twine check failed:\n{twine.stdout}{twine.stderr}")
    return problems


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tag", help="the tag being released, v<version>")
    ap.add_argument("--vsix", type=Path, help="the built extension")
    ap.add_argument("--dist", type=Path, help="build the Python package into this folder and check it")
    ap.add_argument("--notes", type=Path, help="write the version's changelog section here")
    args = ap.parse_args(argv)
    version, publisher, python_version, said = versions()
    problems: list[str] = []
    if python_version != version or said != version:
        problems.append(
            f"package.json says {version}, pyproject.toml {python_version}, cncmacro.__version__ {said}: "
            "one version for all three"
        )
    if args.tag is not None and args.tag != f"v{version}":
        problems.append(f"the tag {args.tag} is not v{version}, the version package.json and pyproject.toml carry")
    section = changelog_section(version)
    if section is None:
        problems.append(f"CHANGELOG.md has no dated section for {version} (## {version} - YYYY-MM-DD)")
    elif args.notes is not None:
        args.notes.write_text(section, encoding="utf-8")
    if args.vsix is not None:
        problems += check_vsix(args.vsix, version, publisher)
    if args.dist is not None:
        problems += check_dist(args.dist, version)
    for p in problems:
        print(f"release check: {p}", file=sys.stderr)
    if not problems:
        print(f"release check: {version} is ready to publish")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
