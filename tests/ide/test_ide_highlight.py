"""Document highlight without a server: on a variable its writes and reads (a local only within
its program), on a label or a jump the label and its jumps, on a program's header or a call of
it the header and its calls; elsewhere nothing."""

from __future__ import annotations

from cncmacro.ide.highlight import Highlight, highlights

from .documents import document

DOC = document(
    "O0001",  # 0
    "#100=1",  # 1
    "N10 #100=#100+1",  # 2
    "IF[#100 LT 5] GOTO10",  # 3
    "M98 P0002",  # 4
    "M30",  # 5
    "O0002",  # 6
    "#1=2",  # 7
    "M99",  # 8
)


def _marks(found: list[Highlight] | None) -> list[tuple[int, int, int, str]] | None:
    if found is None:
        return None
    return [(h.span.line, h.span.start, h.span.end, "write" if h.write else "read") for h in found]


def test_a_variable_marks_its_writes_and_its_reads() -> None:
    assert _marks(highlights(DOC, 3, 4)) == [  # on the #100 of IF[#100 LT 5]
        (1, 0, 4, "write"),
        (2, 4, 8, "write"),
        (2, 9, 13, "read"),
        (3, 3, 7, "read"),
    ]


def test_a_local_variable_is_marked_only_within_its_program() -> None:
    doc = document("O0001", "#1=5", "M98 P0002", "M30", "O0002", "#2=#1", "M99")
    assert _marks(highlights(doc, 5, 4)) == [(5, 3, 5, "read")]


def test_a_label_and_a_jump_to_it_mark_the_label_and_every_jump() -> None:
    both = [(2, 0, 3, "write"), (3, 18, 20, "read")]
    assert _marks(highlights(DOC, 2, 1)) == both  # on N10
    assert _marks(highlights(DOC, 3, 19)) == both  # on the 10 of GOTO10


def test_a_program_header_and_a_call_of_it_mark_the_header_and_every_call() -> None:
    both = [(4, 4, 9, "read"), (6, 0, 5, "write")]
    assert _marks(highlights(DOC, 6, 2)) == both  # on O0002
    assert _marks(highlights(DOC, 4, 6)) == both  # on P0002


def test_nothing_is_marked_on_a_word_that_names_nothing() -> None:
    assert highlights(DOC, 5, 1) is None  # M30
    assert highlights(DOC, 40, 0) is None  # past the end
