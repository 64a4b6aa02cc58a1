"""The static checks pass over a plain line (``Block.plain``) at once unless it may hold a word
they look at; the quick look must never pass over a line the full pattern would look at
(a call, an unknown G code, an M code with a decimal point, a machine file's call code)."""

from __future__ import annotations

import re

from hypothesis import given, settings
from hypothesis import strategies as st

from cncmacro.analysis.line_facts import _plain_hint, _plain_pattern
from cncmacro.dialects import BY_NAME
from cncmacro.library.machine_file import CallCode, MachineSettings

_word = st.tuples(
    st.sampled_from("GgMmXYZFSTNPQ"),
    st.sampled_from(["", "+", "0", "00"]),
    st.sampled_from(["0", "1", "2", "3", "4", "17", "28", "65", "66", "97", "98", "99", "198", "1.5", "2.0", "3."]),
).map("".join)
_line = st.lists(_word, min_size=1, max_size=5).flatmap(
    lambda words: st.sampled_from([" ", "\t", ""]).map(lambda sep: sep.join(words))
)


@settings(max_examples=400, deadline=None)
@given(_line, st.sampled_from(sorted(BY_NAME)), st.sampled_from([{}, {"G150": 9150}, {"M100": 9100}, {"T": 9000}]))
def test_a_plain_line_the_checks_look_at_is_never_passed_over(line, dialect, calls):
    machine = MachineSettings(calls={code: CallCode(number) for code, number in calls.items()})
    profile = BY_NAME[dialect]
    full = re.compile(_plain_pattern(machine, profile)).search
    if full(line):
        assert _plain_hint(machine, profile)(line), line
