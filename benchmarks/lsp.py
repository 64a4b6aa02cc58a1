"""Language-server latency: a real ``cncmacro lsp`` process over stdio on generated CAM programs.

For each size (2k, 20k and 100k lines by default), in a fresh server: the time from opening
the file to its first diagnostics; for one-line edits (a digit typed into a coordinate, as an
editor sends it), the time from sending the change to receiving the diagnostics of that
version, p50 and p95, at random lines and separately at random lines in the last 10% of the
file; the round trip of hovers at random places (p95); and the server's peak resident memory.
Issue 5's budgets are printed beside the figures.

With ``--program FILE`` (repeatable) it measures the given files instead, such as the programs
of a shared benchmark generator, in a fresh server each: open to the first and to the last
diagnostics of the opened version; edits that change one digit of a coordinate at the middle
(50%) and near the end (95%) of the file, alternately, each to the diagnostics of its version,
p50 and p95 per place; hovers on ``#`` variables spread over the file (p95); and the peak
resident memory. The file is copied into an empty folder first (``--in-place``: opened where
it is, its folder the workspace, other programs there included). The budget row is chosen by
the file's line count: the nearest (by ratio) of 20k, 100k and 1M lines, none under 10k. See
docs/benchmarks.md.

    python benchmarks/lsp.py [--sizes 2000,20000,100000] [--edits N] [--hovers N]
    python benchmarks/lsp.py --program cam_100k.nc [--program ...] [--in-place] [--edits N] [--hovers N]
"""

from __future__ import annotations

import argparse
import asyncio
import itertools
import json
import math
import random
import re
import shutil
import statistics
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from lsprotocol import types
from pygls.lsp.client import LanguageClient

from camgen import cam_program
from cncmacro.lsp.diagnostics import PROGRESS_LINES

# lines -> (open ms, edit p95 ms); and for every size hover p95 <= 10 ms; peak RSS at 100k <= 300 MB
BUDGETS = {2_000: (100, 30), 20_000: (600, 50), 100_000: (3_000, 100)}
KINDS = ("system variable", "common", "label", "plain word")
SYSTEM_READ = "#150=#5001+#4001"
_COMMON = re.compile(r"#1\d\d(?!\d)")
# a coordinate word with a number (its digits are group 1), and a ``#`` variable
_COORDINATE = re.compile(r"(?<![#A-Za-z0-9_.])[XYZIJKR]-?(\d*\.\d+|\d+\.?)")
_HASH_VARIABLE = re.compile(r"#\d+|#[A-Za-z_]\w*")
EDIT_PLACES = (0.50, 0.95)  # a given program is edited at its middle and near its end, alternately
QUIET_SECONDS = 0.5  # after the first diagnostics of the opened file, more are waited for this long


@dataclass(frozen=True)
class ProgramBudget:
    """Issue 20's budget for a given program of about ``lines`` lines (ms and MB)."""

    lines: int
    first_ms: float
    all_ms: float | None
    edit_p95_ms: float
    hover_p95_ms: float
    peak_mb: float


PROGRAM_BUDGETS = (
    ProgramBudget(20_000, 300, None, 15, 2, 90),
    ProgramBudget(100_000, 800, None, 30, 2, 200),
    ProgramBudget(1_000_000, 3_000, 8_000, 100, 5, 800),
)


def program_budget(lines: int) -> ProgramBudget | None:
    """The budget row for a program of ``lines`` lines: the nearest by ratio, none under 10k."""
    if lines < 10_000:
        return None
    return min(PROGRAM_BUDGETS, key=lambda b: abs(math.log(lines / b.lines)))


def timeouts(lines: int) -> tuple[float, float]:
    """Seconds to wait for the diagnostics of an opened file and of an edit: generous, and
    growing with the file (a million lines take more than 10 s to open on a slow machine)."""
    return 30 + lines * 120 / 1_000_000, 10 + lines * 30 / 1_000_000


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


