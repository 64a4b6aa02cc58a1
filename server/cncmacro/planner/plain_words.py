"""Reading a plain motion line once: which words it holds and what each does (docs/semantics.md §8).

A plain line (``G01 X12.5 Y-3. F200``) only sets modal codes of groups without side effects, F
and S, and moves axes, an arc's R, I, J, K included. ``PlainWords`` decides such a line once into
a ``PlainPlan`` (``text_plan`` for a ``Block.plain`` line kept as text, ``plan`` for literal words
read by the grammar), which ``Planner.run_plain`` carries out each time the line runs; and it
gives ``machine/straight_runs.py`` the letter codes (``kinds``) and G word lookups it reads many
lines with. A line it declines (None) goes the general way, ``Planner.execute_nc``.
"""

from __future__ import annotations

from string import ascii_letters
from typing import TYPE_CHECKING

from ..dialects.dialect import last_address_key

if TYPE_CHECKING:
    from ..dialects import Dialect
    from ..library.machine_file import MachineSettings

_Words = tuple[tuple[str, float], ...]  # (letter or group, value)
_Axes = tuple[tuple[int, float], ...]  # (axis index, value)
# a block of plain motion decided once: modal settings (group, G), F and S, absolute axes
# (index, value), incremental axes, and the arc words R I J K
PlainPlan = tuple[_Words, _Words, _Axes, _Axes, _Words]
# a plan with the file and the next line appended, as a plain line's runner holds it
PlainRun = tuple[_Words, _Words, _Axes, _Axes, _Words, str, int]
# G20/G21 too: a change of the unit is looked at in one place (units.py); G40/G41/G42 start and
# cancel cutter radius compensation (cutter_stage.py)
# the groups whose codes take axis words as values, not a move (``Planner.execute_nc``): the stored
# stroke check's limits (G22), the centre of a rotation (G68), of a scaling (G51) or of a mirror
# image (G51.1); such a line is not plain motion
VALUE_GROUPS = frozenset(("stroke", "rotation", "scaling", "mirror"))
# (``spindle``: a lathe's G96/G97 decides the S a block without one turns at: spindle_modes.py)
NOT_PLAIN_GROUPS = frozenset(("macro", "canned", "wcs", "length", "units", "cutter", "spindle", *VALUE_GROUPS))
CANCEL_CYCLE = ("canned", 80.0)  # on a mill, G00-G03 cancel a drilling cycle (group 01 over group 09)
_CENTRE_LETTERS = frozenset("RIJK")  # arc radius and centre: kept for a canned cycle's R level
_G_WORDS_KEPT = 1000  # spellings of G words ``g_word`` keeps
# ``kinds``'s codes: an absolute axis's is its index (below PLAIN_INCREMENTAL), so that the
# common word, an axis, is told by one comparison; the others come after
PLAIN_INCREMENTAL = 32  # plus the axis index: an incremental letter (U, V, W on a lathe)
PLAIN_G = 64
PLAIN_F = 65
PLAIN_S = 66
PLAIN_ARC_LETTERS = {67: "R", 68: "I", 69: "J", 70: "K"}  # the arc's radius and centre words
NOT_PLAIN = 99  # a letter a plain motion line cannot hold


