"""Hypothesis strategies that write program lines: valid ones, nearly valid ones and noise."""

from __future__ import annotations

from functools import cache

from hypothesis import strategies as st

from cncmacro.syntax.keywords import ABBREVIABLE

SPACE = st.sampled_from(["", "", " ", "  ", "\t"])
FUNCS = ["SIN", "COS", "TAN", "ASIN", "ACOS", "SQRT", "ABS", "LN", "EXP", "ROUND", "FIX", "FUP", "BIN", "BCD"]
RELOPS = ["EQ", "NE", "GT", "GE", "LT", "LE", "==", "!=", "<>", "<", ">", "<=", ">="]
BINOPS = ["+", "-", "*", "/", "AND", "OR", "XOR", "MOD", "&&", "||"]


@st.composite
def _case(draw, word: str) -> str:
    """A macro word as programs write it: mostly whole, sometimes lower case or shortened to its
    first two or more letters (the FANUC abbreviations, keywords.py)."""
    if word in ABBREVIABLE and draw(st.integers(0, 3)) == 0:
        word = word[: draw(st.integers(2, len(word) - 1))]
    return word.lower() if draw(st.integers(0, 5)) == 0 else word


@st.composite
def number(draw) -> str:
    whole = draw(st.integers(0, 99999))
    form = draw(st.integers(0, 3))
    if form == 0:
        return str(whole)
    if form == 1:
        return f"{whole}."
    if form == 2:
        return f".{draw(st.integers(0, 999))}"
    return f"{whole}.{draw(st.integers(0, 9999))}"


def _join(draw, parts: list[str]) -> str:
    out = ""
    for p in parts:
        out += draw(SPACE) + p
    return out


@cache
def expr(max_leaves: int = 8) -> st.SearchStrategy[str]:
    """An expression of at most ``max_leaves`` numbers and variables. Built once for each size:
    a strategy is reusable, and building and validating a recursive one anew for every draw
    costs more than the draw."""
    atoms = st.one_of(number(), st.integers(0, 9999).map(lambda n: f"#{n}"))

    def extend(inner: st.SearchStrategy[str]) -> st.SearchStrategy[str]:
        return st.one_of(
            st.tuples(inner, st.sampled_from(BINOPS).flatmap(_case), inner, SPACE, SPACE).map(
                lambda t: f"{t[0]}{t[3]}{t[1]}{t[4]}{t[2]}"
            ),
            inner.map(lambda e: f"[{e}]"),
            inner.map(lambda e: f"-{e}"),
            inner.map(lambda e: f"#[{e}]"),
            st.tuples(st.sampled_from(FUNCS).flatmap(_case), inner).map(lambda t: f"{t[0]}[{t[1]}]"),
            st.tuples(_case("ATAN"), inner, inner).map(lambda t: f"{t[0]}[{t[1]}]/[{t[2]}]"),
            st.tuples(inner, st.sampled_from(RELOPS), inner).map(lambda t: f"[{t[0]} {t[1]} {t[2]}]"),
        )

    return st.recursive(atoms, extend, max_leaves=max_leaves)


@st.composite
def condition(draw) -> str:
    left, right = draw(expr(4)), draw(expr(4))
    rel = draw(st.sampled_from(RELOPS))
    single = f"[{left}{draw(SPACE)}{rel}{draw(SPACE)}{right}]"
    if draw(st.booleans()):
        return single
    other = f"[{draw(expr(3))} {draw(st.sampled_from(RELOPS))} {draw(expr(3))}]"
    return f"[{single} {draw(st.sampled_from(['AND', 'OR', 'XOR', '&&', '||']))} {other}]"


@st.composite
def word(draw) -> str:
    letter = draw(st.sampled_from("ABCDEFGHIJKLMPQRSTUVWXYZ"))
    if draw(st.integers(0, 9)) == 0:  # a corner word: ,C chamfer, ,R corner radius, ,A angle
        letter = "," + draw(SPACE) + draw(st.sampled_from("ACRacr"))
    kind = draw(st.integers(0, 5))
    if kind == 0:
        value = draw(number())
    elif kind == 1:
        value = draw(st.sampled_from("+-")) + draw(number())
    elif kind == 2:
        value = draw(st.sampled_from(["", "-"])) + f"#{draw(st.integers(0, 999))}"
    elif kind == 3:
        value = f"[{draw(expr(4))}]"
    elif kind == 4:
        value = draw(st.sampled_from(["[CUT]", "[螺纹切削]", "[O1004]", "[#100]", "[T123]"]))
    else:
        value = draw(number())
    return letter + draw(SPACE) + value


