"""The diagnostic codes: one record per code, the registry every check and front end reads.

``CODES`` is docs/design.md's table of stable diagnostic codes (``tests/test_diagnostic_codes.py``
holds the two together). Each ``Code`` says its default severity, the milder one a check gives
where a control is known to be lenient (the table's "error / warning"), a one-line description in
English and Chinese (the SARIF rules and the settings read it), how it is found (``static``: by
looking at the text, ``run``: by running the program, ``both``), and, for the codes a run finds,
the alarm numbers and the interpreter's alarm subjects it stands for.

A check makes its findings with ``default_severity`` (``diagnostics.diagnostic``,
``line_facts.finding``), so no check writes a severity of its own; ``alarm_code`` turns an alarm
of a run into its code. The user's changes to the severities are ``analysis/severity.py``'s.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..bilingual import Detail, detail
from ..dialects.alarms import (
    ARC_NO_CENTRE,
    ARC_RADIUS,
    ARGUMENT_RANGE,
    BRACKET_NESTING,
    CORNER_FIT,
    CORNER_NO_MOVE,
    CORNER_NOT_CUT,
    COUNT_TWICE,
    CUTTER_ARC_START,
    CUTTER_CORNER,
    CUTTER_INTERFERENCE,
    CUTTER_NO_INTERSECTION,
    CUTTER_PLANE,
    CUTTER_SKIP,
    CYCLE_BAD_VALUE,
    CYCLE_BLOCK_NOT_FOUND,
    CYCLE_P_Q_MISSING,
    DECIMAL_POINT,
    DIVISION_BY_ZERO,
    FORMAT,
    G_ARGUMENT,
    GROOVE_AMOUNT,
    GROOVE_END_POINT,
    GROOVE_RELIEF,
    ILLEGAL_LEAD,
    IMPROPER_G_CODE,
    LOOP_NUMBER,
    MACRO_NESTING,
    MISSING_END,
    NAME_SUBSCRIPT,
    NC_AND_MACRO,
    NO_VARIABLE_NAME,
    NOT_ALONE,
    OFFSET_NUMBER,
    OVERFLOW,
    OVERTRAVEL_MINUS,
    OVERTRAVEL_PLUS,
    P_VALUE_RANGE,
    PECK_Q_MISSING,
    POLAR_START,
    PROGRAM_NOT_FOUND,
    RECIPROCATION_AMOUNT,
    REFERENCE_IN_CYCLE,
    REPEAT_COUNT,
    SEQUENCE_NUMBER,
    SHAPE_COMMAND,
    SHAPE_FIRST_BLOCK,
    SHAPE_LAST_BLOCK,
    SHAPE_NOT_MONOTONE,
    SHAPE_NOT_MONOTONE_X,
    SHAPE_PAST_START,
    STATEMENT_FORMAT,
    SUBPROGRAM_NESTING,
    THREAD_CORNER,
    THREAD_DEPTH,
    THREAD_MIN_DEPTH,
    TOOL_ANGLE,
    VARIABLE_NUMBER,
    WRITE_PROTECTED,
)

ERROR = "error"
WARNING = "warning"
INFORMATION = "information"
HINT = "hint"
SEVERITIES = (ERROR, WARNING, INFORMATION, HINT)

STATIC = "static"  # found by looking at the text
RUN = "run"  # found by running the program
BOTH = "both"
FOUND = (STATIC, RUN, BOTH)

MACRO_ALARM = "macro-alarm"
_UNKNOWN_ALARM = "syntax"  # an alarm number below the macro-alarm base that no code claims


@dataclass(frozen=True, slots=True)
class Code:
    """One diagnostic code (see the module docstring)."""

    name: str
    severity: str
    description: Detail
    found: str = STATIC
    alarms: tuple[int, ...] = ()  # the alarm numbers a run reports as this code
    subjects: tuple[str, ...] = ()  # the interpreter's alarm subjects (``MacroAlarm.subject``)
    milder: str | None = None  # the severity where a control is lenient (see the check)


def _codes(*codes: Code) -> dict[str, Code]:
    return {c.name: c for c in codes}


CODES: dict[str, Code] = _codes(
    Code("syntax", ERROR, detail("The block does not parse.", "程序段无法解析。"),
         BOTH, (FORMAT, STATEMENT_FORMAT)),
    Code("bracket-depth", ERROR, detail("More than 5 nested brackets (alarm 118).", "括号嵌套超过 5 层（报警 118）。"),
         BOTH, (BRACKET_NESTING,)),
    Code("undefined-label", ERROR,
         detail("A GOTO, M99 P, M98 Q, M97 P or H80-H86 target has no N label.",
                "GOTO、M99 P、M98 Q、M97 P 或 H80-H86 的目标没有对应的 N 顺序号。"),
         BOTH, (SEQUENCE_NUMBER,)),
    Code("duplicate-label", WARNING,
         detail("An N number is used twice where it is a jump target.", "作为转移目标的 N 顺序号出现了两次。")),
    Code("duplicate-program", WARNING,
         detail("An O number used twice in a file: the control keeps the first program.",
                "同一文件中 O 程序号重复：系统只保留第一个程序。")),
    Code("label-range", ERROR, detail("A GOTO target is outside 1-99999.", "GOTO 目标超出 1-99999。"),
         BOTH, subjects=("label-range",)),
    Code("loop-mismatch", ERROR,
         detail("DO without END, END without DO, or crossing loops (alarms 124/126).",
                "DO 没有 END、END 没有 DO，或循环交叉（报警 124/126）。"),
         BOTH, (MISSING_END,), milder=WARNING),
    Code("loop-number", ERROR,
         detail("A DO/END number outside 1-3, or loops nested deeper than 3 (alarm 126).",
                "DO/END 号超出 1-3，或循环嵌套超过 3 层（报警 126）。"),
         BOTH, (LOOP_NUMBER,)),
    Code("jump-into-loop", ERROR, detail("A jump into a DO range from outside it.", "从外部转移到 DO 循环范围内。"),
         BOTH, subjects=("jump-into-loop",)),
    Code("if-mismatch", ERROR,
         detail("A block IF [...] THEN without its ENDIF, an ELSE or ENDIF without its IF, or a second ELSE "
                "(controls with the block form of IF).",
                "块形式 IF [...] THEN 没有对应的 ENDIF、ELSE 或 ENDIF 没有对应的 IF，或出现第二个 ELSE"
                "（支持块形式 IF 的系统）。"),
         BOTH, subjects=("if-mismatch",)),
    Code("jump-into-if", ERROR,
         detail("A jump into a branch of a block IF [...] THEN from outside it.",
                "从外部转移到块形式 IF [...] THEN 的分支内。"),
         BOTH, subjects=("jump-into-if",)),
    Code("g65-nc-words", ERROR,
         detail("G65/G66 shares its block with another G or M code, an O word or a prior word (a modal G code "
                "before it is a hint where the control sets it and calls).",
                "G65/G66 与其他 G 或 M 代码、O 代码或其前面的代码在同一程序段"
                "（系统先执行其前的模态 G 代码再调用时为提示）。"),
         milder=HINT),
    Code("g65-word-order", ERROR,
         detail("A word other than P (or H) right after G65/G66 where the control's manual wants P or H there "
                "(GSK980TDi); a warning where the manual gives no alarm for it.",
                "G65/G66 之后紧跟的不是 P（或 H），而系统手册要求紧跟 P 或 H（GSK980TDi）；"
                "手册未给出报警时为警告。"),
         milder=WARNING),
    Code("own-block", ERROR,
         detail("A word beside a G code the control's manual wants in a block of its own (GSK980TDi: G22/G23 "
                "beside a G, M, S or T code stops the run; G12.1, G13.1, G15, G16, G50.2, G51.2 beside another "
                "word is a warning, the manual giving no alarm for it).",
                "与系统手册要求单独编段的 G 代码同段的代码字（GSK980TDi：G22/G23 与 G、M、S、T 代码同段时运行停止；"
                "G12.1、G13.1、G15、G16、G50.2、G51.2 与其他代码字同段为警告，手册未给出报警）。"),
         BOTH, (NOT_ALONE,), milder=WARNING),
    Code("argument-address", ERROR,
         detail("G, L, N, O or P used as a macro argument (alarm 129).",
                "G、L、N、O 或 P 用作宏程序自变量（报警 129）。"),
         BOTH, (G_ARGUMENT,)),
    Code("argument-order", WARNING,
         detail("I, J, K arguments out of their I, J, K order within a set (fanuc).",
                "同一组内的 I、J、K 自变量未按 I、J、K 顺序（fanuc）。")),
    Code("repeat-count-range", ERROR,
         detail("A repeat count (L, or the count in P) is outside 1-9999.",
                "重复次数（L，或 P 中的次数）超出 1-9999。"),
         BOTH, (COUNT_TWICE,), ("repeat-count",), milder=WARNING),
    Code("program-not-found", ERROR,
         detail("A call names a program that is not in the workspace.", "调用的程序不在工作区中。"),
         BOTH, (PROGRAM_NOT_FOUND,)),
    Code("program-number", ERROR,
         detail("A program number has too many digits, or a program name is not allowed.",
                "程序号位数过多，或程序名不允许。"),
         BOTH, (P_VALUE_RANGE,)),
    Code("variable-number", ERROR,
         detail("A variable number that does not exist in the dialect (alarm 115).",
                "该系统中不存在的变量号（报警 115）。"),
         BOTH, (VARIABLE_NUMBER, NO_VARIABLE_NAME, NAME_SUBSCRIPT)),
    Code("write-protected", ERROR,
         detail("An assignment to #0 or to a read-only system variable (alarm 116).",
                "给 #0 或只读系统变量赋值（报警 116）。"),
         BOTH, (WRITE_PROTECTED,)),
    Code("write-only", ERROR, detail("A write-only system variable is read.", "读取了只写系统变量。")),
    Code("nc-and-macro", ERROR,
         detail("NC words and a macro statement in one block (alarm 127).",
                "NC 代码与宏语句在同一程序段（报警 127）。"),
         BOTH, (NC_AND_MACRO,)),
    Code("dialect-feature", ERROR, detail("Syntax that the selected dialect lacks.", "所选系统不支持的语法。")),
    Code("corner-word", WARNING,
         detail("A ,C/,R/,A corner word without a G01/G02/G03 move, or on a profile whose manual lacks it.",
                "没有 G01/G02/G03 移动的 ,C/,R/,A 拐角代码，或所选系统的手册中没有该代码。")),
    Code("unknown-profile", WARNING,
         detail("A (cncmacro: dialect=...) comment that names no profile: it is passed over, and the nearest "
                "valid name is given.",
                "(cncmacro: dialect=...) 注释中的名称不是系统类型：该注释被忽略，并给出最接近的有效名称。")),
    Code("profile-suggestion", INFORMATION,
         detail("The file reads cleanly as another profile, or looks like a lathe program under a mill profile: "
                "likely written for it.",
                "按另一个系统读取时文件没有问题，或在铣床系统下看起来是车床程序：很可能是为该系统编写的。")),
    Code("nesting-depth", ERROR,
         detail("Macro or subprogram nesting is exceeded when the program runs.", "运行时宏程序或子程序嵌套超出上限。"),
         RUN, (SUBPROGRAM_NESTING, MACRO_NESTING)),
    Code("division-by-zero", ERROR,
         detail("A division by zero found by running the program (alarm 112).", "运行程序时发现除数为零（报警 112）。"),
         RUN, (DIVISION_BY_ZERO,)),
    Code("argument-range", ERROR,
         detail("A SQRT, ASIN, ACOS or LN argument, or a #3000/G65 H99 alarm number, out of range, found by "
                "running (119).",
                "运行时发现 SQRT、ASIN、ACOS 或 LN 的自变量，或 #3000/G65 H99 的报警号超出范围（119）。"),
         RUN, (OVERFLOW, ARGUMENT_RANGE)),
    Code(MACRO_ALARM, ERROR,
         detail("A run of the program reaches #3000= or G65 H99 (a macro alarm): an error where every run of a main "
                "program stops there, a warning where the path depends on values the machine knows or the macro is "
                "checked without its caller.",
                "程序运行到 #3000= 或 G65 H99（宏程序报警）：主程序每次运行都会在此停止时为错误；"
                "路径取决于机床上的数值或宏程序未经调用者单独检查时为警告。"),
         RUN, milder=WARNING),
    Code("vacant-argument", INFORMATION,
         detail("A macro reads an argument that a caller never passes.", "宏程序读取了调用者没有传递的自变量。"), RUN),
    Code("unknown-value", HINT,
         detail("The run stops where the program decides something with a value only the machine has (a common "
                "kept at power-off, an offset) and the folder does not give, or with an argument of a macro checked "
                "without its caller: set it under [variables] in .cncmacro.toml, or in the persistent file it names, "
                "to check further; or with a random number (GSK980TDi's RAND, SRAND), which no check can foresee.",
                "程序用只有机床上才有的数值（断电保持的公共变量、补偿值）或单独检查的宏程序的自变量作判断，而文件夹中"
                "没有给出这个值，分析运行在此停止：在 .cncmacro.toml 的 [variables] 或它指定的断电保持变量文件中给出"
                "该值即可继续检查；或用随机数（GSK980TDi 的 RAND、SRAND）作判断，检查无法预知其值。"),
         RUN, subjects=("unknown-value",)),
    Code("endless-loop", ERROR,
         detail("A WHILE loop or IF..GOTO back whose condition nothing in it changes: the control never leaves it "
                "(a warning where the loop reads common variables another path or the operator could change).",
                "WHILE 循环或向回转移的 IF..GOTO，其条件在循环内无任何改变：控制器永远不会离开"
                "（循环读取其他通道或操作者可能修改的公共变量时为警告）。"),
         RUN, milder=WARNING),
    Code("run-limit", INFORMATION,
         detail("The analysis run stopped at its block budget (a possible endless loop), or in an endless "
                "loop that comes back with nothing changed.",
                "分析运行在程序段上限处停止（可能是死循环），或停在一个再次执行时没有任何变化的死循环中。"),
         RUN),
    Code("not-simulated", INFORMATION,
         detail("A cycle the control has that the simulation does not cut: its block moves nothing, and the tool "
                "is where the cycle ends on the control, its start point.",
                "控制器具有但模拟不切削的循环：该程序段不移动，刀具位于该循环在控制器上结束的位置，即其起点。"),
         RUN),
    Code("feed-per-minute", HINT,
         detail("A cut at F below 1 under G98 (feed per minute) on a lathe that powers on in G98: a G99 is missing.",
                "上电默认 G98 的车床在 G98（每分钟进给）下以小于 1 的 F 切削：缺少 G99。"), RUN),
    Code("no-feed", WARNING,
         detail("A cut with no feed (no F given in the program, or F0), or per revolution with no spindle speed: "
                "it takes no time in the cycle time, and the control alarms (FANUC PS0011) or waits for the spindle "
                "unless an earlier program left a feed or a speed.",
                "没有进给速度（程序中未指令 F，或 F0）的切削，或没有主轴转速的每转进给切削：加工时间中不计时间；"
                "除非之前的程序留下了进给速度或转速，否则控制器报警（FANUC PS0011）或等待主轴。"), RUN),
    Code("over-travel", ERROR,
         detail("A move leaves the machine's travel in the machine file's [limits] (FANUC OT0500/OT0501).",
                "移动超出机床文件 [limits] 中的行程（FANUC OT0500/OT0501）。"),
         RUN, (OVERTRAVEL_PLUS, OVERTRAVEL_MINUS)),
    Code("offset-number", ERROR,
         detail("A D, H or lathe offset number the control lacks: the machine file's [limits] offsets, or for a "
                "lathe's T without it the profile's offset table (PS0030).",
                "系统没有的 D、H 或车床刀补号：机床文件 [limits] offsets 之外，"
                "或车床的 T 在未设定时超出配置的刀补表（PS0030）。"),
         RUN, (OFFSET_NUMBER,)),
    Code("unknown-tool", ERROR,
         detail("A T the machine file's [limits] tools does not hold.", "机床文件 [limits] tools 中没有的刀号 T。"),
         RUN, subjects=("unknown-tool",)),
    Code("spindle-limit", WARNING,
         detail("An S above the spindle's top speed in the machine file's [limits]: the control turns it at the "
                "top speed.",
                "S 超过机床文件 [limits] 中的主轴最高转速：系统以最高转速旋转。"),
         RUN, subjects=("spindle-limit",)),
    Code("arc-radius", ERROR,
         detail("An I, J, K arc whose end point is off the start's circle by more than the arc tolerance "
                "(alarm 20, PS0020 on FANUC; a warning on controls whose manuals at hand give no alarm for it).",
                "I、J、K 圆弧的终点偏离起点所在圆周超过圆弧允差（FANUC 报警 20，PS0020；"
                "手头手册未给出报警的系统为警告）。"),
         RUN, (ARC_RADIUS,), ("arc-radius",), milder=WARNING),
    Code("arc-short-radius", WARNING,
         detail("An R arc whose radius is shorter than half the chord: no arc of that radius reaches the end point.",
                "R 圆弧的半径小于弦长的一半：该半径的圆弧到不了终点。"), RUN),
    Code("arc-r-full-circle", WARNING,
         detail("An R arc whose end point is its start: the control makes no move; a full circle takes I, J or K.",
                "R 圆弧的终点就是起点：系统不移动；整圆须用 I、J 或 K。"), RUN),
    Code("arc-centre", ERROR,
         detail("A G02/G03 block that moves in its plane with neither R nor I, J, K: the control cannot find the "
                "arc's centre (FANUC alarm 22, PS0022).",
                "G02/G03 程序段在其平面内移动，但既无 R 也无 I、J、K：系统无法确定圆弧圆心（FANUC 报警 22，PS0022）。"),
         RUN, (ARC_NO_CENTRE,), ("arc-centre",)),
    Code("curve-fault", ERROR,
         detail("A three-point arc (G05/G05.1), an ellipse (G6.2/G6.3) or a parabola (G7.2/G7.3) the control cannot "
                "cut as written: three points on one line, I and K left out, A, B or P 0 or left out, an end point "
                "out of the ellipse's reach, a line parallel to the parabola's axis (GSK980TDi manual §3.5-§3.7: "
                "an alarm).",
                "控制系统无法按所写加工的三点圆弧（G05/G05.1）、椭圆（G6.2/G6.3）或抛物线（G7.2/G7.3）：三点共线、"
                "省略 I 和 K、A、B 或 P 为 0 或省略、终点超出椭圆所及、连线与抛物线对称轴平行"
                "（GSK980TDi 手册 §3.5–§3.7：报警）。"),
         RUN),
    Code("drawing-angle", ERROR,
         detail("A direct drawing dimension (G01 X_ Q_, GSK980TDi) the control cannot cut: the line runs within 1° "
                "of parallel to the axis it must reach, or two lines meant to meet at a corner within 1° of each "
                "other (GSK980TDi manual §3.13: an alarm). The move is drawn as written.",
                "控制系统无法执行的图纸尺寸直接输入（G01 X_ Q_，GSK980TDi）：直线与须到达的轴方向夹角在 1° 以内，"
                "或应相交的两条直线夹角在 1° 以内（GSK980TDi 手册 §3.13：报警）。移动按所写绘制。"),
         RUN),
    Code("cutter-arc", ERROR,
         detail("Cutter radius compensation started or cancelled on a G02/G03 arc (PS0034; a warning where the "
                "control has no such alarm).",
                "在 G02/G03 圆弧上建立或取消刀具半径补偿（PS0034；系统无此报警时为警告）。"),
         RUN, (CUTTER_ARC_START,), ("cutter-arc",), milder=WARNING),
    Code("cutter-interference", ERROR,
         detail("Under G41/G42 the tool centre's path runs against a programmed block, the cutter is larger than "
                "an inside arc, or an inside corner's offsets do not meet (PS0041, PS0033; a warning where the "
                "control has no such alarm).",
                "G41/G42 下刀具中心轨迹与编程轨迹方向相反、刀具大于内侧圆弧，或内角处的偏置轨迹没有交点"
                "（PS0041、PS0033；系统无此报警时为警告）。"),
         RUN, (CUTTER_INTERFERENCE, CUTTER_NO_INTERSECTION), ("cutter-interference",), milder=WARNING),
    Code("cutter-plane", ERROR,
         detail("G17/G18/G19 changes the plane while cutter radius compensation is on (PS0037; a warning where the "
                "control has no such alarm).",
                "刀具半径补偿有效时用 G17/G18/G19 变更了平面（PS0037；系统无此报警时为警告）。"),
         RUN, (CUTTER_PLANE,), ("cutter-plane",), milder=WARNING),
    Code("cutter-corner", ERROR,
         detail("A chamfer or corner R (,C or ,R) on the block that starts or cancels cutter radius compensation, "
                "or changes between G41 and G42 (FANUC PS0039).",
                "在建立或取消刀具半径补偿、或 G41/G42 切换的程序段中指令了倒角或拐角R（,C 或 ,R）（FANUC PS0039）。"),
         RUN, (CUTTER_CORNER,), ("cutter-corner",)),
    Code("corner-fit", ERROR,
         detail("A chamfer or corner R (,C, ,R; the GSK980TDi's L, D) that does not fit its moves: a move too short, "
                "a radius too large (FANUC PS0055; the GSK980TDi's alarms of its manual §3.11.3).",
                "倒角或拐角R（,C、,R；GSK980TDi 的 L、D）无法插入其两段移动之间：移动过短或半径过大"
                "（FANUC PS0055；GSK980TDi 手册 §3.11.3 的报警）。"),
         RUN, (CORNER_FIT,), ("corner-fit",)),
    Code("corner-next", ERROR,
         detail("The block after a chamfer or corner R (,C, ,R) does not go on with a G01, G02 or G03 move in its "
                "plane: no move, a move off the plane (FANUC PS0051), or a G00, a cycle, a return (PS0052).",
                "倒角或拐角R（,C、,R）的下一程序段不是该平面内的 G01、G02 或 G03：它没有移动、移到平面之外"
                "（FANUC PS0051），或是 G00、循环、返回参考点等（PS0052）。"),
         RUN, (CORNER_NO_MOVE, CORNER_NOT_CUT), ("corner-next",)),
    Code("cutter-skip", ERROR,
         detail("A skip G31 commanded while cutter radius compensation (G41/G42) is in force (FANUC PS0035, "
                "Mitsubishi P608; a warning where the control's manual asks for G40 first but names no alarm).",
                "刀具半径补偿（G41/G42）有效时指令了跳转 G31（FANUC PS0035、三菱 P608；"
                "系统手册只要求先用 G40 取消而未给出报警时为警告）。"),
         RUN, (CUTTER_SKIP,), ("cutter-skip",), milder=WARNING),
    Code("polar-start", ERROR,
         detail("Polar coordinate interpolation (G12.1) started under feed per revolution (G99) or in tool nose "
                "radius compensation (GSK980TDi).",
                "在每转进给（G99）状态或刀尖半径补偿中启动极坐标插补（G12.1）（广数 GSK980TDi）。"),
         RUN, (POLAR_START,), ("polar-start",)),
    Code("cutter-offset", HINT,
         detail("G41/G42 with a D whose offset has no value in the run: the tool centre is drawn on the programmed "
                "path.",
                "G41/G42 所用 D 的补偿值在本次运行中没有数值：刀具中心按编程轨迹绘制。"), RUN),
    Code("unit-change", WARNING,
         detail("G20/G21 changes the unit after the program has moved: FANUC has it at the program's start, "
                "before the coordinate system is set.",
                "程序移动之后用 G20/G21 改变了单位：FANUC 要求在程序开头、设定坐标系之前指定。"), RUN),
    Code("not-executed", HINT,
         detail("Blocks that the analysis runs never reached.", "分析运行从未到达的程序段。"), RUN),
    Code("decimal-point", ERROR,
         detail("An M code written with a decimal point (alarm 007).", "M 代码带有小数点（报警 007）。"),
         BOTH, (DECIMAL_POINT,), milder=WARNING),
    Code("unknown-g-code", ERROR,
         detail("A G code the control lacks and the machine does not map to a call (010).",
                "系统没有、机床也未映射为调用的 G 代码（010）。"),
         BOTH, (IMPROPER_G_CODE,), milder=WARNING),
    Code("cycle-block", ERROR,
         detail("A lathe cycle block (G70-G76) the control refuses: P or Q missing, a depth, count, step or tool "
                "angle out of range, a chamfer or corner R in a thread block (warning where the alarm is not "
                "documented); a variable-lead thread (G34) whose lead is negative or would fall below zero; "
                "G27-G30 while a drilling canned cycle is in force (PS0044); G73/G83 with no Q or Q0 (PS0045); a FANUC "
                "drilling cycle using a Z or R given before the G80 or G00-G03 that cleared them (warning); GSK's "
                "G86 with I0 or I below R.",
                "系统拒绝的车床循环程序段（G70-G76）：缺少 P 或 Q，切深、次数、移动量或刀尖角度超出范围，"
                "螺纹程序段中有倒角或拐角 R（报警未见说明时为警告）；导程为负或将降到零以下的变导程螺纹（G34）；"
                "钻孔固定循环有效时指令 G27-G30（PS0044）；G73/G83 没有 Q 或 Q0（PS0045）；"
                "FANUC 钻孔循环使用了在清除它们的 G80 或 G00-G03 之前指令的 Z 或 R（警告）；"
                "广数 G86 的 I 为 0 或小于 R。"),
         BOTH, (THREAD_CORNER, CYCLE_P_Q_MISSING, CYCLE_BAD_VALUE, TOOL_ANGLE, THREAD_MIN_DEPTH, THREAD_DEPTH,
                GROOVE_RELIEF, GROOVE_END_POINT, GROOVE_AMOUNT, REPEAT_COUNT, ILLEGAL_LEAD, REFERENCE_IN_CYCLE,
                PECK_Q_MISSING, RECIPROCATION_AMOUNT),
         ("cycle-block",),
         milder=WARNING),
    Code("cycle-shape", ERROR,
         detail("A finishing shape of G70-G73 the control refuses: its block not found, its first or last block, "
                "a command not allowed in it, not monotone, past the start point (a warning where the control "
                "checks it only when set to).",
                "系统拒绝的 G70-G73 精加工形状：找不到其程序段，首段或末段不当，含有不允许的指令，不单调，"
                "超出起点（系统仅在设定时才检查的为警告）。"),
         BOTH, (CYCLE_BLOCK_NOT_FOUND, SHAPE_NOT_MONOTONE, SHAPE_FIRST_BLOCK, SHAPE_LAST_BLOCK, SHAPE_PAST_START,
                SHAPE_COMMAND, SHAPE_NOT_MONOTONE_X), ("cycle-shape", "shape-label", "shape-command"),
         milder=WARNING),
    Code("keyword-abbreviation", HINT,
         detail("A macro word written shortened (WH for WHILE), read as the whole word.",
                "宏语句关键字的缩写（WH 表示 WHILE），按完整关键字读取。")),
    Code("empty-if", WARNING,
         detail("An IF with nothing after it in its block: it governs nothing, the next block always runs.",
                "IF 之后同一程序段中没有内容：条件不控制任何代码，下一程序段总会执行。")),
    Code("after-tape-end", HINT,
         detail("Text after the closing % (the end of the tape), which is not read.",
                "结尾 %（纸带结束）之后的文字，不会被读取。")),
    Code("internal-error", ERROR,
         detail("The checker itself failed on this line, program or file (a bug to report).",
                "检查器本身在此行、程序或文件上出错（请报告此缺陷）。"),
         BOTH),
    Code("machine-file", ERROR,
         detail("The machine file (.cncmacro.toml) cannot be used: the defaults stand in.",
                "机床文件（.cncmacro.toml）无法使用：改用默认设置。")),
    Code("machine-file-note", INFORMATION,
         detail("What the machine file (.cncmacro.toml) adds to its profile: common variable ranges the profile "
                "does not list; and [calls] entries its profile does not call (a standard G code on GSK980TDi).",
                "机床文件（.cncmacro.toml）在其系统配置之外增加的内容：配置未列出的公共变量范围；以及其系统配置"
                "不作调用的 [calls] 项（GSK980TDi 的标准 G 代码）。")),
)  # fmt: skip

_BY_ALARM: dict[int, str] = {n: c.name for c in CODES.values() for n in c.alarms}
_BY_SUBJECT: dict[str, str] = {s: c.name for c in CODES.values() for s in c.subjects}


def default_severity(code: str, milder: bool = False) -> str:
    """The severity of a finding of ``code``: its default, or with ``milder`` the milder one the
    registry gives it. ``KeyError`` for a code that is not registered, ``ValueError`` for
    ``milder`` on a code that has no milder severity."""
    c = CODES[code]
    if not milder:
        return c.severity
    if c.milder is None:
        raise ValueError(f"diagnostic code '{code}' has no milder severity")
    return c.milder


def alarm_code(number: int, subject: str | None, macro_alarm_base: int) -> str:
    """The code of an alarm found by running: the interpreter's ``subject`` decides where it names
    one (it is more precise than a number that covers several things: ``L`` out of range is 119 on
    fanuc and 291 on gsk980tdi), else the alarm number; numbers from the dialect's macro-alarm base
    up (``#3000=n``, ``G65 H99``) are the program's own alarms, ``macro-alarm``."""
    if subject is not None and subject in _BY_SUBJECT:
        return _BY_SUBJECT[subject]
    code = _BY_ALARM.get(number)
    if code is not None:
        return code
    if number >= macro_alarm_base:
        return MACRO_ALARM
    return _UNKNOWN_ALARM
