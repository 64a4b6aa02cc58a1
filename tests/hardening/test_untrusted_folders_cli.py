"""``cncmacro check`` and ``cncmacro run`` on a folder that anybody may have filled (docs/design.md
"Untrusted folders and files"): a folder that cannot be entered, a file name that is not UTF-8,
a thousand nested folders, a 2 GB program file, a FIFO named like a program, a hostile machine
file. Each is named on standard error, never a traceback or a hang, and every other file is
still checked."""

from __future__ import annotations

import json
import os
import resource
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from hardening.unprivileged import command
from hardening.untrusted import (
    FINDING,
    HOSTILE_MACHINE_FILES,
    make_deep,
    remove_deep,
    shut_folders,
    sparse_file,
    write_gbk_named,
)

fifo_only = pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="needs FIFOs")


def cli(*args: str, cwd: Path | None = None, unprivileged: bool = False, memory: int | None = None,
        env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:  # fmt: skip
    """``python -m cncmacro ARGS`` (meeting file permissions even as root, with its address space
    limited to ``memory`` bytes), at most 60 s."""
    args_ = [sys.executable, "-m", "cncmacro", *args]

    def limit() -> None:
        if memory is not None:
            resource.setrlimit(resource.RLIMIT_AS, (memory, memory))

    return subprocess.run(
        command(*args_) if unprivileged else args_, capture_output=True, text=True, timeout=60, cwd=cwd,
        preexec_fn=limit, env={**os.environ, **(env or {})}, errors="strict",
    )  # fmt: skip


def assert_clean(r: subprocess.CompletedProcess[str]) -> None:
    assert "Traceback" not in r.stderr, r.stderr


@pytest.fixture
def walled(tmp_path: Path) -> Iterator[Path]:
    with shut_folders(tmp_path) as root:
        yield root


def test_folders_that_cannot_be_entered_or_listed_are_named_and_the_rest_is_checked(walled: Path) -> None:
    r = cli("check", str(walled), unprivileged=True)
    assert_clean(r)
    assert r.returncode == 2  # unreadable input
    assert r.stdout == f"{walled / 'O0001.nc'}:2:4: error: #50 does not exist on FANUC 0i Custom Macro B " \
                       "(alarm 115) [variable-number]\n"  # fmt: skip
    assert f"{walled / 'shut'}: cannot read the folder (Permission denied)" in r.stderr
    assert f"{walled / 'listed' / 'inner'}: cannot read the folder (Permission denied)" in r.stderr
    assert f"{walled / 'listed' / 'O0002.nc'}: cannot read: Permission denied" in r.stderr
    inside = walled / "shut" / "O0003.nc"
    r = cli("check", "--locale", "zh-CN", str(inside), unprivileged=True)
    assert_clean(r)
    assert (r.returncode, r.stderr) == (2, f"cncmacro：{inside}：无法读取：Permission denied\n")


@pytest.fixture
def gbk_named(tmp_path: Path) -> Path:
    folder = tmp_path / "zip"
    folder.mkdir()
    write_gbk_named(folder, b"O0001\n#1=#50\nG65 P9100\nM30\n")
    (folder / "O9100.nc").write_text("O9100\n#2=#60\nM99\n", encoding="utf-8")
    return folder


@pytest.mark.skipif(sys.platform != "linux", reason="a file name that is not UTF-8 needs a byte file system")
@pytest.mark.parametrize("fmt", ["text", "json", "sarif"])
def test_a_file_name_that_is_not_utf8_is_shown_decoded_and_every_output_is_utf8(gbk_named: Path, fmt: str) -> None:
    # a strict UTF-8 standard output, as a UTF-8 locale gives; relative paths, as CI runs it
    r = cli("check", "--format", fmt, "zip", cwd=gbk_named.parent, env={"PYTHONIOENCODING": "utf-8:strict"})
    assert_clean(r)
    assert r.returncode == 1
    r.stdout.encode("utf-8")  # valid: text=True with errors="strict" decoded it already
    if fmt == "text":
        assert r.stdout.splitlines() == [
            "zip/O9100.nc:2:4: error: #60 does not exist on FANUC 0i Custom Macro B (alarm 115) [variable-number]",
            "zip/程序.nc:2:4: error: #50 does not exist on FANUC 0i Custom Macro B (alarm 115) [variable-number]",
        ]
    elif fmt == "json":
        assert [(d["file"], d["line"]) for d in json.loads(r.stdout)] == [("zip/O9100.nc", 2), ("zip/程序.nc", 2)]
    else:
        results = json.loads(r.stdout)["runs"][0]["results"]
        uris = [res["locations"][0]["physicalLocation"]["artifactLocation"]["uri"] for res in results]
        assert uris == ["zip/O9100.nc", "zip/%B3%CC%D0%F2.nc"]  # the name's own bytes


def test_a_thousand_nested_folders_are_searched_without_recursion(tmp_path: Path) -> None:
    (tmp_path / "O0002.nc").write_text("O0002\nM30\n", encoding="utf-8")
    deep = make_deep(tmp_path)
    (deep / "O0001.nc").write_text(FINDING, encoding="utf-8")
    try:
        r = cli("check", "--format", "json", str(tmp_path))
        assert_clean(r)
        assert r.returncode == 1
        assert [(d["file"], d["code"]) for d in json.loads(r.stdout)] == [(str(deep / "O0001.nc"), "variable-number")]
    finally:
        remove_deep(tmp_path / "d")


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="a sparse file and an address-space limit")
def test_a_2_gb_program_file_in_the_folder_is_named_not_read(tmp_path: Path) -> None:
    (tmp_path / "O0001.nc").write_text(FINDING, encoding="utf-8")
    sparse_file(tmp_path / "O9100.nc")  # 2 GB that take no disk
    r = cli("check", str(tmp_path), memory=1024**3)  # reading it would need 2 GB
    assert_clean(r)
    assert r.returncode == 2
    assert "#50 does not exist" in r.stdout
    big = tmp_path / "O9100.nc"
    assert r.stderr == f"cncmacro: {big}: 2,147,483,648 bytes, over the limit of 8,000,000: not read\n"