def coordinate_digit(doc_lines: list[str], start: int) -> tuple[int, int]:
    """(line, column) of the last digit of the first coordinate at or after line ``start``
    (from the top again past the end), outside comment lines."""
    for i in itertools.chain(range(start, len(doc_lines)), range(0, start)):
        line = doc_lines[i]
        if line.lstrip().startswith(("(", ";")):
            continue
        m = _COORDINATE.search(line)
        if m is not None:
            digits = m.group(1)
            return i, m.start(1) + max(k for k, c in enumerate(digits) if c.isdigit())
    raise ValueError("the program has no coordinate to edit")


def variable_places(doc_lines: list[str], count: int) -> list[tuple[int, int]]:
    """``count`` places just after the ``#`` of a variable, spread evenly over the program."""
    sites = [
        (i, m.start() + 1) for i, line in enumerate(doc_lines) if "#" in line for m in _HASH_VARIABLE.finditer(line)
    ]
    if not sites:
        return []
    step = len(sites) / count
    return [sites[min(len(sites) - 1, int(k * step + step / 2))] for k in range(count)]


def utf16(line: str, column: int) -> int:
    """The UTF-16 column (the protocol's default) of the character at ``column`` of ``line``."""
    return len(line[:column].encode("utf-16-le")) // 2


@dataclass
class Figures:
    lines: int
    open_ms: float
    edits_ms: list[float]
    tail_edits_ms: list[float]
    hovers_ms: list[float]
    kinds_ms: dict[str, list[float]]
    peak_mb: float | None


@dataclass
class ProgramFigures:
    """The figures of one given program file."""

    name: str
    lines: int
    first_ms: float
    all_ms: float
    findings: int
    edits_ms: dict[float, list[float]]  # per place (a fraction of the file)
    hovers_ms: list[float]
    peak_mb: float | None
    timeouts: int = 0
    notes: list[str] = field(default_factory=list)


def pct(xs: list[float], p: float) -> float:
    s = sorted(xs)
    return s[min(len(s) - 1, max(0, round(p * len(s)) - 1))]


