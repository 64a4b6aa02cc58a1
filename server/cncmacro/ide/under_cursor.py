"""What the cursor is on, for the features that act on a name: an N label or a jump's number,
or a program (an O header's number, or the word of a call that names a program)."""

from __future__ import annotations

from collections.abc import Mapping

from ..analysis.indexes.call_sites import call_site
from ..library.machine_file import CallCode
from ..syntax.nodes import Block
from .source import EditorDocument


def label_under(doc: EditorDocument, block: Block, column: int) -> tuple[int, int, int, str] | None:
    """(label number, start, end, kind) when code-point ``column`` of ``block`` is on an N label
    or a jump's number."""
    if block.label is not None and block.label_span and block.label_span[0] <= column <= block.label_span[1]:
        return block.label, block.label_span[0], block.label_span[1], "N"
    for j in doc.sites.jumps_of(block):
        if j.start <= column <= j.end:
            return j.label, j.start, j.end, j.kind
    return None


def program_under(
    doc: EditorDocument, block: Block, column: int, calls: Mapping[str, CallCode] | None
) -> tuple[int, bool] | None:
    """(program number, whether a call names it) when ``column`` of ``block`` is on an O
    header's number or on the word of a call that names its program by number
    (``call_sites.call_site``: ``M98 P30040`` names O0040); ``calls`` are the machine file's
    call codes."""
    if block.program is not None and block.program_span and block.program_span[0] <= column <= block.program_span[1]:
        return block.program, False
    site = call_site(block, doc.dialect, calls)
    if site is not None and site.target.start <= column <= site.target.end and site.number is not None:
        return site.number, True
    return None
