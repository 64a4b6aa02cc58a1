"""The concrete example blocks of the controller manuals, as printed.

Each entry is (seed, where in the manual, dialect, block). Format templates with placeholders
(□, ○, ``P_``, ``#i``, ``Hm``) are not programs and are left out. Seed 003's text lost its
``=`` signs and some brackets in extraction; its examples are listed separately with them
restored as the thesis writes them in words.
"""

from __future__ import annotations

_G = "gsk980tdi"
_F = "fanuc"

SEED_BLOCKS: list[tuple[str, str, str, str]] = [
    # seed 000 §3.28.1 variable references
    ("000", "3.28.1 address substitution", _G, "F#103"),
    ("000", "3.28.1 address substitution", _G, "Z-#110"),
    ("000", "3.28.1 variable-number substitution", _G, "X#9100"),
    ("000", "3.28.1 variable-number substitution", _G, "X-#9100"),
    ("000", "3.28.1 vacant reference", _G, "G00 X100 Z#1"),
    ("000", "3.28.1 vacant reference", _G, "G00 X100 Z0"),
    ("000", "3.28.1 vacant arithmetic", _G, "#2=#1"),
    ("000", "3.28.1 vacant arithmetic", _G, "#2=#1 * 5"),
    ("000", "3.28.1 vacant arithmetic", _G, "#2=#1+#1"),
    # seed 000 §3.28.2 G65 H-code examples
    ("000", "3.28.2 H01", _G, "G65 H01 P#101 Q1005;"),
    ("000", "3.28.2 H01", _G, "G65 H01 P#101 Q#110;"),
    ("000", "3.28.2 H01", _G, "G65 H01 P#101 Q-#102;"),
    ("000", "3.28.2 H02", _G, "G65 H02 P#101 Q#102 R15;"),
    ("000", "3.28.2 H03", _G, "G65 H03 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H04", _G, "G65 H04 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H05", _G, "G65 H05 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H11", _G, "G65 H11 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H12", _G, "G65 H12 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H13", _G, "G65 H13 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H21", _G, "G65 H21 P#101 Q#102;"),
    ("000", "3.28.2 H22", _G, "G65 H22 P#101 Q#102;"),
    ("000", "3.28.2 H23", _G, "G65 H23 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H24", _G, "G65 H24 P#101 Q#102;"),
    ("000", "3.28.2 H25", _G, "G65 H25 P#101 Q#102;"),
    ("000", "3.28.2 H26", _G, "G65 H26 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H27", _G, "G65 H27 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H31", _G, "G65 H31 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H32", _G, "G65 H32 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H33", _G, "G65 H33 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H34", _G, "G65 H34 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H80", _G, "G65 H80 P120;"),
    ("000", "3.28.2 H81", _G, "G65 H81 P1000 Q#201 R#202;"),
    ("000", "3.28.2 H82", _G, "G65 H82 P1000 Q#101 R#102;"),
    ("000", "3.28.2 H83", _G, "G65 H83 P1000 Q#101 R#102;"),
    ("000", "3.28.2 H84", _G, "G65 H84 P1000 Q#101 R#102;"),
    ("000", "3.28.2 H85", _G, "G65 H85 P1000 Q#101 R#102;"),
    ("000", "3.28.2 H86", _G, "G65 H86 P1000 Q#101 R#102;"),
    ("000", "3.28.2 H99", _G, "G65 H99 P15(/用户自定义报警);"),
    ("000", "3.28.2 note 2", _G, "G65 H81 P#100 Q#101 R#102;"),
    # seed 000 §3.28.3 calls
    ("000", "3.28.3.1 G65 format 1", _G, "G65 P1200 L2"),
    ("000", "3.28.3.1 G65 format 2", _G, "G65 P[CUT] L2 ;"),
    ("000", "3.28.3.1 G65 format 2", _G, "G65 P[螺纹切削] ;"),
    ("000", "3.28.3.1 argument II", _G, "G65 P9010 A1 B2 C3 I14 J15 I6 J7 K9 K11 K12 J30;"),
    ("000", "3.28.3.2 G66 format 1", _G, "G66 P1200 L2"),
    ("000", "3.28.3.2 G66 format 2", _G, "G66 P[CUT] L2 ;"),
    ("000", "3.28.3.2 G66 format 2", _G, "G66 P[螺纹切削] ;"),
    ("000", "3.28.3.3 G67 example", _G, "O2005 (O2005)；"),
    ("000", "3.28.3.3 G67 example", _G, "G00 X100 Z50；"),
    ("000", "3.28.3.3 G67 example", _G, "G66 P0100 L2 A2 B20 C20 I30 J20 K20；"),
    ("000", "3.28.3.3 G67 example", _G, "G01 X80 Z50；"),
    ("000", "3.28.3.3 G67 example", _G, "G67；"),
    ("000", "3.28.3.3 G67 example", _G, "G01 X20 Z50；"),
    ("000", "3.28.3.3 G67 example", _G, "M30；"),
    # seed 001: G65/G66 and M/T/G-code calls
    ("001", "G65 format 2", _G, "G65 P[#100] L2；"),
    ("001", "G65 format 2", _G, "G65 P[O1004] L3；"),
    ("001", "G65 format 2", _G, "G65 P[T123] L2；"),
    ("001", "argument list", _G, "G65 P0012 J12 K22 J25 I33 J32；"),
    ("001", "G66 format 2", _G, "G66 P[#100] L2;"),
    ("001", "G66 format 2", _G, "G66 P[O1004] L3;"),
    ("001", "G66 format 2", _G, "G66 P[T123] L2;"),
    ("001", "G66 example", _G, "G00 X100 Z50;"),
    ("001", "G66 example", _G, "G66 P0100 L2 A2 B20 C20 I30 J20 K20;"),
    ("001", "G66 example", _G, "G01 X80 Z50;"),
    ("001", "G66 example", _G, "G0 U0 W0;"),
    ("001", "G66 example", _G, "G01 U1;"),
    ("001", "G66 example", _G, "G67;"),
    ("001", "G66 example", _G, "G01 X20 Z50;"),
    ("001", "G66 example", _G, "M30;"),
    ("001", "M/T/G code calls example", _G, "G0 X0 Z0;"),
    ("001", "M/T/G code calls example", _G, "G500;"),
    ("001", "M/T/G code calls example", _G, "T2;"),
    ("001", "M/T/G code calls example", _G, "M31;"),
    ("001", "M/T/G code calls example", _G, "M30;"),
    # seed 002: M98 / M99
    ("002", "M98 format 2", _G, "M98 P[#100] L3"),
    ("002", "M98 format 2", _G, "M98 P[O0023] L3 ;"),
    ("002", "M98 format 2", _G, "M98 P[T0023] L3 ;"),
]

