"""Language-server benchmark: a real ``cncmacro lsp`` process over stdio, a 100k-line CAM program.

Prints the time from opening the file to its first diagnostics; for one-line edits, the time
from sending the change to receiving the diagnostics of that version (debounce included); the
round-trip time of hovers at random places; and the server's peak resident memory. The budgets
(issue 5) are <= 100 ms p95 from edit to diagnostics, <= 10 ms p95 per hover, <= 300 MB peak.

    python benchmarks/lsp.py [--lines N] [--edits N] [--hovers N]
"""

from __future__ import annotations

import argparse
import asyncio
import random
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from lsprotocol import types
from pygls.lsp.client import LanguageClient

from camgen import cam_program


def p95(xs: list[float]) -> float:
    return sorted(xs)[max(0, int(len(xs) * 0.95) - 1)]


async def run(lines: int, edits: int, hovers: int) -> None:
    text = cam_program(lines)
    folder = Path(tempfile.mkdtemp(prefix="cncmacro-lsp-bench-"))
    path = folder / "CAM.nc"
    path.write_text(text, "utf-8")
    uri = path.as_uri()
    waiting: dict[int, asyncio.Future[float]] = {}

    client = LanguageClient("bench", "1")

    @client.feature(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    def published(params: types.PublishDiagnosticsParams) -> None:
        fut = waiting.get(params.version or -1)
        if fut is not None and not fut.done():
            fut.set_result(time.perf_counter())

    await client.start_io(sys.executable, "-m", "cncmacro", "lsp")
    await client.initialize_async(
        types.InitializeParams(capabilities=types.ClientCapabilities(), root_uri=folder.as_uri(), locale="en")
    )
    client.initialized(types.InitializedParams())
    loop = asyncio.get_running_loop()

    waiting[1] = loop.create_future()
    t0 = time.perf_counter()
    client.text_document_did_open(types.DidOpenTextDocumentParams(types.TextDocumentItem(uri, "cncmacro", 1, text)))
    first = await waiting[1] - t0
    print(f"{lines} lines: open -> first diagnostics {first * 1000:.0f} ms")

    doc_lines = text.split("\n")
    rnd = random.Random(5)
    times = []
    for k in range(edits):
        version = k + 2
        line = rnd.randrange(5, len(doc_lines) - 5)
        col = len(doc_lines[line])
        waiting[version] = loop.create_future()
        t0 = time.perf_counter()
        client.text_document_did_change(
            types.DidChangeTextDocumentParams(
                types.VersionedTextDocumentIdentifier(uri=uri, version=version),
                [
                    types.TextDocumentContentChangePartial(
                        range=types.Range(types.Position(line, col), types.Position(line, col)), text=" "
                    )
                ],
            )
        )
        times.append(await waiting[version] - t0)
        doc_lines[line] += " "
    print(
        f"one-line edit -> diagnostics of that version: median {statistics.median(times) * 1000:.1f} ms, "
        f"p95 {p95(times) * 1000:.1f} ms ({edits} edits)"
    )

    hover_times = []
    for _ in range(hovers):
        line = rnd.randrange(0, len(doc_lines))
        col = rnd.randrange(0, max(1, len(doc_lines[line])))
        t0 = time.perf_counter()
        await client.text_document_hover_async(
            types.HoverParams(types.TextDocumentIdentifier(uri), types.Position(line, col))
        )
        hover_times.append(time.perf_counter() - t0)
    print(
        f"hover round trip: median {statistics.median(hover_times) * 1000:.2f} ms, "
        f"p95 {p95(hover_times) * 1000:.2f} ms ({hovers} hovers)"
    )

    server = client._server  # the subprocess
    if server is not None and sys.platform.startswith("linux"):
        status = Path(f"/proc/{server.pid}/status").read_text()
        peak = next(x for x in status.splitlines() if x.startswith("VmHWM"))
        print(f"server peak RSS: {int(peak.split()[1]) / 1024:.0f} MB")
    await client.shutdown_async(None)
    client.exit(None)
    await client.stop()
    path.unlink()
    folder.rmdir()


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lines", type=int, default=100_000)
    ap.add_argument("--edits", type=int, default=40)
    ap.add_argument("--hovers", type=int, default=300)
    args = ap.parse_args()
    asyncio.run(run(args.lines, args.edits, args.hovers))
    return 0


if __name__ == "__main__":
    sys.exit(main())
