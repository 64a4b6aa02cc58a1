"""Language-server latency: a real ``cncmacro lsp`` process over stdio on generated CAM programs.

For each size (2k, 20k and 100k lines by default), in a fresh server: the time from opening
the file to its first diagnostics; for one-line edits (a digit typed into a coordinate, as an
editor sends it), the time from sending the change to receiving the diagnostics of that
version, p50 and p95, at random lines and separately at random lines in the last 10% of the
file; the round trip of hovers at random places (p95); and the server's peak resident memory.
Issue 5's budgets are printed beside the figures.

    python benchmarks/lsp.py [--sizes 2000,20000,100000] [--edits N] [--hovers N]
"""

from __future__ import annotations

import argparse
import asyncio
import random
import re
import statistics
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from lsprotocol import types
from pygls.lsp.client import LanguageClient

from camgen import cam_program

# lines -> (open ms, edit p95 ms); and for every size hover p95 <= 10 ms; peak RSS at 100k <= 300 MB
BUDGETS = {2_000: (100, 30), 20_000: (600, 50), 100_000: (3_000, 100)}
KINDS = ("system variable", "common", "label", "plain word")
SYSTEM_READ = "#150=#5001+#4001"
_COMMON = re.compile(r"#1\d\d(?!\d)")


def with_system_reads(text: str) -> str:
    """``text`` with every 1000th plain motion line (``X.. Y..``) replaced by ``SYSTEM_READ``."""
    lines = text.split("\n")
    for i in range(500, len(lines), 1000):
        while i < len(lines) - 5 and not lines[i].startswith("X"):
            i += 1
        lines[i] = SYSTEM_READ
    return "\n".join(lines)


def hover_places(doc_lines: list[str], kind: str) -> list[tuple[int, int]]:
    """(line, column) of every place of ``kind`` in the program."""
    out = []
    for i, line in enumerate(doc_lines):
        if kind == "system variable" and line == SYSTEM_READ:
            out.append((i, line.index("#5001") + 2))
        elif kind == "common" and line.startswith("#") and line != SYSTEM_READ:
            m = _COMMON.search(line)
            if m is not None:
                out.append((i, m.start() + 2))
        elif kind == "label" and line.startswith("N"):
            out.append((i, 1))
        elif kind == "plain word" and line.startswith("X"):
            out.append((i, 1))
    return out


@dataclass
class Figures:
    lines: int
    open_ms: float
    edits_ms: list[float]
    tail_edits_ms: list[float]
    hovers_ms: list[float]
    kinds_ms: dict[str, list[float]]
    peak_mb: float | None


def pct(xs: list[float], p: float) -> float:
    s = sorted(xs)
    return s[min(len(s) - 1, max(0, round(p * len(s)) - 1))]


