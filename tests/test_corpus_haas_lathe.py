"""The Haas lathe corpus (tests/corpus/haas-lathe): shop programs of a Haas ST lathe with its
one-block cycles and macros. ``cncmacro check`` finds nothing in them (no error, warning or
information), every main program runs to completion in a time a lathe could take (10 s to
30 min, some cutting) and does what its programmer meant; O10011's time is worked out by hand.

haas-lathe's timing: rapids 24,000 mm/min on X (of the radius) and Z, a turret index 0.5 s."""

from __future__ import annotations

import io
import json
import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from cncmacro.cli.check import check_paths
from test_corpus import CORPUS, run, var

HAAS_T = CORPUS / "haas-lathe"


def passes(r: dict[str, Any], code: str, mode: str | None = None) -> list[dict[str, Any]]:
    return [m for m in r["moves"] if m.get("pass_of") == code and (mode is None or m["mode"] == mode)]


def check_o10001(r: dict[str, Any]) -> None:
    rough = passes(r, "G71", "G01")
    assert min(m["to"]["X"] for m in rough) == pytest.approx(24.0 - 1.0 + 0.4)  # the chamfer's start + U0.4
    levels = sorted({round(m["from"]["X"], 3) for m in rough if m["from"]["X"] == m["to"]["X"]}, reverse=True)
    assert {33.0, 30.0, 27.0} <= set(levels)  # D1.5 a radius: 3 mm of diameter a level from X36


def check_o10002(r: dict[str, Any]) -> None:
    threads = passes(r, "G76", "G32")
    # the last pass at the minor diameter, written to 0.001 mm (X#5: 18.1598 is X18.160)
    assert threads[-1]["to"]["X"] == pytest.approx(20.0 - 2 * 0.6134 * 1.5, abs=0.001)
    assert threads[0]["to"]["X"] == pytest.approx(20.0 - 2 * 0.3)  # the first at D0.3


def check_o10003(r: dict[str, Any]) -> None:
    cuts = [m for m in r["moves"] if m["mode"] == "G92"]
    assert cuts[-1]["to"]["X"] == pytest.approx(13.55) and cuts[-2]["to"]["X"] == pytest.approx(13.55)
    assert cuts[0]["to"]["X"] == pytest.approx(15.6)


def check_o10004(r: dict[str, Any]) -> None:
    pecks = passes(r, "G75", "G01")
    assert {round(m["to"]["Z"], 3) for m in pecks} == {-12.0, -14.5, -17.0, -19.5, -20.0, -32.0}
    assert min(m["to"]["X"] for m in pecks) == pytest.approx(24.0)


def check_o10005(r: dict[str, Any]) -> None:
    assert var(r, 500) == 1.0
    assert any(m["mode"] == "G01" and m["to"]["X"] == pytest.approx(1.0) for m in r["moves"])  # parted off


def check_o10006(r: dict[str, Any]) -> None:
    assert len([m for m in r["moves"] if m["mode"] == "G90"]) == 2 * 4  # two passes for each of four parts


def check_o10007(r: dict[str, Any]) -> None:
    ends = [m["to"]["Z"] for m in r["moves"] if m["mode"] == "G01" and m["from"]["X"] == m["to"]["X"]]
    assert {-15.0, -20.0, -25.0} <= {round(z, 3) for z in ends}  # each pin to its length B


def check_o10008(r: dict[str, Any]) -> None:
    grooves = [m["from"]["Z"] for m in r["moves"] if m["mode"] == "G01"]
    assert grooves == pytest.approx([-8.0, -18.0, -28.0])  # M97 P100 L3: three grooves 10 mm apart


def check_o10009(r: dict[str, Any]) -> None:
    levels = sorted({round(m["to"]["Z"], 3) for m in passes(r, "G72", "G01") if m["from"]["Z"] == m["to"]["Z"]})
    assert levels[:2] == [-5.9, -5.0]  # D1: a level each mm, the deepest at the face -6 + W0.1


def check_o10010(r: dict[str, Any]) -> None:
    pecks = passes(r, "G74", "G01")
    assert min(m["to"]["Z"] for m in pecks) == pytest.approx(-30.0) and all(m["to"]["X"] == 0.0 for m in pecks)


