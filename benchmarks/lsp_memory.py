"""Language-server memory under an editor's traffic, and the time to open many documents.

A real ``cncmacro lsp`` process over stdio. Its resident memory is read at the start of the
session (initialized, one program open with its diagnostics) and after 40,000 one-line edits of
that program and 10,000 documents opened and closed, sent in batches with short pauses as an
editor sends them (the server keeps up between batches). Issue 16's budget: the end within 20% of
the start. Then 2,000 documents are opened at once and the time until every one has its
diagnostics is printed (budget: under 10 s).

    python benchmarks/lsp_memory.py [--edits 40000] [--cycles 10000] [--many 2000]
"""

from __future__ import annotations

import argparse
import asyncio
import sys
import tempfile
import time
from pathlib import Path

from lsprotocol import types
from pygls.lsp.client import LanguageClient

GROWTH_BUDGET = 0.20
MANY_SECONDS = 10.0
BATCH = 200  # messages between pauses


def resident_mb(client: LanguageClient) -> float:
    pid = client._server.pid  # type: ignore[union-attr]  # the server's process
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS"):
            return int(line.split()[1]) / 1024
    raise RuntimeError("no VmRSS")


class Session:
    """A server over stdio and the latest version of each document's diagnostics."""

    def __init__(self) -> None:
        self.client = LanguageClient("bench", "1")
        self.versions: dict[str, int | None] = {}

        @self.client.feature(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
        def published(params: types.PublishDiagnosticsParams) -> None:
            self.versions[params.uri] = params.version

    async def settle(self, uri: str, version: int, timeout: float = 60.0) -> None:
        """Wait until ``uri`` has the diagnostics of ``version``."""
        end = time.monotonic() + timeout
        while self.versions.get(uri) != version:
            if time.monotonic() > end:
                raise RuntimeError(f"no diagnostics for version {version} of {uri}")
            await asyncio.sleep(0.01)

    def open(self, path: Path, text: str) -> str:
        path.write_text(text, "utf-8")
        uri = path.as_uri()
        item = types.TextDocumentItem(uri, "cnc-macro", 1, text)
        self.client.text_document_did_open(types.DidOpenTextDocumentParams(item))
        return uri

    def close(self, uri: str) -> None:
        self.client.text_document_did_close(types.DidCloseTextDocumentParams(types.TextDocumentIdentifier(uri)))

    def edit(self, uri: str, version: int, text: str) -> None:
        change = types.TextDocumentContentChangePartial(
            range=types.Range(types.Position(1, 3), types.Position(1, 100)), text=text
        )
        ident = types.VersionedTextDocumentIdentifier(uri=uri, version=version)
        self.client.text_document_did_change(types.DidChangeTextDocumentParams(ident, [change]))


async def main(edits: int, cycles: int, many: int) -> int:
    root = Path(tempfile.mkdtemp(prefix="cncmacro-memory-bench-"))
    s = Session()
    client = s.client
    await client.start_io(sys.executable, "-m", "cncmacro", "lsp")
    await client.initialize_async(
        types.InitializeParams(capabilities=types.ClientCapabilities(), root_uri=root.as_uri(), locale="en")
    )
    client.initialized(types.InitializedParams())
    uri = s.open(root / "EDITED.nc", "O0001\n#1=1\nG01 X1. Y2. F100.\nM30\n")
    await s.settle(uri, 1)
    await asyncio.sleep(1.0)
    start = resident_mb(client)
    began = time.monotonic()
    version = 1
    rounds = max(1, edits // 4_000)
    per_round_edits, per_round_cycles = edits // rounds, cycles // rounds
    opened = 0
    samples = [start]
    for _ in range(rounds):
        for k in range(per_round_edits):
            version += 1
            s.edit(uri, version, str(version))
            if k % BATCH == 0:
                await asyncio.sleep(0.01)
        await s.settle(uri, version)
        for k in range(per_round_cycles):
            n = opened + 1000
            opened += 1
            other = s.open(root / f"O{n}.nc", f"O{n}\n#1={n}\nG01 X{n}. F100.\nM30\n")
            s.close(other)
            (root / f"O{n}.nc").unlink()
            if k % BATCH == 0:
                await asyncio.sleep(0.01)
        await client.workspace_symbol_async(types.WorkspaceSymbolParams(query="O"))
        samples.append(resident_mb(client))
    await asyncio.sleep(2.0)  # a quiet moment: the server cleans up
    end = resident_mb(client)
    took = time.monotonic() - began
    growth = (end - start) / start
    print(f"traffic: {version - 1:,} edits and {opened:,} open/close cycles in {took:.0f} s")
    print("resident memory after each round: " + ", ".join(f"{x:.0f}" for x in samples) + " MB")
    verdict = "within" if growth <= GROWTH_BUDGET else "OVER"
    print(f"resident memory: {start:.1f} MB at the start, {end:.1f} MB at the end: {growth:+.1%} "
          f"({verdict} the budget of +{GROWTH_BUDGET:.0%})")  # fmt: skip

    folder = root / "many"
    folder.mkdir()
    t0 = time.monotonic()
    uris = [s.open(folder / f"O{k + 20000}.nc", f"O{k + 20000}\n#1={k}\nG01 X{k}. F100.\nM98 P{k + 20001}\nM30\n")
            for k in range(many)]  # fmt: skip
    for u in uris:
        await s.settle(u, 1, timeout=120.0)
    many_s = time.monotonic() - t0
    print(f"{many:,} documents opened at once: all diagnostics in {many_s:.1f} s (budget < {MANY_SECONDS:g} s)")
    await client.shutdown_async(None)
    client.exit(None)
    await client.stop()
    return 0 if growth <= GROWTH_BUDGET and many_s < MANY_SECONDS else 1


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--edits", type=int, default=40_000)
    ap.add_argument("--cycles", type=int, default=10_000)
    ap.add_argument("--many", type=int, default=2_000)
    a = ap.parse_args()
    sys.exit(asyncio.run(main(a.edits, a.cycles, a.many)))
