"""The debug adapter's parts below the wire tests in ``tests/dap/``: Content-Length framing,
where a breakpoint is verified, hit counts, and step back by checkpoints plus replay giving
exactly the state the run had (docs/design.md "The debugger")."""

from __future__ import annotations

import io
import json

import pytest

from cncmacro.dap.protocol import Event, MessageWriter, ProtocolError, Response, read_message
from cncmacro.dap.session import Session
from cncmacro.debugging.breakpoints import Asked, Breakpoints, hit_test
from cncmacro.debugging.history import History
from running import lines, machine


def frame(payload: dict) -> bytes:
    body = json.dumps(payload).encode()
    return b"Content-Length: %d\r\n\r\n" % len(body) + body


def test_framing_reads_requests_one_after_another():
    stream = io.BytesIO(
        frame({"seq": 1, "type": "request", "command": "initialize", "arguments": {"locale": "zh-CN"}})
        + frame({"seq": 2, "type": "request", "command": "threads"})
    )
    first = read_message(stream)
    second = read_message(stream)
    assert (first.seq, first.command, first.arguments) == (1, "initialize", {"locale": "zh-CN"})
    assert (second.seq, second.command, second.arguments) == (2, "threads", {})
    assert read_message(stream) is None


def test_framing_reports_damaged_messages():
    with pytest.raises(ProtocolError) as bad_json:
        read_message(io.BytesIO(b"Content-Length: 3\r\n\r\n{x}"))
    assert not bad_json.value.fatal
    with pytest.raises(ProtocolError) as bad_header:
        read_message(io.BytesIO(b"Content-Length: lots\r\n\r\n{}"))
    assert bad_header.value.fatal
    with pytest.raises(ProtocolError) as not_a_request:
        read_message(io.BytesIO(frame({"seq": 4, "type": "request", "command": 5})))
    assert not_a_request.value.seq == 4  # it can still be answered


def test_writer_numbers_messages_and_frames_utf8():
    out = io.BytesIO()
    writer = MessageWriter(out)
    writer.send(Response(7, "evaluate", True, {"result": "<空>"}))
    writer.send(Event("stopped", {"reason": "pause"}))
    data = out.getvalue()
    header, _, rest = data.partition(b"\r\n\r\n")
    length = int(header.split(b":")[1])
    first = json.loads(rest[:length].decode())
    assert first == {"seq": 1, "type": "response", "request_seq": 7, "command": "evaluate", "success": True,
                     "body": {"result": "<空>"}}  # fmt: skip
    assert b'"seq": 2' in rest[length:] and b'"event": "stopped"' in rest[length:]


def test_breakpoints_are_verified_where_the_run_stops(tmp_path):
    path = tmp_path / "O9100.nc"
    path.write_text("%\nO9100 (TITLE)\n(COMMENT)\n\n#100=1\nM99\n%\n", encoding="utf-8")
    bps = Breakpoints()
    made = bps.set_lines(str(path), [Asked(0), Asked(2), Asked(4), Asked(6), Asked(39)])
    assert [(b.verified, b.line) for b in made] == [(True, 4), (True, 4), (True, 4), (False, None), (False, None)]
    missing = bps.set_lines(str(tmp_path / "nothing.nc"), [Asked(0)])
    assert not missing[0].verified and "cannot read" in (missing[0].message or "")


def test_hit_counts():
    assert [hit_test("3")(n) for n in (2, 3, 4)] == [False, True, False]
    assert [hit_test(">=2")(n) for n in (1, 2, 3)] == [False, True, True]
    assert [hit_test("%2")(n) for n in (1, 2, 3, 4)] == [False, True, False, True]
    assert hit_test("") is None
    with pytest.raises(ValueError):
        hit_test("often")


PROGRAM = lines("#1=0", "WHILE[#1 LT 50]DO1", "#1=#1+1", "#[100+#1]=#1*2", "END1", "M30")


def state(m):
    return m.blocks, m.frames[-1].pc, list(m.L), list(m.C), m.status


def test_step_back_replays_to_exactly_the_state_the_run_had():
    m = machine(PROGRAM)
    history = History(interval=7, keep=1000)
    history.reset(m)
    seen = []
    while not m.finished:
        seen.append(state(m))
        m.step()
        history.record(m)
    for target in (len(seen) - 1, 100, 50, 13, 0):
        assert history.go_to(m, target)
        assert state(m)[:4] == seen[target][:4]


def test_history_is_bounded_and_says_when_it_does_not_reach_back():
    m = machine(PROGRAM)
    history = History(interval=10, keep=3)
    history.reset(m)
    while not m.finished:
        m.step()
        history.record(m)
    assert len(history.checkpoints) == 3
    assert not history.go_to(m, 0)
    assert m.blocks == history.earliest > 0


def test_reverse_continue_finds_the_last_earlier_stop():
    m = machine(PROGRAM)
    history = History(interval=5)
    history.reset(m)
    for _ in range(40):
        m.step()
        history.record(m)
    now = m.blocks
    looked = []

    def look(mm, first, arrival, change, entered):
        looked.append(mm.blocks)
        return arrival and mm.frames[-1].pc == 3 and mm.L[1] == 4

    found = next(block for block, here in history.past(m, look) if here and block < now)
    assert sorted(set(looked))[-1] == now and found < now  # the past is walked from the present back
    assert history.go_to(m, found)
    assert m.frames[-1].pc == 3 and m.L[1] == 4 and m.C[104] is None


def test_a_session_answers_unknown_and_early_requests_with_failures():
    out = io.BytesIO()
    session = Session(MessageWriter(out))
    session.handle(read_message(io.BytesIO(frame({"seq": 1, "type": "request", "command": "fly"}))))
    session.handle(read_message(io.BytesIO(frame({"seq": 2, "type": "request", "command": "stackTrace"}))))
    session.handle(read_message(io.BytesIO(frame({"seq": 3, "type": "request", "command": "launch",
                                                  "arguments": {"program": "/no/such/file.nc"}}))))  # fmt: skip
    replies = [json.loads(part[: part.rfind(b"}") + 1]) for part in out.getvalue().split(b"\r\n\r\n")[1:]]
    assert [(r["request_seq"], r["success"]) for r in replies] == [(1, False), (2, False), (3, False)]
    assert "unknown request 'fly'" in replies[0]["message"]
    assert "launch one first" in replies[1]["message"]
    assert "there is no file /no/such/file.nc" in replies[2]["message"]


def test_each_breakpoint_request_refuses_breakpoints_that_are_not_a_list_of_objects():
    out = io.BytesIO()
    session = Session(MessageWriter(out))
    requests = [
        ("setBreakpoints", {"source": {"path": "/w/O1000.nc"}, "breakpoints": [3]}),
        ("setFunctionBreakpoints", {"breakpoints": {"name": "O1000"}}),
        ("setDataBreakpoints", {"breakpoints": ["#100"]}),
    ]
    for seq, (command, arguments) in enumerate(requests, 1):
        message = {"seq": seq, "type": "request", "command": command, "arguments": arguments}
        session.handle(read_message(io.BytesIO(frame(message))))
    replies = [json.loads(part[: part.rfind(b"}") + 1]) for part in out.getvalue().split(b"\r\n\r\n")[1:]]
    assert [(r["command"], r["success"]) for r in replies] == [(c, False) for c, _ in requests]
    assert all("'breakpoints' must be a list of objects" in r["message"] for r in replies)
