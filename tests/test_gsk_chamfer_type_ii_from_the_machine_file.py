"""The GSK980TDi's chamfer word L of type II (manual §3.11.1: "两种类型可由状态参数№181.0 进行设置选择
… Ⅱ型代表 L 为倒角点与交叉点间的长度", the two types are chosen by state parameter №181.0; type II: L
is the distance from each chamfer point to the intersection; docs/semantics.md §10.1): the machine
file's ``chamfer_type = "II"`` cuts L as FANUC's ``,C``, each end L from the corner. Type I (L the
chamfer's own length) stays the default. Before, the machine file had no such key and L was
always type I."""

from __future__ import annotations

from math import sqrt
from pathlib import Path

import pytest

from cli_capture import run_json
from cncmacro.library.machine_file import MachineFileError, settings_from_mapping
from running import lines

PROGRAM = lines("O0004", "T0101", "G98 M03 S500", "G0 X0 Z2", "G01 Z0 F100", "X40 L2", "Z-20", "M30")


def _cuts(tmp_path: Path, machine: str) -> list[tuple[float, float, float]]:
    result = run_json(tmp_path, PROGRAM, "O0004.nc", machine)
    return [(round(mv["to"]["X"], 6), round(mv["to"]["Z"], 6), round(mv["time"], 6))
            for mv in result["moves"] if mv["kind"] != "rapid"]  # fmt: skip


def test_10_lathe_gsk_l_of_type_ii_is_the_distance_from_the_intersection(tmp_path: Path) -> None:
    # L2 between +X and -Z at the corner X40 Z0 (radius 20): each end 2 from the corner, X(20-2)·2 =
    # X36 Z0 and X40 Z-2; the chamfer 2·√2 = 2.828427 mm long. At 100 mm/min (0.6 s a mm): Z 2 mm
    # 1.2 s; X 18 mm 10.8 s; the chamfer 1.697056 s; Z 18 mm 10.8 s
    cuts = _cuts(tmp_path, 'base = "gsk980tdi"\nchamfer_type = "II"\n')
    assert cuts == [(0.0, 0.0, 1.2), (36.0, 0.0, 10.8), (40.0, -2.0, round(2.0 * sqrt(2.0) * 0.6, 6)),
                    (40.0, -20.0, 10.8)]  # fmt: skip


def test_10_lathe_gsk_l_of_type_i_stays_the_default(tmp_path: Path) -> None:
    # type I: the chamfer itself 2 long, its ends √2 from the corner: X(20-√2)·2 = X37.171573, Z-1.414214
    d = sqrt(2.0)
    cuts = _cuts(tmp_path, 'base = "gsk980tdi"\nchamfer_type = "I"\n')
    assert [c[:2] for c in cuts] == [(0.0, 0.0), (round(40.0 - 2.0 * d, 6), 0.0), (40.0, round(-d, 6)), (40.0, -20.0)]


def test_the_key_takes_i_or_ii_and_only_a_profile_with_the_chamfer_word_l() -> None:
    assert settings_from_mapping({"base": "gsk980tdi", "chamfer_type": "II"}).chamfer_type == "II"
    with pytest.raises(MachineFileError, match='must be "I" or "II"'):
        settings_from_mapping({"base": "gsk980tdi", "chamfer_type": 2})
    with pytest.raises(MachineFileError, match="no chamfer word L"):
        settings_from_mapping({"base": "fanuc-0i-lathe", "chamfer_type": "II"})
