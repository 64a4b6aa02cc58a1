"""The probing and tool-setting macros a Haas mill keeps on the control (``PROGRAM_DOCS``, read by
the ``haas`` profile): what each does, the G65 arguments it reads and the variables it writes.

They are Renishaw's Inspection Plus cycles as Haas ships them (O9810–O9843), the WIPS probe on
and off (O9832/O9833) and Haas's tool-setter macros (O9023, O9853, O9995). docs/profiles.md
"Probing macros on the control" names the sources and says how each number was checked; what
the sources leave unclear (O9801–O9804, O9817, O9818, O9820, O9821, the arguments B of O9853 and
I, K of O9995) is left out. Every text is our own wording.

The results: Inspection Plus writes its measurements to #185–#199 on Haas, in the order Renishaw
uses on every control (X, Y, Z position, size, angle, the errors of each, true position, metal
condition, direction, out-of-tolerance and probe-error flags).
"""

from __future__ import annotations

from .tables import ProgramDoc

Arg = tuple[str, str, str]
Result = tuple[int, str, str]

# ---------------------------------------------------------------------------------------------
# arguments several Inspection Plus cycles read the same way

_Q: Arg = (
    "Q",
    "overtravel: how far past the expected surface the probe may move before the cycle gives up",
    "超程量：测头越过预期表面还可移动的距离，超过则循环报警",
)
_R_OUTSIDE: Arg = (
    "R",
    "radial clearance kept around the feature before the probe moves down beside it (negative: an "
    "internal feature with an island, measured from inside)",
    "测头下降前与特征保持的径向间隙（负值：带凸岛的内部特征，从内侧测量）",
)
_S: Arg = (
    "S",
    "work offset to set from the result: 1–6 for G54–G59, 154.01–154.99 for G154 P1–P99",
    "用测量结果设定的工件坐标系：1～6为G54～G59，154.01～154.99为G154 P1～P99",
)
_T: Arg = (
    "T",
    "tool offset to correct with the error (the tool that cut the feature)",
    "用误差修正的刀具补偿号（加工该特征的刀具）",
)
_F: Arg = (
    "F",
    "share of the error put into the tool offset, 0 to 1 (with T)",
    "误差计入刀具补偿的比例，0～1（与T一起使用）",
)
_V: Arg = (
    "V",
    "dead zone: an error smaller than this leaves the tool offset alone (with T)",
    "不修正区：误差小于此值时不修正刀具补偿（与T一起使用）",
)
_H: Arg = (
    "H",
    "tolerance on the size: outside it the cycle stops with a message",
    "尺寸公差：超差时循环停止并显示信息",
)
_M: Arg = (
    "M",
    "tolerance on the position: outside it the cycle stops with a message",
    "位置公差：超差时循环停止并显示信息",
)
_B: Arg = (
    "B",
    "tolerance on the angle: outside it the cycle stops with a message",
    "角度公差：超差时循环停止并显示信息",
)
_W: Arg = (
    "W",
    "print the result: 1 as the next feature, 2 as the first feature of a new component",
    "输出测量结果：1为下一个特征，2为新工件的第一个特征",
)
_UPDATES: tuple[Arg, ...] = (_S, _T, _F, _V, _H, _M, _W)

# ---------------------------------------------------------------------------------------------
# the results, #185-#199

_RESULTS: dict[int, tuple[str, str]] = {
    185: ("X position measured", "测得的X位置"),
    186: ("Y position measured", "测得的Y位置"),
    187: ("Z position measured", "测得的Z位置"),
    188: ("size measured (width or diameter)", "测得的尺寸（宽度或直径）"),
    189: ("angle measured", "测得的角度"),
    190: ("X error", "X误差"),
    191: ("Y error", "Y误差"),
    192: ("Z error", "Z误差"),
    193: ("size error", "尺寸误差"),
    194: ("angle error", "角度误差"),
    195: ("true position error", "真实位置误差"),
    196: ("metal condition", "材料状态"),
    197: ("direction indicator", "方向标志"),
    198: ("out-of-tolerance flag", "超差标志"),
    199: ("probe error flag", "测头错误标志"),
}


