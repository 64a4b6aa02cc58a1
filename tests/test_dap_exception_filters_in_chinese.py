"""docs/debugging.md, exception filters: the Breakpoints view names the debugger's two filters in
the editor's language. The adapter's `initialize` answer gives them, so under a Chinese locale
(`locale: zh-cn`, as VS Code sends it) they read 所有报警 and #3006 信息, with their descriptions
in Chinese; in English they stay "All alarms" and "#3006 messages"."""

from __future__ import annotations

import io
from typing import Any

from cncmacro.dap.protocol import MessageWriter
from cncmacro.dap.session import Session


def filters(locale: str | None) -> list[tuple[str, str, str]]:
    args: dict[str, Any] = {"adapterID": "cnc-macro"}
    if locale is not None:
        args["locale"] = locale
    body = Session(MessageWriter(io.BytesIO())).on_initialize(args)
    return [(f["filter"], f["label"], f["description"]) for f in body["exceptionBreakpointFilters"]]


def test_the_exception_filters_are_named_in_chinese_under_a_chinese_locale() -> None:
    assert filters("zh-cn") == [
        ("alarms", "所有报警", "程序发出报警时停止（#3000、除数为零等）"),
        ("messages", "#3006 信息", "在 #3006 操作信息和 M00 处停止"),
    ]
    assert [label for _, label, _ in filters("zh-CN")] == ["所有报警", "#3006 信息"]  # any zh locale, any case


def test_in_english_they_keep_their_names() -> None:
    assert (
        filters("en")
        == filters(None)
        == [
            ("alarms", "All alarms", "Stop when the program raises an alarm (#3000, division by zero, ...)"),
            ("messages", "#3006 messages", "Stop at #3006 operator messages and M00"),
        ]
    )