class PlainWords:
    """The plain-line reading of one machine (module docstring)."""

    def __init__(
        self, dialect: Dialect, settings: MachineSettings, g_groups: dict[float, str], axis_index: dict[str, int]
    ) -> None:
        self.dialect = dialect
        self.settings = settings
        self.g_groups = g_groups
        self.axis_index = axis_index
        self._drills = dialect.drills
        self._kinds: dict[str, int] | None = None
        self._groups: dict[float, str] | None = None
        self._g_words: dict[str, tuple[str, float]] = {}
        # letter -> where its last value is kept, for the letters the profile's address
        # variables read (``Dialect.last_address_letters``; empty on FANUC and GSK)
        self.last_keys = {letter: last_address_key(letter) for letter in dialect.last_address_letters}

    def text_plan(self, text: str) -> PlainPlan | None:
        """``plan`` read straight from a ``Block.plain`` line: whitespace-separated
        address-number words with at most three decimals, so that a literal axis value is
        already on the grid (docs/semantics.md §2). None when the line is not plain motion or its
        values need the general rounding (increment input mode, S with a fraction)."""
        kinds = self.kinds()
        if not kinds:
            return None
        modal: list[tuple[str, float]] = []
        codes: list[tuple[str, float]] = []
        axes: list[tuple[int, float]] = []
        inc: list[tuple[int, float]] = []
        extra: list[tuple[str, float]] = []
        groups = self.g_groups_plain()
        for word in text.split():
            kind = kinds[word[0]]
            if kind == NOT_PLAIN:
                return None
            v = float(word[1:])
            if kind < PLAIN_INCREMENTAL:
                axes.append((kind, v))
            elif kind < PLAIN_G:
                inc.append((kind - PLAIN_INCREMENTAL, v))
            elif kind == PLAIN_G:
                group = groups.get(v)
                if group is None:
                    return None
                modal.append((group, v))
                if group == "motion" and self._drills:
                    modal.append(CANCEL_CYCLE)
            elif kind == PLAIN_F:
                codes.append(("F", v))
            elif kind == PLAIN_S:
                if v % 1:
                    return None
                codes.append(("S", v))
            else:
                extra.append((PLAIN_ARC_LETTERS[kind], v))
            if self.last_keys:
                self._keep_last(word[0].upper(), v, codes)
        return tuple(modal), tuple(codes), tuple(axes), tuple(inc), tuple(extra)

    def _keep_last(self, letter: str, v: float, codes: list[tuple[str, float]]) -> None:
        """Add the last value of ``letter`` to a plan's codes when the profile's address
        variables read it (``last_keys``)."""
        key = self.last_keys.get(letter)
        if key is not None:
            codes.append((key, v))

    def g_groups_plain(self) -> dict[float, str]:
        """G code -> modal group, for the G codes a plain line may carry: those of a modal
        group without side effects beyond the group, and not configured to call a program."""
        groups = self._groups
        if groups is None:
            calls = self.settings.calls
            groups = self._groups = {
                g: group
                for g, group in self.g_groups.items()
                if group and group not in NOT_PLAIN_GROUPS and f"G{g:g}" not in calls
            }
        return groups

    def g_words(self) -> dict[str, tuple[str, float]]:
        """G word as written (``G01``, ``g1``) -> its ``g_groups_plain`` group ("" for none)
        and its value, for each one ``g_word`` has read: a plain line's G word is looked up,
        not read again (reading a number costs more than the rest of the word)."""
        return self._g_words

    def g_word(self, word: str) -> tuple[str, float]:
        """Read G word ``word`` for ``g_words``, and keep it there (while it holds fewer than
        ``_G_WORDS_KEPT``: a program can spell one code many ways)."""
        v = float(word[1:])
        read = (self.g_groups_plain().get(v, ""), v)
        if len(self._g_words) < _G_WORDS_KEPT:
            self._g_words[word] = read
        return read

    def kinds(self) -> dict[str, int]:
        """Every ASCII letter (either case) -> its code: an axis's index, ``PLAIN_INCREMENTAL``
        plus the index for an incremental letter, ``PLAIN_G``, ``PLAIN_F``, ``PLAIN_S``, a key
        of ``PLAIN_ARC_LETTERS`` for R, I, J, K, and ``NOT_PLAIN`` for the others (a
        ``Block.plain`` word starts with an ASCII letter, so looking it up never misses). Empty
        in increment input mode, where a value without a point counts least increments, and
        for a machine of more axes than the codes leave room for."""
        kinds = self._kinds
        if kinds is not None:
            return kinds
        if self.settings.decimal_point == "increment" or len(self.axis_index) > PLAIN_INCREMENTAL:
            kinds = self._kinds = {}
            return kinds
        kinds = dict.fromkeys(ascii_letters, NOT_PLAIN)
        codes = {"G": PLAIN_G, "F": PLAIN_F, "S": PLAIN_S, **{c: k for k, c in PLAIN_ARC_LETTERS.items()}}
        codes.update(self.axis_index)
        for letter, axis in self.dialect.incremental_letters.items():
            if axis in self.axis_index:
                codes[letter] = PLAIN_INCREMENTAL + self.axis_index[axis]
        for letter, code in codes.items():
            kinds[letter] = kinds[letter.lower()] = code
        self._kinds = kinds
        return kinds

    def plan(self, words: list[tuple[str, float]]) -> PlainPlan | None:
        """For a block of literal words that only sets modal codes, F or S and moves axes:
        (modal settings, codes, absolute axes, incremental axes, arc words R I J K), decided
        once; None for anything else (one-shot G codes, canned cycles, tools), which
        ``Planner.execute_nc`` does."""
        modal: list[tuple[str, float]] = []
        codes: list[tuple[str, float]] = []
        axes: list[tuple[int, float]] = []
        inc: list[tuple[int, float]] = []
        extra: list[tuple[str, float]] = []
        axis_index = self.axis_index
        inc_letters = self.dialect.incremental_letters
        for letter, v in words:
            if letter == "G":
                group = self.g_groups.get(v)
                if not group or group in NOT_PLAIN_GROUPS:
                    return None
                modal.append((group, v))
                if group == "motion" and self._drills:
                    modal.append(CANCEL_CYCLE)
            elif letter in axis_index:
                axes.append((axis_index[letter], v))
            elif letter in inc_letters and inc_letters[letter] in axis_index:
                inc.append((axis_index[inc_letters[letter]], v))
            elif letter in ("F", "S"):
                codes.append((letter, v))
            elif letter in _CENTRE_LETTERS:
                extra.append((letter, v))
            else:
                return None
            if self.last_keys:
                self._keep_last(letter, v, codes)
        return tuple(modal), tuple(codes), tuple(axes), tuple(inc), tuple(extra)


_SHARED_KEPT = 8  # machines whose reading ``shared_plain_words`` keeps
_shared: dict[tuple[int, int], PlainWords] = {}


def shared_plain_words(
    dialect: Dialect, settings: MachineSettings, g_groups: dict[float, str], axis_index: dict[str, int]
) -> PlainWords:
    """The ``PlainWords`` of a machine of ``dialect`` and ``settings``, shared by each run of it: a
    reading is decided by the profile and the machine file alone, and what it learns (the G
    words' spellings) holds for any run. ``g_groups`` and ``axis_index`` are those the planner
    derives from the two. A check of thousands of small files makes one, not one a file."""
    key = (id(dialect), id(settings))
    found = _shared.get(key)
    if found is not None and found.dialect is dialect and found.settings is settings:
        return found
    if len(_shared) >= _SHARED_KEPT:
        _shared.pop(next(iter(_shared)))
    made = _shared[key] = PlainWords(dialect, settings, g_groups, axis_index)
    return made