@st.composite
def statement(draw) -> str:
    kind = draw(st.integers(0, 8))
    var = draw(st.sampled_from(["#1", "#100", "#[#2+1]", "#3000", "#9100"]))
    if kind == 0:
        return _join(draw, [var, "=", draw(expr())])
    if kind == 1:
        target = draw(st.sampled_from(["10", "#5", "[#1+2]"]))
        return _join(draw, [draw(_case("IF")), draw(condition()), draw(_case("GOTO")), target])
    if kind == 2:
        return _join(draw, [draw(_case("IF")), draw(condition()), draw(_case("THEN")), var, "=", draw(expr(4))])
    if kind == 3:
        return _join(draw, [draw(_case("WHILE")), draw(condition()), draw(_case("DO")), str(draw(st.integers(0, 4)))])
    if kind == 4:
        return _join(draw, [draw(st.sampled_from(["DO", "END"]).flatmap(_case)), str(draw(st.integers(1, 3)))])
    if kind == 5:
        return _join(draw, [draw(_case("GOTO")), draw(st.sampled_from(["10", "#1", "[#2*10]"]))])
    if kind == 6:  # THEN left out (docs/semantics.md §4)
        return _join(draw, [draw(_case("IF")), draw(condition()), var, "=", draw(expr(4))])
    if kind == 7:  # Haas's conditional M99 (docs/semantics.md §4)
        target = draw(st.sampled_from(["10", "#5", "[#1+2]"]))
        return _join(draw, [draw(condition()), draw(_case("M")) + "99", draw(_case("P")) + target])
    return draw(_case(draw(st.sampled_from(["POPEN", "PCLOS", "DPRNT"])))) + (
        "[X#2[53]**Y#5[53]]" if draw(st.booleans()) else ""
    )


@st.composite
def line(draw) -> str:
    """A block, usually valid, sometimes with a label, a comment, a ';' or noise."""
    parts: list[str] = []
    if draw(st.integers(0, 9)) == 0:
        parts.append(draw(st.sampled_from(["/", "/2"])))
    if draw(st.integers(0, 4)) == 0:
        parts.append(f"N{draw(st.integers(1, 99999))}")
    shape = draw(st.integers(0, 3))
    if shape == 0:
        parts += draw(st.lists(word(), min_size=1, max_size=6))
    elif shape == 1:
        parts.append(draw(statement()))
    elif shape == 2:
        parts += draw(st.lists(word(), min_size=1, max_size=3))
        parts.append(draw(statement()))
    else:
        parts.append(draw(st.text(alphabet="GXYZN#[]+-*/=0123456789. ANDORIFGOTOWHILE;(),", max_size=30)))
    text = "".join(draw(SPACE) + p for p in parts)
    if draw(st.integers(0, 5)) == 0:
        text += draw(st.sampled_from([";", " (COMMENT)", "(注释)", ";(X)", " (OPEN"]))
    return text


@st.composite
def plain_number(draw) -> str:
    """A number as a CAM program writes it after an address: codes near those the controls call,
    end and refuse (0-3, 65, 97-99, 198, ...), leading zeros, a sign, up to three decimals."""
    whole = draw(st.one_of(st.integers(0, 12), st.sampled_from([28, 30, 54, 65, 66, 80, 81, 97, 98, 99, 100, 150,
                                                                198, 999]), st.integers(0, 9999)))  # fmt: skip
    text = "0" * draw(st.integers(0, 2)) + str(whole)
    form = draw(st.integers(0, 4))
    if form == 1:
        text += "."
    elif form == 2:
        text += "." + draw(st.sampled_from(["0", "00", "1", "4", "5", "6", "9", "04", "95", "999"]))
    elif form == 3:
        text = "." + draw(st.sampled_from(["5", "4", "05", "999"]))
    return draw(st.sampled_from(["", "", "", "+", "-"])) + text


@st.composite
def plain_line(draw) -> str:
    """A line of plain words (``Block.plain``: addresses and numbers only, not starting with N
    or O), as a CAM program writes them, with blanks or tabs between the words."""
    first = draw(st.sampled_from("ABCDEFGHIJKLMPQRSTUVWXYZabcdefghijklmpqrstuvwxyz"))
    letters = draw(st.lists(st.sampled_from("GGGMMMTPQLHXYZFSRIJKDUVWABC"), max_size=5))
    words = [f"{letter}{draw(plain_number())}" for letter in [first, *letters]]
    gaps = [draw(st.sampled_from([" ", " ", "  ", "\t"])) for _ in words[1:]]
    return words[0] + "".join(g + w for g, w in zip(gaps, words[1:], strict=True))
