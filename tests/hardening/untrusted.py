"""What a folder that anybody may have filled can hold, for the tests of the command line and of the
language server (docs/design.md "Untrusted folders and files"): folders that cannot be entered, a
file name that is not UTF-8, a thousand nested folders, a 2 GB file, hostile machine files."""

from __future__ import annotations

import os
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest

from hardening.unprivileged import permissions_hold

GBK_NAME = b"\xb3\xcc\xd0\xf2.nc"  # "程序.nc" in GBK, as a Chinese Windows zip leaves it on Linux
FINDING = "O0001\n#1=#50\nM30\n"  # variable-number on line 2 (0-based 1)
DEEP = 1000

# Python 3.11's tomllib reads a 10,000-level table header, whose key is then refused; 3.10's
# tomli recurses once per level and the file is refused as nested too deeply. Clear either way.
DEEP_HEADER_SAID = "'base' must be" if sys.version_info >= (3, 11) else "nested too deeply"

# name -> (the content of .cncmacro.toml, what its error says)
HOSTILE_MACHINE_FILES: dict[str, tuple[str | bytes, str]] = {
    "nested inline tables": ("a = " + "{a = " * 10_000 + "1" + "}" * 10_000 + "\n", "nested too deeply"),
    "nested arrays": ("common = " + "[" * 10_000 + "]" * 10_000 + "\n", "nested too deeply"),
    "a table header 10,000 levels deep": ("[" + ".".join(["base"] + ["a"] * 10_000) + "]\n", DEEP_HEADER_SAID),
    "a superscript digit": ('[calls]\n"G²" = 9000\n', "'calls.G²' must be a G or M code"),
    "a superscript variable": ('[variables]\n"²" = 1\n', "'variables.²' is not a variable number"),
    "a number too big for a float": (
        "[variables]\n100 = " + "9" * 400 + "\n",
        "'variables.100' must be a finite number a variable holds (±1e+47 at most)",
    ),
    "not UTF-8": (b'base = "\xb3\xcc"\n', "not UTF-8 text (byte 0xb3 on line 1)"),
    "2 MB": ("# " + "x" * 2_000_000 + "\n", "2,000,003 bytes, over the limit of 1,000,000"),
}


@contextmanager
def shut_folders(root: Path) -> Iterator[Path]:
    """In ``root``: the program ``O0001.nc`` (with a finding), a folder ``listed`` that can be
    listed but not entered (mode 644, holding ``O0002.nc`` and a folder ``inner``) and a folder
    ``shut`` that can be neither (mode 000, holding ``O0003.nc``). Skips the test where the
    permissions cannot be made to hold (see ``unprivileged.py``); restores them after."""
    (root / "O0001.nc").write_text(FINDING, encoding="utf-8")
    listed = root / "listed"
    listed.mkdir()
    (listed / "O0002.nc").write_text("O0002\nM30\n", encoding="utf-8")
    (listed / "inner").mkdir()
    shut = root / "shut"
    shut.mkdir()
    (shut / "O0003.nc").write_text("O0003\nM30\n", encoding="utf-8")
    listed.chmod(0o644)
    shut.chmod(0o000)
    try:
        if not permissions_hold(shut):
            pytest.skip("folder permissions cannot be made to hold here")
        yield root
    finally:
        listed.chmod(0o755)
        shut.chmod(0o755)


def write_gbk_named(folder: Path, content: bytes, name: bytes = GBK_NAME) -> str:
    """A file whose name is GBK bytes; its path as the system gives it (surrogate escapes)."""
    path = os.path.join(os.fsencode(folder), name)
    with open(path, "wb") as f:
        f.write(content)
    return os.fsdecode(path)


def make_deep(root: Path, depth: int = DEEP) -> Path:
    """``depth`` nested folders ``d/d/d/...`` under ``root`` (``os.makedirs`` recurses per
    level); the deepest."""
    deep = root
    for _ in range(depth):
        deep = deep / "d"
        deep.mkdir()
    return deep


def remove_deep(top: Path) -> None:
    """Remove a deep tree of folders without recursion (``shutil.rmtree`` recurses per level)."""
    folders = [str(top)]
    for folder in folders:  # grows while it is read: every folder, the deepest last
        for entry in os.scandir(folder):
            if entry.is_dir(follow_symlinks=False):
                folders.append(entry.path)
            else:
                os.unlink(entry.path)
    for folder in reversed(folders):
        os.rmdir(folder)


def sparse_file(path: Path, size: int = 2 * 1024**3) -> None:
    """A file of ``size`` bytes that takes no disk (nothing written)."""
    with open(path, "wb") as f:
        f.truncate(size)