def _results(*numbers: int) -> tuple[Result, ...]:
    return tuple((n, *_RESULTS[n]) for n in numbers)


_FEATURE_RESULTS = _results(185, 186, 188, 190, 191, 193, 195, 196)

_CORNER_RESULTS: tuple[Result, ...] = (
    *_results(185, 186),
    (189, "angle of the X surface", "X向表面的角度"),
    *_results(190, 191),
    (192, "angle of the Y surface", "Y向表面的角度"),
    (193, "angle error of the Y surface", "Y向表面的角度误差"),
    (194, "angle error of the X surface", "X向表面的角度误差"),
    *_results(195),
)

_CORNER_ARGUMENTS: tuple[Arg, ...] = (
    ("X", "X position of the corner", "拐角的X位置"),
    ("Y", "Y position of the corner", "拐角的Y位置"),
    (
        "I",
        "spacing of the touches on the X face (with J, the corner's angle is measured too)",
        "X向表面上两次触碰的间距（与J同用时同时测量拐角角度）",
    ),
    ("J", "spacing of the touches on the Y face", "Y向表面上两次触碰的间距"),
    _Q,
    _B,
    _S,
    _M,
    _W,
)

PROGRAM_DOCS: tuple[ProgramDoc, ...] = (
    ProgramDoc(
        9023,
        "Tool setter: measure a tool (Haas WIPS)",
        "对刀仪：测量刀具（Haas WIPS）",
        "Measures the tool named by T on the table tool setter and writes its length offset (and its "
        "diameter with A13).",
        "在工作台对刀仪上测量T指定的刀具，写入其长度补偿（A13时同时写入直径）。",
        (
            (
                "A",
                "what to measure: 12 the length of a tool that does not turn (drill, tap), 23 the length of a "
                "turning tool (end or face mill), 13 its length and diameter",
                "测量方式：12为不旋转刀具（钻头、丝锥）的长度，23为旋转刀具（立铣刀、面铣刀）的长度，13为长度和直径",
            ),
            ("T", "tool number", "刀具号"),
            (
                "H",
                "approximate length of the tool, to come down to the setter quickly",
                "刀具的大致长度，用于快速接近对刀仪",
            ),
            ("D", "tool diameter", "刀具直径"),
        ),
    ),
    ProgramDoc(
        9810,
        "Protected positioning (Renishaw Inspection Plus)",
        "保护定位移动（雷尼绍 Inspection Plus）",
        "Moves at feed to the point given with the probe armed. If the stylus touches anything on the "
        "way the move stops and the cycle raises an alarm (path obstructed) instead of crashing the probe.",
        "测头启动状态下以进给速度移动到给定点。途中测针触碰到任何物体时移动停止并报警（路径受阻），以免撞坏测头。",
        (
            ("X", "X to move to", "移动目标X"),
            ("Y", "Y to move to", "移动目标Y"),
            ("Z", "Z to move to", "移动目标Z"),
            ("F", "feed of the move", "移动的进给速度"),
            (
                "M",
                "1: no alarm when the probe is triggered on the way (the program goes on)",
                "1：途中测头触发时不报警（程序继续）",
            ),
        ),
    ),
    ProgramDoc(
        9811,
        "Single surface measurement (Renishaw Inspection Plus)",
        "单面测量（雷尼绍 Inspection Plus）",
        "Touches one surface along X, Y or Z (give one of them: where the surface is expected) and "
        "reports where it is. With S it sets that axis of a work offset; with T it corrects a tool offset.",
        "沿X、Y或Z方向触碰一个表面（三者给一个：表面的预期位置），报告其实际位置。给S时设定工件坐标系的该轴，给T时修正刀具补偿。",
        (
            ("X", "expected X of the surface (measure along X)", "表面的预期X位置（沿X测量）"),
            ("Y", "expected Y of the surface (measure along Y)", "表面的预期Y位置（沿Y测量）"),
            ("Z", "expected Z of the surface (measure along Z)", "表面的预期Z位置（沿Z测量）"),
            _Q,
            *_UPDATES,
        ),
        _results(185, 186, 187, 188, 190, 191, 192, 193, 195, 196, 197, 198, 199),
    ),
    ProgramDoc(
        9812,
        "Web or pocket measurement (Renishaw Inspection Plus)",
        "凸台/槽宽测量（雷尼绍 Inspection Plus）",
        "Touches both sides of a pocket or slot (from inside) or of a web (from outside, going down to Z "
        "beside it) along X or Y, and reports its width and centre.",
        "沿X或Y方向触碰槽（从内侧）或凸台（从外侧，在其旁边下降到Z）的两侧，报告其宽度和中心。",
        (
            ("X", "nominal width along X", "X向名义宽度"),
            ("Y", "nominal width along Y", "Y向名义宽度"),
            ("Z", "Z at which a web is measured (leave out for a pocket)", "测量凸台时的Z高度（测槽时省略）"),
            _Q,
            _R_OUTSIDE,
            *_UPDATES,
        ),
        _FEATURE_RESULTS,
    ),
    ProgramDoc(
        9814,
        "Bore or boss measurement (Renishaw Inspection Plus)",
        "孔/圆柱凸台测量（雷尼绍 Inspection Plus）",
        "Touches a bore (from inside) or a boss (from outside, going down to Z beside it) at four points "
        "and reports its diameter and centre.",
        "在四点触碰孔（从内侧）或圆柱凸台（从外侧，在其旁边下降到Z），报告其直径和中心。",
        (
            ("D", "nominal diameter", "名义直径"),
            ("Z", "Z at which a boss is measured (leave out for a bore)", "测量凸台时的Z高度（测孔时省略）"),
            _Q,
            _R_OUTSIDE,
            *_UPDATES,
        ),
        _FEATURE_RESULTS,
    ),
    ProgramDoc(
        9815,
        "Internal corner (Renishaw Inspection Plus)",
        "内拐角测量（雷尼绍 Inspection Plus）",
        "Touches the two faces of an inside corner and reports where the corner is (and, with I and J, "
        "the angle of each face).",
        "触碰内拐角的两个面，报告拐角的位置（给I、J时还报告各面的角度）。",
        _CORNER_ARGUMENTS,
        _CORNER_RESULTS,
    ),
    ProgramDoc(
        9816,
        "External corner (Renishaw Inspection Plus)",
        "外拐角测量（雷尼绍 Inspection Plus）",
        "Touches the two faces of an outside corner and reports where the corner is (and, with I and J, "
        "the angle of each face).",
        "触碰外拐角的两个面，报告拐角的位置（给I、J时还报告各面的角度）。",
        _CORNER_ARGUMENTS,
        _CORNER_RESULTS,
    ),
    ProgramDoc(
        9819,
        "Holes or bosses on a pitch circle (Renishaw Inspection Plus)",
        "节圆上的孔或凸台测量（雷尼绍 Inspection Plus）",
        "Measures holes or bosses spaced evenly on a pitch circle and reports the circle's centre and "
        "diameter and the angle of the pattern.",
        "测量均布在节圆上的孔或凸台，报告节圆的中心、直径和分布角度。",
        (
            ("A", "angle of the first hole", "第一个孔的角度"),
            ("B", "number of holes or bosses", "孔或凸台的个数"),
            ("C", "diameter of the pitch circle", "节圆直径"),
            ("D", "diameter of each hole or boss", "每个孔或凸台的直径"),
            ("K", "Z at which the holes are measured", "测量孔时的Z高度"),
            ("Z", "Z at which the bosses are measured", "测量凸台时的Z高度"),
            _Q,
            _R_OUTSIDE,
            _S,
            _H,
            _M,
            _W,
        ),
        (
            *_results(185, 186, 188, 189, 190, 191),
            (192, "pitch circle diameter error", "节圆直径误差"),
            *_results(193, 194, 195, 196),
            (197, "number of the hole measured last", "最后测量的孔号"),
        ),
    ),
    ProgramDoc(
        9823,
        "Bore or boss on three points (Renishaw Inspection Plus)",
        "三点测孔/凸台（雷尼绍 Inspection Plus）",
        "Measures a bore or boss from three touches at the angles given, for a part of a circle that "
        "four touches cannot reach, and reports its diameter and centre.",
        "在给定的三个角度触碰孔或凸台（用于四点测量无法到达的部分圆弧），报告其直径和中心。",
        (
            ("A", "angle of the first touch", "第一点的角度"),
            ("B", "angle of the second touch", "第二点的角度"),
            ("C", "angle of the third touch", "第三点的角度"),
            ("D", "nominal diameter", "名义直径"),
            ("Z", "Z at which a boss is measured (leave out for a bore)", "测量凸台时的Z高度（测孔时省略）"),
            _Q,
            _R_OUTSIDE,
            *_UPDATES,
        ),
    ),
    ProgramDoc(
        9832,
        "Work probe on (Haas WIPS)",
        "工件测头开启（Haas WIPS）",
        "Turns the spindle probe on and gets it ready to measure. Call it once the probe is in the "
        "spindle, before the first measuring cycle; O9833 turns it off.",
        "开启主轴测头并使其进入测量准备状态。测头装入主轴后、第一个测量循环之前调用；用O9833关闭。",
    ),
    ProgramDoc(
        9833,
        "Work probe off (Haas WIPS)",
        "工件测头关闭（Haas WIPS）",
        "Turns the spindle probe off after the last measuring cycle, before the probe is put away.",
        "在最后一个测量循环之后、放回测头之前关闭主轴测头。",
    ),
    ProgramDoc(
        9843,
        "Angle of a surface (Renishaw Inspection Plus)",
        "表面角度测量（雷尼绍 Inspection Plus）",
        "Touches one surface at two points a distance D apart and reports how far it is turned from "
        "the nominal angle A; a program then rotates its coordinates (G68) by that error.",
        "在相距D的两点触碰同一表面，报告其相对名义角度A的偏转量；程序可据此用G68旋转坐标系。",
        (
            ("X", "expected X of the surface (measure along X)", "表面的预期X位置（沿X测量）"),
            ("Y", "expected Y of the surface (measure along Y)", "表面的预期Y位置（沿Y测量）"),
            ("D", "distance between the two touches", "两次触碰的间距"),
            ("A", "nominal angle of the surface", "表面的名义角度"),
            _Q,
            _B,
            _W,
        ),
        ((194, "angle error: how far the surface is turned from A", "角度误差：表面相对A的偏转量"),),
    ),
    ProgramDoc(
        9853,
        "Tool setter: broken tool check (Haas WIPS)",
        "对刀仪：断刀检测（Haas WIPS）",
        "Checks on the tool setter that the tool named by T is still as long as its offset says, and "
        "stops with an alarm when it is shorter by more than H (a broken tool). It cancels tool length "
        "compensation.",
        "在对刀仪上检查T指定的刀具长度是否仍与补偿值相符，短于补偿值超过H（断刀）时报警停止。执行后刀具长度补偿被取消。",
        (
            ("T", "tool number", "刀具号"),
            ("H", "how much shorter the tool may be before it counts as broken", "判为断刀前允许的长度减少量"),
        ),
    ),
    ProgramDoc(
        9995,
        "Tool setter: measure a tool, older call (Haas WIPS)",
        "对刀仪：测量刀具，旧调用方式（Haas WIPS）",
        "Haas's general WIPS macro; with A0 it measures the tool in the spindle on the tool setter, as O9023 does.",
        "Haas 的通用 WIPS 宏程序；A0 时在对刀仪上测量主轴上的刀具，与O9023相同。",
        (
            ("A", "operation: 0 measures a tool", "操作：0为测量刀具"),
            (
                "B",
                "tool type: 1 drill, 2 tap, 3 face mill, 4 end mill, 5 spot drill, 6 ball nose, 7 probe",
                "刀具类型：1钻头，2丝锥，3面铣刀，4立铣刀，5定心钻，6球头刀，7测头",
            ),
            (
                "C",
                "how: 1 the length of a turning tool, 2 of a tool that does not turn, 3 length and diameter",
                "测量方式：1为旋转刀具的长度，2为不旋转刀具的长度，3为长度和直径",
            ),
            ("T", "tool number", "刀具号"),
            ("E", "approximate length of the tool", "刀具的大致长度"),
            ("D", "tool diameter", "刀具直径"),
        ),
    ),
)