class Session:
    """A server over stdio, with the times at which each version's diagnostics arrived."""

    def __init__(self) -> None:
        self.client = LanguageClient("bench", "1")
        self.waiting: dict[int, asyncio.Future[float]] = {}

        @self.client.feature(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
        def published(params: types.PublishDiagnosticsParams) -> None:
            fut = self.waiting.get(params.version if params.version is not None else -1)
            if fut is not None and not fut.done():
                fut.set_result(time.perf_counter())

    def expect(self, version: int) -> asyncio.Future[float]:
        fut: asyncio.Future[float] = asyncio.get_running_loop().create_future()
        self.waiting[version] = fut
        return fut


async def measure(lines: int, edits: int, hovers: int) -> Figures:
    text = with_system_reads(cam_program(lines))
    folder = Path(tempfile.mkdtemp(prefix="cncmacro-lsp-bench-"))
    path = folder / "O0001.nc"
    path.write_text(text, "utf-8")
    uri = path.as_uri()
    s = Session()
    client = s.client
    await client.start_io(sys.executable, "-m", "cncmacro", "lsp")
    await client.initialize_async(
        types.InitializeParams(capabilities=types.ClientCapabilities(), root_uri=folder.as_uri(), locale="en")
    )
    client.initialized(types.InitializedParams())
    await asyncio.sleep(0.3)  # the server settles after ``initialized``

    fut = s.expect(1)
    t0 = time.perf_counter()
    client.text_document_did_open(types.DidOpenTextDocumentParams(types.TextDocumentItem(uri, "cncmacro", 1, text)))
    open_ms = (await fut - t0) * 1000

    doc_lines = text.split("\n")
    rnd = random.Random(5)
    version = 1

    async def edit_at(line: int) -> float:
        nonlocal version
        version += 1
        while "X" not in doc_lines[line] or "#" in doc_lines[line]:
            line += 1 if line < len(doc_lines) - 10 else -200
        col = doc_lines[line].index("X") + 1
        fut = s.expect(version)
        t0 = time.perf_counter()
        client.text_document_did_change(
            types.DidChangeTextDocumentParams(
                types.VersionedTextDocumentIdentifier(uri=uri, version=version),
                [
                    types.TextDocumentContentChangePartial(
                        range=types.Range(types.Position(line, col), types.Position(line, col)), text="1"
                    )
                ],
            )
        )
        ms = (await fut - t0) * 1000
        doc_lines[line] = doc_lines[line][:col] + "1" + doc_lines[line][col:]
        await asyncio.sleep(0.02)  # as between keystrokes
        return ms

    n = len(doc_lines)
    everywhere = [await edit_at(rnd.randrange(5, n - 10)) for _ in range(edits)]
    tail = [await edit_at(rnd.randrange(n - n // 10, n - 10)) for _ in range(edits)]

    async def hover_at(line: int, col: int) -> float:
        t0 = time.perf_counter()
        await client.text_document_hover_async(
            types.HoverParams(types.TextDocumentIdentifier(uri), types.Position(line, col))
        )
        return (time.perf_counter() - t0) * 1000

    hover_ms = []
    for _ in range(hovers):
        line = rnd.randrange(0, n - 1)
        hover_ms.append(await hover_at(line, rnd.randrange(0, max(1, len(doc_lines[line])))))
    kinds_ms: dict[str, list[float]] = {}
    for kind in KINDS:
        places = hover_places(doc_lines, kind)
        kinds_ms[kind] = [await hover_at(*rnd.choice(places)) for _ in range(hovers // 2)] if places else []

    peak = None
    server = client._server  # the subprocess
    if server is not None and sys.platform.startswith("linux"):
        status = Path(f"/proc/{server.pid}/status").read_text()
        peak = int(next(x for x in status.splitlines() if x.startswith("VmHWM")).split()[1]) / 1024
    await client.shutdown_async(None)
    client.exit(None)
    await client.stop()
    path.unlink()
    folder.rmdir()
    return Figures(lines, open_ms, everywhere, tail, hover_ms, kinds_ms, peak)


def report(figures: list[Figures]) -> None:
    print("| lines | open -> diags | edit anywhere p50 / p95 | edit in last 10% p50 / p95 | hover p95 | peak RSS |")
    print("| ---: | ---: | ---: | ---: | ---: | ---: |")
    for f in figures:
        budget = BUDGETS.get(f.lines)
        ob = f" (<= {budget[0]})" if budget else ""
        eb = f" (<= {budget[1]})" if budget else ""
        rss = f"{f.peak_mb:.0f} MB" + (" (<= 300)" if f.lines == 100_000 else "") if f.peak_mb else "?"
        print(
            f"| {f.lines:,} | {f.open_ms:.0f} ms{ob} "
            f"| {statistics.median(f.edits_ms):.1f} / {pct(f.edits_ms, 0.95):.1f} ms{eb} "
            f"| {statistics.median(f.tail_edits_ms):.1f} / {pct(f.tail_edits_ms, 0.95):.1f} ms{eb} "
            f"| {pct(f.hovers_ms, 0.95):.2f} ms (<= 10) | {rss} |"
        )
    print()
    print("| lines | " + " | ".join(f"hover {k} p50 / p95" for k in KINDS) + " |")
    print("| ---: |" + " ---: |" * len(KINDS))
    for f in figures:
        cells = [
            f"{statistics.median(ms):.2f} / {pct(ms, 0.95):.2f} ms" if ms else "-"
            for ms in (f.kinds_ms[k] for k in KINDS)
        ]
        print(f"| {f.lines:,} | " + " | ".join(cells) + " |")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="2000,20000,100000")
    ap.add_argument("--edits", type=int, default=40)
    ap.add_argument("--hovers", type=int, default=200)
    args = ap.parse_args()
    figures = []
    for size in (int(x) for x in args.sizes.split(",")):
        figures.append(asyncio.run(measure(size, args.edits, args.hovers)))
        print(f"measured {size:,} lines", file=sys.stderr)
    report(figures)
    return 0


if __name__ == "__main__":
    sys.exit(main())