def check_o10011(r: dict[str, Any]) -> None:
    # G97 S900, F0.25 per revolution: 225 mm/min. From X0 Z0 (the turret index 0.5 s first):
    #   G00 X52 Z2: 26 mm of radius at 24,000 mm/min = 0.065 s
    #   each G90 pass to X48, X46, X44 with I-1.5: in at rapid to X - 3 (3.5, 4.5, 5.5 mm of radius),
    #   the taper cut sqrt(1.5^2 + 32^2) = 32.0351 mm = 8.5427 s, out to X52 at the feed (2, 3, 4 mm:
    #   0.5333, 0.8, 1.0667 s), back 32 mm at rapid 0.08 s
    #   G00 X150 Z100: 98 mm of Z = 0.245 s
    taper = math.hypot(1.5, 32.0) / 225 * 60
    passes_s = sum(r_in / 24000 * 60 + taper + out / 225 * 60 + 0.08 for r_in, out in ((3.5, 2), (4.5, 3), (5.5, 4)))
    assert r["cycle"]["seconds"] == pytest.approx(0.5 + 0.065 + passes_s + 0.245, rel=1e-3)  # 29.11 s
    starts = [m["legs"][0]["to"]["X"] for m in r["moves"] if m["mode"] == "G90"]
    assert starts == pytest.approx([45.0, 43.0, 41.0])


def check_o10012(r: dict[str, Any]) -> None:
    faces = [m["to"]["Z"] for m in r["moves"] if m["mode"] == "G94"]
    assert faces == pytest.approx([-1.0, -2.0, -3.0, -4.0])


def check_o10013(r: dict[str, Any]) -> None:
    assert var(r, 2701) == pytest.approx(-0.024)  # measured 30.024 against 30: the X wear takes -0.024


def check_o10014(r: dict[str, Any]) -> None:
    # G42 with #2201 = 0.4: the nose centre runs 0.4 off the part, X30 + 2 x 0.4 = X30.8 at the fillet's start,
    # and round the R3 fillet (its centre outside the part) on a radius of 3 - 0.4 = 2.6: to Z-15 - 2.6
    [arc] = [m for m in r["moves"] if m["mode"] == "G02"]
    assert arc["tool_path"]["from"]["X"] == pytest.approx(30.8)
    assert arc["tool_path"]["pieces"][-1]["to"]["Z"] == pytest.approx(-17.6)


def check_o10015(r: dict[str, Any]) -> None:
    bore = passes(r, "G71", "G01")
    assert bore and max(m["to"]["X"] for m in bore) == pytest.approx(26.0 - 0.4)  # U-0.4 leaves stock in the bore


def check_o10016(r: dict[str, Any]) -> None:
    # I3 relief in four passes: 3, 2, 1, 0 on the radius, so the shape's first X20 (+ U0.4) starts each
    # pass at 26.4, 24.4, 22.4, 20.4
    starts = [m["to"]["X"] for m in passes(r, "G73", "G00") if m["from"]["X"] == pytest.approx(62.0)]
    assert starts == pytest.approx([26.4, 24.4, 22.4, 20.4])
    assert len([m for m in r["moves"] if m["mode"] == "G03" and m.get("pass_of") is None]) == 1  # G70: the R6 dome


MAINS: dict[Path, Callable[[dict[str, Any]], None]] = {
    HAAS_T / f"O{10000 + n}.nc": check for n, check in enumerate(
        (check_o10001, check_o10002, check_o10003, check_o10004, check_o10005, check_o10006, check_o10007,
         check_o10008, check_o10009, check_o10010, check_o10011, check_o10012, check_o10013, check_o10014,
         check_o10015, check_o10016), start=1)
}  # fmt: skip


@pytest.mark.parametrize("path", list(MAINS), ids=lambda p: p.name)
def test_haas_lathe_program_runs_in_a_plausible_time_and_does_what_it_means(path: Path) -> None:
    r = run(path)
    assert r["lathe"] is True and r["dialect"] == "haas-lathe"
    assert 10.0 <= r["cycle"]["seconds"] <= 30 * 60 and r["cycle"]["cut"] > 0
    MAINS[path](r)


def test_haas_lathe_corpus_checks_clean() -> None:
    out, err = io.StringIO(), io.StringIO()
    status = check_paths([str(HAAS_T)], out, err, "json")
    assert json.loads(out.getvalue()) == [] and status == 0 and err.getvalue() == ""


def test_haas_lathe_corpus_holds_fifteen_programs() -> None:
    assert len(MAINS) >= 15 and all(p.exists() for p in MAINS)