SEED_003_RESTORED: list[tuple[str, str, str, str]] = [
    # 4.2 tool offsets: "#100#11001" and "#11001100." lost their '='
    ("003", "4.2 read tool offset", _F, "#100=#11001"),
    ("003", "4.2 read tool offset", _F, "#100=#2201"),
    ("003", "4.2 write tool offset", _F, "#11001=100."),
    ("003", "4.2 write tool offset", _F, "#2201=100."),
    # 4.3 / 4.4 alarm and stop: "#30001;" lost its '='
    ("003", "4.3 macro alarm", _F, "#3000=1;"),
    ("003", "4.4 stop with message", _F, "#3006=1(MESSAGE);"),
    # 4.8 / 4.9 / 4.10: "#100#4010" and friends lost their '='
    ("003", "4.8 modal information", _F, "#100=#4010;"),
    ("003", "4.9 current position", _F, "#100=#5003;"),
    ("003", "4.10 work offset", _F, "#100=#5221"),
    ("003", "4.10 work offset", _F, "#100=#2501"),
    ("003", "4.10 work offset", _F, "#5221=100."),
    ("003", "4.10 work offset", _F, "#2501=100."),
]

SEED_PROGRAMS: dict[str, str] = {
    "O0100": "\n".join(
        [
            "O0100; (#100 是已加工零件个数, 初始值=0)",
            "G00 X100 Z100;",
            "T0101;",
            "IF[#100<100]GOTO10; (已连续加工了 100 个?)",
            "G65 P9580 U-0.01 W-0.01; (调用宏程序补偿刀具磨损)",
            "N10 G00 X50 Z50;",
            "T0202;",
            "IF[#100<100]GOTO20; (已连续加工了 100 个?)",
            "G65 P9580 U-0.01 W-0.01; (调用宏程序补偿刀具磨损)",
            "N20 G00 X50 Z50;",
            "#100=#100+1; (已加工零件个数+1)",
            "IF[#100==100]THEN #100=0;",
            "M30;",
        ]
    ),
    "O9580": "\n".join(
        [
            "O9580;",
            "G65 H23 P#101 Q#4120 R100; (获取刀偏号)",
            "IF[#101==0]GOTO10; (刀偏为 0 则不修改磨损值)",
            "#102=2000+#101; (X 轴磨损宏变量)",
            "#103=2100+#101; (Z 轴磨损宏变量)",
            "#9102=#9102+#21; (修改 X 轴磨损)",
            "#9103=#9103+#23; (修改 Z 轴磨损)",
            "T#4120; (调用新的刀偏值)",
            "N10 M99;",
        ]
    ),
}