class Session:
    """A server over stdio, with the times at which each version's diagnostics arrived."""

    def __init__(self) -> None:
        self.client = LanguageClient("bench", "1")
        self.waiting: dict[int, asyncio.Future[float]] = {}
        self.arrivals: list[tuple[float, int | None, int]] = []  # (time, version, number of diagnostics)
        self.analysed: asyncio.Event | None = None  # set when an analysis's progress ends
        self.body_read_at = 0.0  # when the last message's bytes were read (before they are converted)
        self.stderr_lines: list[str] = []  # what the server wrote to stderr
        self._drainer: asyncio.Future[None] | None = None

        @self.client.feature(types.WINDOW_WORK_DONE_PROGRESS_CREATE)
        def create(params: types.WorkDoneProgressCreateParams) -> None:
            return None

        @self.client.feature(types.PROGRESS)
        def progress(params: types.ProgressParams) -> None:
            ended = isinstance(params.value, dict) and params.value.get("kind") == "end"
            ended = ended or isinstance(params.value, types.WorkDoneProgressEnd)
            if ended and str(params.token).startswith("cncmacro-analysis-") and self.analysed is not None:
                self.analysed.set()

        @self.client.feature(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
        def published(params: types.PublishDiagnosticsParams) -> None:
            now = self.body_read_at
            self.arrivals.append((now, params.version, len(params.diagnostics)))
            fut = self.waiting.get(params.version if params.version is not None else -1)
            if fut is not None and not fut.done():
                fut.set_result(now)

    def expect(self, version: int) -> asyncio.Future[float]:
        fut: asyncio.Future[float] = asyncio.get_running_loop().create_future()
        self.waiting[version] = fut
        return fut

    async def start(self, folder: Path) -> None:
        """Start the server, initialize it on ``folder`` and let it settle."""
        await self.client.start_io(sys.executable, "-m", "cncmacro", "lsp")
        self._time_reads()
        self._drain_stderr()
        await self.client.initialize_async(
            types.InitializeParams(
                capabilities=types.ClientCapabilities(window=types.WindowClientCapabilities(work_done_progress=True)),
                root_uri=folder.as_uri(),
                locale="en",
            )
        )
        self.client.initialized(types.InitializedParams())
        await asyncio.sleep(0.3)  # the server settles after ``initialized``

    def _time_reads(self) -> None:
        """Note when each message's bytes have been read: a message arrives then, as the shared
        harness ``lsp_latency.py`` times it, not after this client has turned its JSON into
        protocol objects (which costs it 30-50 ms for a thousand findings: the client's time,
        not the server's)."""
        server = self.client._server
        stream = server.stdout if server is not None else None
        if stream is None:
            return
        read = stream.readexactly

        async def timed(n: int) -> bytes:
            body = await read(n)
            self.body_read_at = time.perf_counter()
            return body

        stream.readexactly = timed  # type: ignore[method-assign]

    def _drain_stderr(self) -> None:
        """Read what the server writes to stderr (its warnings), kept in ``stderr_lines``: a
        pipe nobody reads fills up and would stop the server in the middle of a write."""
        server = self.client._server
        stream = server.stderr if server is not None else None
        if stream is None:
            return

        async def drain() -> None:
            while line := await stream.readline():
                self.stderr_lines.append(line.decode("utf-8", "replace").rstrip())

        self._drainer = asyncio.ensure_future(drain())

    def peak_mb(self) -> float | None:
        """The server's peak resident memory (Linux only)."""
        server = self.client._server  # the subprocess
        if server is None or not sys.platform.startswith("linux"):
            return None
        status = Path(f"/proc/{server.pid}/status").read_text()
        return int(next(x for x in status.splitlines() if x.startswith("VmHWM")).split()[1]) / 1024

    async def stop(self) -> None:
        try:
            await asyncio.wait_for(self.client.shutdown_async(None), 30)
            self.client.exit(None)
        finally:
            await self.client.stop()

    def open_document(self, uri: str, language: str, text: str) -> float:
        """Send ``didOpen`` for ``text`` and return when it was sent: the message is made into
        its bytes first, as the shared harness ``lsp_latency.py`` makes it before its clock
        starts (turning a 1M-line text into JSON costs this client 0.2-0.3 s: its time, not the
        server's), then written to the server's input as the client writes every message."""
        params = {"textDocument": {"uri": uri, "languageId": language, "version": 1, "text": text}}
        body = json.dumps({"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": params}).encode("utf-8")
        data = f"Content-Length: {len(body)}\r\n\r\n".encode("ascii") + body
        server = self.client._server
        assert server is not None and server.stdin is not None
        sent = time.perf_counter()
        server.stdin.write(data)
        return sent

    def change(self, uri: str, version: int, line: int, start: int, end: int, text: str) -> None:
        """Send one edit: ``text`` in place of the columns ``start``..``end`` (UTF-16) of ``line``."""
        where = types.Range(types.Position(line, start), types.Position(line, end))
        self.client.text_document_did_change(
            types.DidChangeTextDocumentParams(
                types.VersionedTextDocumentIdentifier(uri=uri, version=version),
                [types.TextDocumentContentChangePartial(range=where, text=text)],
            )
        )

    async def hover(self, uri: str, line: int, col: int) -> float:
        t0 = time.perf_counter()
        await self.client.text_document_hover_async(
            types.HoverParams(types.TextDocumentIdentifier(uri), types.Position(line, col))
        )
        return (time.perf_counter() - t0) * 1000


async def arrival(fut: asyncio.Future[float], timeout: float, what: str) -> float:
    """When ``fut``'s diagnostics arrived; a clear error after ``timeout`` seconds."""
    try:
        return await asyncio.wait_for(fut, timeout)
    except asyncio.TimeoutError:
        raise TimeoutError(f"no diagnostics for {what} within {timeout:.0f} s") from None


async def measure(lines: int, edits: int, hovers: int) -> Figures:
    text = with_system_reads(cam_program(lines))
    folder = Path(tempfile.mkdtemp(prefix="cncmacro-lsp-bench-"))
    path = folder / "O0001.nc"
    path.write_text(text, "utf-8")
    uri = path.as_uri()
    open_timeout, edit_timeout = timeouts(lines)
    s = Session()
    await s.start(folder)
    try:
        fut = s.expect(1)
        t0 = s.open_document(uri, "cncmacro", text)
        open_ms = (await arrival(fut, open_timeout, "the opened file") - t0) * 1000

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
            s.change(uri, version, line, col, col, "1")
            ms = (await arrival(fut, edit_timeout, f"version {version}") - t0) * 1000
            doc_lines[line] = doc_lines[line][:col] + "1" + doc_lines[line][col:]
            await asyncio.sleep(0.02)  # as between keystrokes
            return ms

        n = len(doc_lines)
        everywhere = [await edit_at(rnd.randrange(5, n - 10)) for _ in range(edits)]
        tail = [await edit_at(rnd.randrange(n - n // 10, n - 10)) for _ in range(edits)]

        hover_ms = []
        for _ in range(hovers):
            line = rnd.randrange(0, n - 1)
            hover_ms.append(await s.hover(uri, line, rnd.randrange(0, max(1, len(doc_lines[line])))))
        kinds_ms: dict[str, list[float]] = {}
        for kind in KINDS:
            places = hover_places(doc_lines, kind)
            kinds_ms[kind] = [await s.hover(uri, *rnd.choice(places)) for _ in range(hovers // 2)] if places else []

        peak = s.peak_mb()
    finally:
        await s.stop()
        shutil.rmtree(folder, ignore_errors=True)
    return Figures(lines, open_ms, everywhere, tail, hover_ms, kinds_ms, peak)


async def measure_program(program: Path, edits: int, hovers: int, in_place: bool = False) -> ProgramFigures:
    """The figures of a given program, opened under its own name in an empty folder, so that
    nothing beside the file is read as part of the workspace; ``in_place``: where it is, with
    its folder as the workspace (as the shared harness opens it), other programs there included."""
    text = program.read_text("utf-8")
    if in_place:
        folder, path = program.resolve().parent, program.resolve()
    else:
        folder = Path(tempfile.mkdtemp(prefix="cncmacro-lsp-bench-"))
        path = folder / program.name
        path.write_text(text, "utf-8")
    uri = path.as_uri()
    doc_lines = text.split("\n")
    lines = len(doc_lines) - (1 if text.endswith("\n") else 0)
    open_timeout, edit_timeout = timeouts(lines)
    s = Session()
    await s.start(folder)
    try:
        fut = s.expect(1)
        opened_at = s.open_document(uri, "cnc-macro", text)
        s.analysed = asyncio.Event()
        first = await arrival(fut, open_timeout, "the opened file")
        if lines >= PROGRESS_LINES:  # its first analysis reports progress: all diagnostics come after its end
            await asyncio.wait_for(s.analysed.wait(), open_timeout)
        while True:  # later diagnostics of the opened file, until none came for a moment
            await asyncio.sleep(QUIET_SECONDS)
            if s.arrivals[-1][0] < time.perf_counter() - QUIET_SECONDS:
                break
        last = max(t for t, v, _ in s.arrivals if v in (1, None))
        findings = next(k for t, v, k in s.arrivals if v == 1)

        sites = {
            place: coordinate_digit(doc_lines, min(len(doc_lines) - 1, int(place * lines))) for place in EDIT_PLACES
        }
        edits_ms: dict[float, list[float]] = {place: [] for place in EDIT_PLACES}
        version, missed = 1, 0
        for place in itertools.islice(itertools.cycle(EDIT_PLACES), edits * len(EDIT_PLACES)):
            line, col = sites[place]
            digit = str((int(doc_lines[line][col]) + 1) % 10)  # one digit changed, as a typo fixed
            version += 1
            fut = s.expect(version)
            t0 = time.perf_counter()
            s.change(uri, version, line, utf16(doc_lines[line], col), utf16(doc_lines[line], col + 1), digit)
            doc_lines[line] = doc_lines[line][:col] + digit + doc_lines[line][col + 1 :]
            try:
                edits_ms[place].append((await asyncio.wait_for(fut, edit_timeout) - t0) * 1000)
            except asyncio.TimeoutError:
                missed += 1
                edits_ms[place].append(edit_timeout * 1000)  # counted as the wait, and said below
            await asyncio.sleep(0.02)  # as between keystrokes

        hover_ms = [
            await s.hover(uri, line, utf16(doc_lines[line], col)) for line, col in variable_places(doc_lines, hovers)
        ]
        peak = s.peak_mb()
    finally:
        await s.stop()
        if not in_place:
            shutil.rmtree(folder, ignore_errors=True)
    notes = [f"{missed} edits got no diagnostics within {edit_timeout:.0f} s (counted as that)"] if missed else []
    if not hover_ms:
        notes.append("no # variable to hover")
    return ProgramFigures(
        program.name,
        lines,
        (first - opened_at) * 1000,
        (last - opened_at) * 1000,
        findings,
        edits_ms,
        hover_ms,
        peak,
        missed,
        notes,
    )


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


def report_programs(figures: list[ProgramFigures]) -> None:
    """The figures of given programs, each beside the budget of its row (issue 20)."""
    places = " | ".join(f"edit at {p:.0%} p50 / p95" for p in EDIT_PLACES)
    print(f"| program | lines | open -> first / all diags | findings | {places} | hover p95 | peak RSS |")
    print("| --- | ---: | ---: | ---: |" + " ---: |" * (len(EDIT_PLACES) + 2))
    for f in figures:
        b = program_budget(f.lines)
        if b is None:
            ob = eb = hb = rb = ""
        else:
            ob = f" (<= {b.first_ms:,.0f}" + (f" / {b.all_ms:,.0f})" if b.all_ms else ")")
            eb, hb, rb = f" (<= {b.edit_p95_ms:.0f})", f" (<= {b.hover_p95_ms:.0f})", f" (<= {b.peak_mb:.0f})"
        edits = " | ".join(
            f"{statistics.median(ms):.1f} / {pct(ms, 0.95):.1f} ms{eb}" if ms else "-" for ms in f.edits_ms.values()
        )
        hover = f"{pct(f.hovers_ms, 0.95):.2f} ms{hb}" if f.hovers_ms else "-"
        rss = f"{f.peak_mb:.0f} MB{rb}" if f.peak_mb else "?"
        print(
            f"| {f.name} | {f.lines:,} | {f.first_ms:,.0f} / {f.all_ms:,.0f} ms{ob} | {f.findings} "
            f"| {edits} | {hover} | {rss} |"
        )
    for f in figures:
        for note in f.notes:
            print(f"{f.name}: {note}")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="2000,20000,100000", help="generated programs' lines, e.g. 2000,1000000")
    ap.add_argument("--program", action="append", type=Path, default=[], help="measure this file instead (repeatable)")
    ap.add_argument(
        "--in-place",
        action="store_true",
        help="open each --program where it is, its folder the workspace (other programs there are read too)",
    )
    ap.add_argument("--edits", type=int, default=40, help="edits per place")
    ap.add_argument("--hovers", type=int, default=200)
    args = ap.parse_args()
    if args.program:
        measured = []
        for program in args.program:
            measured.append(asyncio.run(measure_program(program, args.edits, args.hovers, args.in_place)))
            print(f"measured {program.name}", file=sys.stderr)
        report_programs(measured)
        return 0
    figures = []
    for size in (int(x) for x in args.sizes.split(",")):
        figures.append(asyncio.run(measure(size, args.edits, args.hovers)))
        print(f"measured {size:,} lines", file=sys.stderr)
    report(figures)
    return 0


if __name__ == "__main__":
    sys.exit(main())