@fifo_only
def test_a_fifo_named_like_a_program_never_blocks(tmp_path: Path) -> None:
    (tmp_path / "O0001.nc").write_text(FINDING, encoding="utf-8")
    fifo = tmp_path / "O1234.nc"
    os.mkfifo(fifo)
    r = cli("check", str(tmp_path))  # found by the search: passed over
    assert_clean(r)
    assert (r.returncode, r.stderr) == (1, "")
    r = cli("check", str(fifo))  # named: said
    assert (r.returncode, r.stderr) == (2, f"cncmacro: {fifo}: a FIFO (named pipe), not a file: not read\n")
    r = cli("run", str(fifo))
    assert_clean(r)
    assert r.returncode == 2 and "a FIFO (named pipe), not a file" in r.stderr
    os.mkfifo(tmp_path / ".cncmacro-vars.json")  # where run keeps #500-#999
    r = cli("run", str(tmp_path / "O0001.nc"))
    assert_clean(r)
    assert r.returncode == 2 and ".cncmacro-vars.json: the persistent-variable file is not a regular file" in r.stderr


@pytest.mark.parametrize("name", HOSTILE_MACHINE_FILES)
def test_a_hostile_machine_file_is_a_clear_error_of_check_and_run(tmp_path: Path, name: str) -> None:
    content, said = HOSTILE_MACHINE_FILES[name]
    machine = tmp_path / ".cncmacro.toml"
    machine.write_bytes(content if isinstance(content, bytes) else content.encode("utf-8"))
    (tmp_path / "O0001.nc").write_text(FINDING, encoding="utf-8")
    for args in (["check", str(tmp_path)], ["run", "--no-save", str(tmp_path / "O0001.nc")]):
        r = cli(*args)
        assert_clean(r)
        assert r.returncode == 2
        assert r.stderr.startswith(f"cncmacro {args[0]}: {machine}: "), r.stderr
        assert said in r.stderr


@fifo_only
def test_a_machine_file_that_is_a_fifo_is_a_clear_error(tmp_path: Path) -> None:
    (tmp_path / "O0001.nc").write_text(FINDING, encoding="utf-8")
    fifo = tmp_path / "machine.toml"
    os.mkfifo(fifo)
    for args in (["check", "--machine", str(fifo), str(tmp_path)],
                 ["run", "--machine", str(fifo), str(tmp_path / "O0001.nc")]):  # fmt: skip
        r = cli(*args)
        assert_clean(r)
        assert (r.returncode, r.stderr) == (
            2, f"cncmacro {args[0]}: {fifo}: a FIFO (named pipe), not a file: not read (the machine file)\n"
        )  # fmt: skip
