"""Concrete example blocks printed in the cncmacro seed manuals 000-004, for parser and
interpreter tests. SEED_BLOCKS holds one program block per entry as (seed_id, where,
dialect, block): seeds 000-002 are the GSK980TDi macro, G65/G66 and M98/M99 chapters
(dialect "gsk980tdi"), seeds 003-004 the FANUC 0i Custom Macro B thesis and the English
FANUC-style manual (dialect "fanuc"). Each block is the line as the manual prints it, with
its spacing, its trailing ASCII or full-width semicolon and any parenthesised comment;
format templates with placeholders are left out, markup escapes of the source text
(such as &lt; for <) are shown as the printed character, and entries marked
"# uncertain:" are prose-embedded forms or fragments that may not be standalone blocks.
The text of seed 003 lost most '=' signs and square brackets, so its blocks appear here as
printed and again, as the thesis intended them, in SEED_003_RESTORED. SEED_PROGRAMS holds
the two complete example programs of seed 000 (O0100 and O9580)."""

SEED_BLOCKS: list[tuple[str, str, str, str]] = [
    # Seed 000: GSK980TDi 3.28 宏代码
    ("000", "3.28.1 变量的表示 示例", "gsk980tdi", "#105"),  # uncertain: a variable, not a full block
    ("000", "3.28.1 变量的表示 示例", "gsk980tdi", "#109"),  # uncertain: a variable, not a full block
    ("000", "3.28.1 变量的表示 示例", "gsk980tdi", "# [#125 + #100 * #111]"),  # uncertain: a variable, not a full block
    ("000", "3.28.1 变量的引用 1) 示例", "gsk980tdi", "F#103"),
    ("000", "3.28.1 变量的引用 1) 示例", "gsk980tdi", "F15"),  # uncertain: equivalent form named in prose
    ("000", "3.28.1 变量的引用 1) 示例", "gsk980tdi", "Z-#110"),
    ("000", "3.28.1 变量的引用 1) 示例", "gsk980tdi", "Z-250"),  # uncertain: equivalent form named in prose
    ("000", "3.28.1 变量的引用 2) 示例", "gsk980tdi", "X#9100"),
    ("000", "3.28.1 变量的引用 2) 示例", "gsk980tdi", "X500"),  # uncertain: equivalent form named in prose
    ("000", "3.28.1 变量的引用 2) 示例", "gsk980tdi", "X-#9100"),
    ("000", "3.28.1 变量的引用 2) 示例", "gsk980tdi", "X-500"),  # uncertain: equivalent form named in prose
    ("000", "3.28.1 变量的引用 注", "gsk980tdi", "M#230"),  # uncertain: word quoted in prose (out of range)
    ("000", "3.28.1 空变量 1) 引用", "gsk980tdi", "G00 X100 Z#1"),
    ("000", "3.28.1 空变量 1) 引用", "gsk980tdi", "G00 X100 Z0"),  # uncertain: equivalent form named in prose
    ("000", "3.28.1 空变量 2) 运算 当#1=<空>时", "gsk980tdi", "#2=#1"),
    ("000", "3.28.1 空变量 2) 运算 当#1=<空>时", "gsk980tdi", "#2=#1 * 5"),
    ("000", "3.28.1 空变量 2) 运算 当#1=<空>时", "gsk980tdi", "#2=#1+#1"),
    ("000", "3.28.1 空变量 2) 运算 当#1=0时", "gsk980tdi", "#2=#1"),
    ("000", "3.28.1 空变量 2) 运算 当#1=0时", "gsk980tdi", "#2=#1 * 5"),
    ("000", "3.28.1 空变量 2) 运算 当#1=0时", "gsk980tdi", "#2=#1+#1"),
    (
        "000",
        "3.28.1 空变量 3) 条件表达式 当#1=<空>时",
        "gsk980tdi",
        "#1 EQ #0",
    ),  # uncertain: condition, not a full block
    (
        "000",
        "3.28.1 空变量 3) 条件表达式 当#1=<空>时",
        "gsk980tdi",
        "#1 NE #0",
    ),  # uncertain: condition, not a full block
    (
        "000",
        "3.28.1 空变量 3) 条件表达式 当#1=<空>时",
        "gsk980tdi",
        "#1 GE #0",
    ),  # uncertain: condition, not a full block
    (
        "000",
        "3.28.1 空变量 3) 条件表达式 当#1=<空>时",
        "gsk980tdi",
        "#1 GT #0",
    ),  # uncertain: condition, not a full block
    ("000", "3.28.1 空变量 3) 条件表达式 当#1=0时", "gsk980tdi", "#1 EQ #0"),  # uncertain: condition, not a full block
    ("000", "3.28.1 空变量 3) 条件表达式 当#1=0时", "gsk980tdi", "#1 NE #0"),  # uncertain: condition, not a full block
    ("000", "3.28.1 空变量 3) 条件表达式 当#1=0时", "gsk980tdi", "#1 GE #0"),  # uncertain: condition, not a full block
    ("000", "3.28.1 空变量 3) 条件表达式 当#1=0时", "gsk980tdi", "#1 GT #0"),  # uncertain: condition, not a full block
    ("000", "3.28.1 应用举例 O0100", "gsk980tdi", "O0100; (#100 是已加工零件个数, 初始值=0)"),
    ("000", "3.28.1 应用举例 O0100", "gsk980tdi", "G00 X100 Z100;"),
    ("000", "3.28.1 应用举例 O0100", "gsk980tdi", "T0101;"),
    ("000", "3.28.1 应用举例 O0100", "gsk980tdi", "IF[#100<100]GOTO10; (已连续加工了 100 个?)"),
    ("000", "3.28.1 应用举例 O0100", "gsk980tdi", "G65 P9580 U-0.01 W-0.01; (调用宏程序补偿刀具磨损)"),
    ("000", "3.28.1 应用举例 O0100", "gsk980tdi", "N10 G00 X50 Z50;"),
    ("000", "3.28.1 应用举例 O0100", "gsk980tdi", "T0202;"),
    ("000", "3.28.1 应用举例 O0100", "gsk980tdi", "IF[#100<100]GOTO20; (已连续加工了 100 个?)"),
    ("000", "3.28.1 应用举例 O0100", "gsk980tdi", "G65 P9580 U-0.01 W-0.01; (调用宏程序补偿刀具磨损)"),
    ("000", "3.28.1 应用举例 O0100", "gsk980tdi", "N20;"),  # uncertain: printed "N20 .....;", label kept
    ("000", "3.28.1 应用举例 O0100", "gsk980tdi", "#100=#100+1; (已加工零件个数+1)"),
    ("000", "3.28.1 应用举例 O0100", "gsk980tdi", "IF[#100==100]THEN #100=0;"),
    ("000", "3.28.1 应用举例 O0100", "gsk980tdi", "M30;"),
    ("000", "3.28.1 应用举例 O9580", "gsk980tdi", "O9580;"),
    ("000", "3.28.1 应用举例 O9580", "gsk980tdi", "G65 H23 P#101 Q#4120 R100; (获取刀偏号)"),
    ("000", "3.28.1 应用举例 O9580", "gsk980tdi", "IF[#101==0]GOTO10; (刀偏为 0 则不修改磨损值)"),
    ("000", "3.28.1 应用举例 O9580", "gsk980tdi", "#102=2000+#101; (X 轴磨损宏变量)"),
    ("000", "3.28.1 应用举例 O9580", "gsk980tdi", "#103=2100+#101; (Z 轴磨损宏变量)"),
    ("000", "3.28.1 应用举例 O9580", "gsk980tdi", "#9102=#9102+#21; (修改 X 轴磨损)"),
    ("000", "3.28.1 应用举例 O9580", "gsk980tdi", "#9103=#9103+#23; (修改 Z 轴磨损)"),
    ("000", "3.28.1 应用举例 O9580", "gsk980tdi", "T#4120; (调用新的刀偏值)"),
    ("000", "3.28.1 应用举例 O9580", "gsk980tdi", "N10 M99;"),
    # 3.28.2: the formula glosses printed after each example, e.g. (#101 = 1005), are
    # explanations of the manual, not part of the block, and are left out.
    ("000", "3.28.2 H01 example", "gsk980tdi", "G65 H01 P#101 Q1005;"),
    ("000", "3.28.2 H01 example", "gsk980tdi", "G65 H01 P#101 Q#110;"),
    ("000", "3.28.2 H01 example", "gsk980tdi", "G65 H01 P#101 Q-#102;"),
    ("000", "3.28.2 H02 example", "gsk980tdi", "G65 H02 P#101 Q#102 R15;"),
    ("000", "3.28.2 H03 example", "gsk980tdi", "G65 H03 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H04 example", "gsk980tdi", "G65 H04 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H05 example", "gsk980tdi", "G65 H05 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H11 example", "gsk980tdi", "G65 H11 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H12 example", "gsk980tdi", "G65 H12 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H13 example", "gsk980tdi", "G65 H13 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H21 example", "gsk980tdi", "G65 H21 P#101 Q#102;"),
    ("000", "3.28.2 H22 example", "gsk980tdi", "G65 H22 P#101 Q#102;"),
    ("000", "3.28.2 H23 example", "gsk980tdi", "G65 H23 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H24 example", "gsk980tdi", "G65 H24 P#101 Q#102;"),
    ("000", "3.28.2 H25 example", "gsk980tdi", "G65 H25 P#101 Q#102;"),
    ("000", "3.28.2 H26 example", "gsk980tdi", "G65 H26 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H27 example", "gsk980tdi", "G65 H27 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H31 example", "gsk980tdi", "G65 H31 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H32 example", "gsk980tdi", "G65 H32 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H33 example", "gsk980tdi", "G65 H33 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H34 example", "gsk980tdi", "G65 H34 P#101 Q#102 R#103;"),
    ("000", "3.28.2 H80 example", "gsk980tdi", "G65 H80 P120; (转到 N120 程序段)"),
    ("000", "3.28.2 H81 example", "gsk980tdi", "G65 H81 P1000 Q#201 R#202;"),
    ("000", "3.28.2 H82 example", "gsk980tdi", "G65 H82 P1000 Q#101 R#102;"),
    ("000", "3.28.2 H83 example", "gsk980tdi", "G65 H83 P1000 Q#101 R#102;"),
    ("000", "3.28.2 H84 example", "gsk980tdi", "G65 H84 P1000 Q#101 R#102;"),
    ("000", "3.28.2 H85 example", "gsk980tdi", "G65 H85 P1000 Q#101 R#102;"),
    ("000", "3.28.2 H86 example", "gsk980tdi", "G65 H86 P1000 Q#101 R#102;"),
    ("000", "3.28.2 H99 example", "gsk980tdi", "G65 H99 P15(/用户自定义报警);"),
    ("000", "3.28.2 转移命令 注 2", "gsk980tdi", "G65 H81 P#100 Q#101 R#102;"),
    ("000", "3.28.3.1 G65 格式一 示例", "gsk980tdi", "G65 P1200 L2"),
    ("000", "3.28.3.1 G65 格式二 示例", "gsk980tdi", "G65 P[CUT] L2 ;"),
    ("000", "3.28.3.1 G65 格式二 示例", "gsk980tdi", "G65 P[螺纹切削] ;"),
    ("000", "3.28.3.1 自变量的指定 示例", "gsk980tdi", "G65 P9010 A1 B2 C3 I14 J15 I6 J7 K9 K11 K12 J30;"),
    ("000", "3.28.3.2 G66 格式一 示例", "gsk980tdi", "G66 P1200 L2"),
    ("000", "3.28.3.2 G66 格式二 示例", "gsk980tdi", "G66 P[CUT] L2 ;"),
    ("000", "3.28.3.2 G66 格式二 示例", "gsk980tdi", "G66 P[螺纹切削] ;"),
    ("000", "3.28.3.3 G67 代码格式", "gsk980tdi", "G67；"),
    ("000", "3.28.3.3 G67 示例 O2005", "gsk980tdi", "O2005 (O2005)；"),
    ("000", "3.28.3.3 G67 示例 O2005", "gsk980tdi", "G00 X100 Z50；"),
    ("000", "3.28.3.3 G67 示例 O2005", "gsk980tdi", "G66 P0100 L2 A2 B20 C20 I30 J20 K20；"),
    ("000", "3.28.3.3 G67 示例 O2005", "gsk980tdi", "G01 X80 Z50；"),
    ("000", "3.28.3.3 G67 示例 O2005", "gsk980tdi", "G67；"),
    ("000", "3.28.3.3 G67 示例 O2005", "gsk980tdi", "G01 X20 Z50；"),
    ("000", "3.28.3.3 G67 示例 O2005", "gsk980tdi", "M30；"),
    # Seed 001: GSK980TDi G65/G66/G67 and M/T/G-code macro calls
    ("001", "G65 格式二 例", "gsk980tdi", "G65 P[#100] L2；"),
    ("001", "G65 格式二 例", "gsk980tdi", "G65 P[O1004] L3；"),
    ("001", "G65 格式二 例", "gsk980tdi", "G65 P[T123] L2；"),
    ("001", "G65 指令字说明 P", "gsk980tdi", "G65 P[T123] L2"),  # uncertain: quoted in a prose table cell
    ("001", "G65 自变量列表说明", "gsk980tdi", "G65 P0012 J12 K22 J25 I33 J32；"),
    ("001", "G66 格式一 指令格式", "gsk980tdi", "G67;"),
    ("001", "G66 格式二 指令格式", "gsk980tdi", "G67;"),
    ("001", "G66 格式二 例", "gsk980tdi", "G66 P[#100] L2;"),
    ("001", "G66 格式二 例", "gsk980tdi", "G66 P[O1004] L3;"),
    ("001", "G66 格式二 例", "gsk980tdi", "G66 P[T123] L2;"),
    ("001", "G66 格式二 例", "gsk980tdi", "G67"),
    ("001", "G66 指令字说明 G66", "gsk980tdi", "G66 P[T123] L2;"),  # uncertain: quoted in a prose table cell
    ("001", "G66 指令字说明 P", "gsk980tdi", "G66 P[T123] L2"),  # uncertain: quoted in a prose table cell
    ("001", "G66 编程示例 O0002", "gsk980tdi", "O0002"),  # uncertain: printed as the heading "程序: O0002"
    ("001", "G66 编程示例 O0002", "gsk980tdi", "G00 X100 Z50;"),
    ("001", "G66 编程示例 O0002", "gsk980tdi", "G66 P0100 L2 A2 B20 C20 I30 J20 K20;"),
    ("001", "G66 编程示例 O0002", "gsk980tdi", "G01 X80 Z50;"),
    ("001", "G66 编程示例 O0002", "gsk980tdi", "G0 U0 W0;"),
    ("001", "G66 编程示例 O0002", "gsk980tdi", "G01 U1;"),
    ("001", "G66 编程示例 O0002", "gsk980tdi", "G67;"),
    ("001", "G66 编程示例 O0002", "gsk980tdi", "G01 X20 Z50;"),
    ("001", "G66 编程示例 O0002", "gsk980tdi", "M30;"),
    ("001", "M、T、G 代码调用宏程序 编程示例", "gsk980tdi", "G0 X0 Z0;"),
    ("001", "M、T、G 代码调用宏程序 编程示例", "gsk980tdi", "G500;"),
    ("001", "M、T、G 代码调用宏程序 编程示例", "gsk980tdi", "T2;"),
    ("001", "M、T、G 代码调用宏程序 编程示例", "gsk980tdi", "M31;"),
    ("001", "M、T、G 代码调用宏程序 编程示例", "gsk980tdi", "M30;"),
    # Seed 002: GSK980TDi M98/M99/M198
    ("002", "M98 指令字 P 格式二 例", "gsk980tdi", "M98 P[#100] L3"),
    ("002", "M98 指令字 P 格式二 例", "gsk980tdi", "M98 P[O0023] L3 ;"),
    ("002", "M98 指令字 P 格式二 例", "gsk980tdi", "M98 P[T0023] L3 ;"),
    # Seed 003: FANUC-0i macro thesis, as printed (see SEED_003_RESTORED)
    ("003", "3.2 表3-2 当#1空时", "fanuc", "#2=#1"),
    ("003", "3.2 表3-2 当#1空时", "fanuc", "#2=#1*5"),
    ("003", "3.2 表3-2 当#1空时", "fanuc", "#2=#2+#1"),  # uncertain: the other column has #2=#1+#1
    ("003", "3.2 表3-2 当#1=0时", "fanuc", "#2=#1"),
    ("003", "3.2 表3-2 当#1=0时", "fanuc", "#2=#1*5"),
    ("003", "3.2 表3-2 当#1=0时", "fanuc", "#2=#1+#1"),
    ("003", "3.3 条件表达式", "fanuc", "#24GT#36"),  # uncertain: condition, brackets lost
    ("003", "3.3 条件表达式 当#1空时", "fanuc", "#1EQ#0"),  # uncertain: condition, not a full block
    ("003", "3.3 条件表达式 当#1空时", "fanuc", "#1NE#0"),  # uncertain: condition, not a full block
    ("003", "3.3 条件表达式 当#1空时", "fanuc", "#1GE#0"),  # uncertain: condition, not a full block
    ("003", "3.3 条件表达式 当#1空时", "fanuc", "#1GT#0"),  # uncertain: condition, not a full block
    ("003", "3.3 条件表达式 当#1=0时", "fanuc", "#1EQ#0"),  # uncertain: condition, not a full block
    ("003", "3.3 条件表达式 当#1=0时", "fanuc", "#1NE#0"),  # uncertain: condition, not a full block
    ("003", "3.3 条件表达式 当#1=0时", "fanuc", "#1GE#0"),  # uncertain: condition, not a full block
    ("003", "3.3 条件表达式 当#1=0时", "fanuc", "#1GT#0"),  # uncertain: condition, not a full block
    # 4.2-4.10: printed with the '=' lost
    ("003", "4.2 刀具补偿值 读取", "fanuc", "#100#11001"),
    ("003", "4.2 刀具补偿值 读取", "fanuc", "#100#2201;"),
    ("003", "4.2 刀具补偿值 书写", "fanuc", "#11001100.;"),
    ("003", "4.2 刀具补偿值 书写", "fanuc", "#2201100.;"),
    ("003", "4.3 宏程序报警", "fanuc", "#30001;"),
    ("003", "4.4 停止和信息显示", "fanuc", "#30061(MESSAGE);"),
    ("003", "4.8 模态信息", "fanuc", "#100#4010;"),
    ("003", "4.9 当前位置", "fanuc", "#100#5003;"),
    ("003", "4.10 工件坐标系补偿值 读取", "fanuc", "#100#5221"),
    ("003", "4.10 工件坐标系补偿值 读取", "fanuc", "#100#2501;"),
    ("003", "4.10 工件坐标系补偿值 书写", "fanuc", "#5221100.;"),
    ("003", "4.10 工件坐标系补偿值 书写", "fanuc", "#2501100.;"),
    # Seed 004 prints only format templates (G65 Pp Ll <specify arguments>;, B_A_D_ ... J_K_)
    # and argument tables, so it has no concrete blocks.
]

