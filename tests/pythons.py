"""The Python interpreters on this machine that cncmacro supports (3.10 and newer), for the tests
that must prove it runs on the oldest and the newest of them.

Looked for: ``pyenv``'s versions (``$PYENV_ROOT`` or ``~/.pyenv``), ``python3.N`` on the PATH, and
``python3`` itself. Each candidate is asked for its version; one interpreter found in two places
counts once. ``python tests/pythons.py`` prints the oldest and the newest as JSON, for the editor
tests (Node) to use.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

OLDEST_SUPPORTED = (3, 10)
_PROBE = "import sys; print(*sys.version_info[:3], sys.executable)"


@dataclass(frozen=True)
class Interpreter:
    """One Python: its version and the executable that starts it."""

    version: tuple[int, int, int]
    executable: str

    @property
    def name(self) -> str:
        return "Python " + ".".join(map(str, self.version))


def _candidates() -> list[str]:
    found: list[str] = []
    root = os.environ.get("PYENV_ROOT") or str(Path.home() / ".pyenv")
    versions = Path(root) / "versions"
    if versions.is_dir():
        found += [str(p / "bin" / "python3") for p in sorted(versions.iterdir()) if (p / "bin" / "python3").exists()]
    for minor in range(OLDEST_SUPPORTED[1], 30):
        path = shutil.which(f"python3.{minor}")
        if path:
            found.append(path)
    for name in ("python3", "python"):
        path = shutil.which(name)
        if path:
            found.append(path)
    return found


def _probe(command: str) -> Interpreter | None:
    try:
        out = subprocess.run([command, "-c", _PROBE], capture_output=True, text=True, timeout=30, check=False)
    except (OSError, subprocess.SubprocessError):
        return None
    parts = out.stdout.split(maxsplit=3)
    if out.returncode != 0 or len(parts) != 4:
        return None
    return Interpreter((int(parts[0]), int(parts[1]), int(parts[2])), parts[3].strip())


def supported_interpreters() -> list[Interpreter]:
    """Every supported interpreter found, oldest first, one per version."""
    by_version: dict[tuple[int, int, int], Interpreter] = {}
    for command in _candidates():
        found = _probe(command)
        if found is not None and found.version[:2] >= OLDEST_SUPPORTED:
            by_version.setdefault(found.version, found)
    return [by_version[v] for v in sorted(by_version)]


def oldest_and_newest() -> list[Interpreter]:
    """The oldest and the newest supported interpreter (one when only one version is here)."""
    found = supported_interpreters()
    return [] if not found else sorted({found[0], found[-1]}, key=lambda i: i.version)


def main() -> None:
    found = oldest_and_newest()
    print(json.dumps([{"version": ".".join(map(str, i.version)), "executable": i.executable} for i in found]))


if __name__ == "__main__":
    sys.exit(main())