SEED_003_RESTORED: list[tuple[str, str, str, str]] = [
    # 3.3: the square brackets that enclose a condition restored
    ("003", "3.3 条件表达式", "fanuc", "[#24GT#36]"),  # uncertain: condition, not a full block
    # 4.2: '=' restored between the variable and the tool offset read or written
    ("003", "4.2 刀具补偿值 读取", "fanuc", "#100=#11001"),
    ("003", "4.2 刀具补偿值 读取", "fanuc", "#100=#2201;"),
    ("003", "4.2 刀具补偿值 书写", "fanuc", "#11001=100.;"),
    ("003", "4.2 刀具补偿值 书写", "fanuc", "#2201=100.;"),
    # 4.3: '=' restored between #3000 and the alarm number 1
    ("003", "4.3 宏程序报警", "fanuc", "#3000=1;"),
    # 4.4: '=' restored between #3006 and 1
    ("003", "4.4 停止和信息显示", "fanuc", "#3006=1(MESSAGE);"),
    # 4.8: '=' restored between #100 and the modal variable #4010
    ("003", "4.8 模态信息", "fanuc", "#100=#4010;"),
    # 4.9: '=' restored between #100 and the position variable #5003
    ("003", "4.9 当前位置", "fanuc", "#100=#5003;"),
    # 4.10: '=' restored between the variable and the work offset read or written
    ("003", "4.10 工件坐标系补偿值 读取", "fanuc", "#100=#5221"),
    ("003", "4.10 工件坐标系补偿值 读取", "fanuc", "#100=#2501;"),
    ("003", "4.10 工件坐标系补偿值 书写", "fanuc", "#5221=100.;"),
    ("003", "4.10 工件坐标系补偿值 书写", "fanuc", "#2501=100.;"),
]

SEED_PROGRAMS: dict[str, str] = {
    # O0100: the "N20 .....;" block is kept as "N20;" because GOTO20 jumps to it
    "O0100": (
        "O0100; (#100 是已加工零件个数, 初始值=0)\n"
        "G00 X100 Z100;\n"
        "T0101;\n"
        "IF[#100<100]GOTO10; (已连续加工了 100 个?)\n"
        "G65 P9580 U-0.01 W-0.01; (调用宏程序补偿刀具磨损)\n"
        "N10 G00 X50 Z50;\n"
        "T0202;\n"
        "IF[#100<100]GOTO20; (已连续加工了 100 个?)\n"
        "G65 P9580 U-0.01 W-0.01; (调用宏程序补偿刀具磨损)\n"
        "N20;\n"
        "#100=#100+1; (已加工零件个数+1)\n"
        "IF[#100==100]THEN #100=0;\n"
        "M30;"
    ),
    "O9580": (
        "O9580;\n"
        "G65 H23 P#101 Q#4120 R100; (获取刀偏号)\n"
        "IF[#101==0]GOTO10; (刀偏为 0 则不修改磨损值)\n"
        "#102=2000+#101; (X 轴磨损宏变量)\n"
        "#103=2100+#101; (Z 轴磨损宏变量)\n"
        "#9102=#9102+#21; (修改 X 轴磨损)\n"
        "#9103=#9103+#23; (修改 Z 轴磨损)\n"
        "T#4120; (调用新的刀偏值)\n"
        "N10 M99;"
    ),
}
