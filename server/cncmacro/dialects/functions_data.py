"""Functions, operators and macro statements shared by both dialects, and the GSK ``G65 Hm`` forms.

``FUNCTIONS`` documents what a programmer writes in a macro expression or statement: the
functions (angles in degrees), the binary operators AND OR XOR MOD, the relations EQ NE GT GE LT
LE, and the statements IF GOTO THEN WHILE DO END and the external output commands POPEN PCLOS
DPRNT BPRNT, following chapters 5 and 7 of seed 003 and docs/semantics.md §3-§5. ``GSK_H_CODES``
documents the GSK980TDi macro arithmetic and branch commands ``G65 Hm P#i Q#j R#k`` of seed 000
§3.28.2 (docs/semantics.md §7): P is the destination variable (or the sequence number for H80-H86 and
the alarm number for H99), Q and R are variables or constants written without ``#``.
``EXTRA_FUNCTIONS`` documents the functions and forms a dialect adds to the common set (the
FANUC 30i's POW, ADP, PRM and ATAN[a,b]; the GSK980TDi's random numbers RAND and SRAND, §3.29.1
of its manual; the block IF's words, ``BLOCK_IF_WORDS``); a dialect
names the ones it has in ``Dialect.extra_functions`` or has them by its ``block_if`` switch
(docs/profiles.md). Each row says what kind of word it is
(``tables.FUNCTION_KINDS``: a function, an operator or a statement word), by which the editor
colours and completes it.
"""

from __future__ import annotations

from .alarms import ARGUMENT_RANGE, DIVISION_BY_ZERO, SEQUENCE_NUMBER
from .tables import FUNCTION, OPERATOR, STATEMENT, FunctionDoc

FUNCTIONS: tuple[FunctionDoc, ...] = (
    # functions
    FunctionDoc(
        "SIN",
        FUNCTION,
        "SIN[a]",
        "Sine of a; a in degrees (90°30' is written 90.5)",
        "正弦，a以度为单位（90°30'写作90.5）",
    ),
    FunctionDoc("COS", FUNCTION, "COS[a]", "Cosine of a; a in degrees", "余弦，a以度为单位"),
    FunctionDoc("TAN", FUNCTION, "TAN[a]", "Tangent of a; a in degrees", "正切，a以度为单位"),
    FunctionDoc(
        "ASIN",
        FUNCTION,
        "ASIN[a]",
        "Arc sine of a, in degrees; a outside -1 to 1 is {alarm}",
        "反正弦，结果以度为单位；a超出-1～1时为{alarm}",
        ARGUMENT_RANGE,
    ),
    FunctionDoc(
        "ACOS",
        FUNCTION,
        "ACOS[a]",
        "Arc cosine of a, in degrees; a outside -1 to 1 is {alarm}",
        "反余弦，结果以度为单位；a超出-1～1时为{alarm}",
        ARGUMENT_RANGE,
    ),
    FunctionDoc(
        "ATAN",
        FUNCTION,
        "ATAN[a]/[b]",
        "Arc tangent of a/b taking the signs of both into account: the angle of the point (b, a), 0 to 360 degrees",
        "反正切a/b，按a、b的符号确定象限：点(b, a)的角度，结果为0～360度",
    ),
    FunctionDoc(
        "ATAN",
        FUNCTION,
        "ATAN[a]",
        "Arc tangent of a, -90 to 90 degrees",
        "反正切a，结果为-90～90度",
    ),
    FunctionDoc(
        "SQRT",
        FUNCTION,
        "SQRT[a]",
        "Square root of a; a negative is {alarm}",
        "平方根；a为负时为{alarm}",
        ARGUMENT_RANGE,
    ),
    FunctionDoc("ABS", FUNCTION, "ABS[a]", "Absolute value of a", "绝对值"),
    FunctionDoc(
        "ROUND",
        FUNCTION,
        "ROUND[a]",
        "Rounds half away from zero: to an integer in an assignment or condition (ROUND[2.5] = 3, "
        "ROUND[-2.5] = -3); inside an NC address to the address's least increment (0.001 mm, 0.0001 inch "
        "under G20, 0.001° for A, B, C)",
        "四舍五入（远离零）：在赋值或条件中取整（ROUND[2.5]=3，ROUND[-2.5]=-3）；"
        "在NC地址中舍入到该地址的最小设定单位（0.001 mm，G20时0.0001 inch，A、B、C为0.001°）",
    ),
    FunctionDoc(
        "FIX",
        FUNCTION,
        "FIX[a]",
        "Drops the fraction, toward zero: FIX[1.7] = 1, FIX[-1.7] = -1",
        "下取整（舍去小数，向零取整）：FIX[1.7]=1，FIX[-1.7]=-1",
    ),
    FunctionDoc(
        "FUP",
        FUNCTION,
        "FUP[a]",
        "Raises any fraction to the next integer away from zero: FUP[1.2] = 2, FUP[-1.2] = -2",
        "上取整（有小数即进位，远离零取整）：FUP[1.2]=2，FUP[-1.2]=-2",
    ),
    FunctionDoc(
        "LN",
        FUNCTION,
        "LN[a]",
        "Natural logarithm of a; a zero or negative is {alarm}",
        "自然对数；a小于等于0时为{alarm}",
        ARGUMENT_RANGE,
    ),
    FunctionDoc("EXP", FUNCTION, "EXP[a]", "e raised to the power a", "指数函数，e的a次方"),
    FunctionDoc(
        "BIN",
        FUNCTION,
        "BIN[a]",
        "Converts a BCD value to binary, for signals exchanged with the PMC (BIN[37] = 25: 0x25 read as BCD)",
        "BCD码转换为二进制，用于与PMC的信号交换（BIN[37]=25，即BCD码0x25）",
    ),
    FunctionDoc(
        "BCD",
        FUNCTION,
        "BCD[a]",
        "Converts a binary value to BCD, for signals exchanged with the PMC (BCD[25] = 37, i.e. 0x25)",
        "二进制转换为BCD码，用于与PMC的信号交换（BCD[25]=37，即0x25）",
    ),
    # operators
    FunctionDoc(
        "AND",
        OPERATOR,
        "a AND b",
        "Bitwise AND of the integers a and b (same precedence as * and /); "
        "between two bracketed conditions in IF/WHILE it means both are true",
        "按位与（整数逐位运算，优先级同*和/）；在IF/WHILE中连接两个带括号的条件时表示两者都成立",
    ),
    FunctionDoc(
        "OR",
        OPERATOR,
        "a OR b",
        "Bitwise OR of the integers a and b (same precedence as + and -); "
        "between two bracketed conditions in IF/WHILE it means either is true",
        "按位或（整数逐位运算，优先级同+和-）；在IF/WHILE中连接两个带括号的条件时表示任一成立",
    ),
    FunctionDoc(
        "XOR",
        OPERATOR,
        "a XOR b",
        "Bitwise exclusive OR of the integers a and b (same precedence as + and -)",
        "按位异或（整数逐位运算，优先级同+和-）",
    ),
    FunctionDoc(
        "MOD",
        OPERATOR,
        "a MOD b",
        "Remainder of a divided by b (same precedence as * and /); b = 0 is {alarm}",
        "a除以b的余数（优先级同*和/）；b为0时为{alarm}",
        DIVISION_BY_ZERO,
    ),
    # relations (only inside IF and WHILE conditions)
    FunctionDoc(
        "EQ",
        OPERATOR,
        "[a EQ b]",
        "True when a equals b exactly. On fanuc vacant differs from 0 here (vacant EQ vacant is true, "
        "0 EQ vacant is false); on gsk980tdi vacant counts as 0",
        "a等于b时成立（精确比较）。fanuc中空与0不同（空EQ空成立，0 EQ空不成立）；gsk980tdi中空按0处理",
    ),
    FunctionDoc(
        "NE",
        OPERATOR,
        "[a NE b]",
        "True when a differs from b. On fanuc vacant differs from 0 here (vacant NE 0 is true); "
        "on gsk980tdi vacant counts as 0",
        "a不等于b时成立。fanuc中空与0不同（空NE 0成立）；gsk980tdi中空按0处理",
    ),
    FunctionDoc(
        "GT", OPERATOR, "[a GT b]", "True when a is greater than b (vacant counts as 0)", "a大于b时成立（空按0处理）"
    ),
    FunctionDoc(
        "GE",
        OPERATOR,
        "[a GE b]",
        "True when a is greater than or equal to b (vacant counts as 0)",
        "a大于或等于b时成立（空按0处理）",
    ),
    FunctionDoc(
        "LT", OPERATOR, "[a LT b]", "True when a is less than b (vacant counts as 0)", "a小于b时成立（空按0处理）"
    ),
    FunctionDoc(
        "LE",
        OPERATOR,
        "[a LE b]",
        "True when a is less than or equal to b (vacant counts as 0)",
        "a小于或等于b时成立（空按0处理）",
    ),
    # statements
    FunctionDoc(
        "IF",
        STATEMENT,
        "IF [condition] GOTO n / IF [condition] THEN statement",
        "Conditional branch: when the condition is true, jump to block Nn, or run the one macro statement "
        "after THEN; otherwise go on with the next block",
        "条件转移：条件成立时转到Nn程序段，或执行THEN后面的一条宏程序语句；不成立时执行下一程序段",
    ),
    FunctionDoc(
        "GOTO",
        STATEMENT,
        "GOTO n",
        "Jump to the block labelled Nn (n 1-99999, may be a variable or expression), searching forward "
        "to the end of the program and then from its start; not found is {alarm}",
        "无条件转移到顺序号为Nn的程序段（n为1～99999，可用变量或表达式），先向后检索到程序结尾，"
        "再从程序开头检索；找不到时为{alarm}",
        SEQUENCE_NUMBER,
    ),
    FunctionDoc(
        "THEN",
        STATEMENT,
        "IF [condition] THEN statement",
        "Runs the single macro statement that follows when the IF condition is true",
        "IF条件成立时执行其后的一条宏程序语句",
    ),
    FunctionDoc(
        "WHILE",
        STATEMENT,
        "WHILE [condition] DO m",
        "Loop: while the condition is true, run the blocks from DO m to END m (m = 1, 2 or 3); "
        "when it is false, go on after END m",
        "循环：条件成立时执行DO m到END m之间的程序段（m=1、2、3），不成立时执行END m之后的程序段",
    ),
    FunctionDoc(
        "DO",
        STATEMENT,
        "DO m",
        "Start of the loop with identification number m (1-3); loops nest at most 3 deep. "
        "DO m without WHILE loops forever",
        "识别号为m（1～3）的循环开始；循环最多嵌套3层。没有WHILE的DO m为无限循环",
    ),
    FunctionDoc(
        "END",
        STATEMENT,
        "END m",
        "End of the loop started by DO m; goes back to its WHILE",
        "DO m循环的结束，返回到对应的WHILE",
    ),
    FunctionDoc(
        "POPEN",
        FUNCTION,
        "POPEN",
        "Opens the external output device (reader/punch interface) before DPRNT or BPRNT",
        "打开外部输出设备（阅读机/穿孔机接口），在DPRNT或BPRNT之前指令",
    ),
    FunctionDoc(
        "PCLOS",
        FUNCTION,
        "PCLOS",
        "Closes the external output device opened by POPEN",
        "关闭由POPEN打开的外部输出设备",
    ),
    FunctionDoc(
        "DPRNT",
        FUNCTION,
        "DPRNT[text #i[a b] ...]",
        "Outputs text and variable values as decimal text; #i[a b] prints #i with a digits before and b "
        "after the decimal point",
        "以十进制文本输出字符和变量值；#i[a b]表示#i输出整数部分a位、小数部分b位",
    ),
    FunctionDoc(
        "BPRNT",
        FUNCTION,
        "BPRNT[text #i[c] ...]",
        "Outputs text as characters and variable values in binary; #i[c] sends #i as a 32-bit binary "
        "integer with c digits after the decimal point",
        "输出字符和二进制的变量值；#i[c]表示#i按小数部分c位转换为32位二进制整数输出",
    ),
)

# the statement words of the block form of IF, which a dialect with ``Dialect.block_if`` has
# (``Dialect.functions``), named by their signatures
BLOCK_IF_WORDS = frozenset({"IF [condition] THEN … ELSE … ENDIF", "ELSE", "ENDIF"})

EXTRA_FUNCTIONS: tuple[FunctionDoc, ...] = (
    FunctionDoc(
        "IF",
        STATEMENT,
        "IF [condition] THEN … ELSE … ENDIF",
        "Block IF: IF [condition] THEN alone on its line runs the blocks up to its ELSE when the condition is "
        "true, else the blocks after the ELSE up to its ENDIF (the ELSE part may be left out); blocks nest",
        "块形式IF：单独一行的IF [条件] THEN在条件成立时执行其后直到ELSE的程序段，不成立时执行ELSE之后直到ENDIF的"
        "程序段（可以没有ELSE部分）；可以嵌套",
    ),
    FunctionDoc(
        "ELSE",
        STATEMENT,
        "ELSE",
        "Starts the blocks a block IF [condition] THEN runs when its condition is false; from the blocks before "
        "it the run goes on after the ENDIF",
        "块形式IF [条件] THEN的条件不成立时所执行程序段的开始；从其前面的程序段执行到此时转到ENDIF之后",
    ),
    FunctionDoc(
        "ENDIF",
        STATEMENT,
        "ENDIF",
        "Ends the block IF [condition] THEN opened before it",
        "结束其前面的块形式IF [条件] THEN",
    ),
    FunctionDoc(
        "ATAN",
        FUNCTION,
        "ATAN[a,b]",
        "Arc tangent of a/b written with a comma: the same as ATAN[a]/[b], the angle of the point (b, a), "
        "0 to 360 degrees",
        "反正切a/b的逗号写法：与ATAN[a]/[b]相同，点(b, a)的角度，结果为0～360度",
    ),
    FunctionDoc(
        "RAND",
        FUNCTION,
        "RAND[a]",
        "A random number between 0 and a, never 0 (GSK980TDi); a check cannot foresee it, so a condition on it "
        "is not judged there, and a simulated run reads it as vacant",
        "产生0到a之间的随机数，不包括0（GSK980TDi）；检查时无法预知其值，因此不判断以它为条件的语句，模拟运行时按空变量读取",
    ),
    FunctionDoc(
        "SRAND",
        FUNCTION,
        "SRAND[a,b]",
        "A random number between a and b (GSK980TDi); a check cannot foresee it, so a condition on it is not "
        "judged there, and a simulated run reads it as vacant",
        "产生a到b之间的随机数（GSK980TDi）；检查时无法预知其值，因此不判断以它为条件的语句，模拟运行时按空变量读取",
    ),
    FunctionDoc(
        "POW",
        FUNCTION,
        "POW[a,b]",
        "a to the power b (POW[2,3] = 8); a negative a with a fractional b, or 0 to a negative power, is {alarm}",
        "a的b次方（POW[2,3]=8）；a为负数而b不是整数，或0的负数次方时为{alarm}",
        ARGUMENT_RANGE,
    ),
    FunctionDoc(
        "ADP",
        FUNCTION,
        "ADP[a]",
        "Adds the decimal point to an argument written without one, as if X10 had been X10. (not 10 least "
        "increments); with calculator-type input, or for a value written with a point, the value stays as it is",
        "为不带小数点指定的自变量补上小数点，使X10按X10.读取（而不是10个最小设定单位）；"
        "计算器型输入时，或自变量带小数点时，数值不变",
    ),
    FunctionDoc(
        "PRM",
        FUNCTION,
        "PRM[n]",
        "Reads parameter n (the simulated machine has no parameters: it reads 0)",
        "读取参数n（模拟机床没有参数，读出为0）",
    ),
    FunctionDoc(
        "PRM",
        FUNCTION,
        "PRM[n,axis]",
        "Reads axis-type parameter n for the axis numbered axis (1 is the first axis); 0 on the simulated machine",
        "读取轴型参数n中第axis轴的值（1为第1轴）；模拟机床读出为0",
    ),
    FunctionDoc(
        "PRM",
        FUNCTION,
        "PRM[n]/[bit]",
        "Reads bit bit (0-7) of bit-type parameter n; 0 on the simulated machine",
        "读取位型参数n的第bit位（0～7）；模拟机床读出为0",
    ),
    FunctionDoc(
        "PRM",
        FUNCTION,
        "PRM[n,axis]/[bit]",
        "Reads bit bit of axis-type bit parameter n for the axis numbered axis; 0 on the simulated machine",
        "读取轴型位参数n中第axis轴的第bit位；模拟机床读出为0",
    ),
)


GSK_H_CODES: tuple[FunctionDoc, ...] = (
    FunctionDoc(
        "H01",
        STATEMENT,
        "G65 H01 P#i Q#j",
        "Assignment: #i = #j (Q-#j gives #i = -#j)",
        "赋值：#i = #j（Q-#j时#i = -#j）",
    ),
    FunctionDoc("H02", STATEMENT, "G65 H02 P#i Q#j R#k", "Decimal addition: #i = #j + #k", "十进制加法：#i = #j + #k"),
    FunctionDoc(
        "H03", STATEMENT, "G65 H03 P#i Q#j R#k", "Decimal subtraction: #i = #j - #k", "十进制减法：#i = #j - #k"
    ),
    FunctionDoc(
        "H04", STATEMENT, "G65 H04 P#i Q#j R#k", "Decimal multiplication: #i = #j × #k", "十进制乘法：#i = #j × #k"
    ),
    FunctionDoc(
        "H05",
        STATEMENT,
        "G65 H05 P#i Q#j R#k",
        "Decimal division: #i = #j ÷ #k (#k = 0 is alarm 112)",
        "十进制除法：#i = #j ÷ #k（#k为0时为112号报警）",
    ),
    FunctionDoc("H11", STATEMENT, "G65 H11 P#i Q#j R#k", "Binary OR: #i = #j OR #k", "二进制或运算：#i = #j OR #k"),
    FunctionDoc("H12", STATEMENT, "G65 H12 P#i Q#j R#k", "Binary AND: #i = #j AND #k", "二进制与运算：#i = #j AND #k"),
    FunctionDoc(
        "H13", STATEMENT, "G65 H13 P#i Q#j R#k", "Binary exclusive OR: #i = #j XOR #k", "二进制异或：#i = #j XOR #k"
    ),
    FunctionDoc("H21", STATEMENT, "G65 H21 P#i Q#j", "Square root: #i = √#j", "十进制开平方：#i = √#j"),
    FunctionDoc("H22", STATEMENT, "G65 H22 P#i Q#j", "Absolute value: #i = |#j|", "十进制取绝对值：#i = |#j|"),
    FunctionDoc(
        "H23",
        STATEMENT,
        "G65 H23 P#i Q#j R#k",
        "Remainder: #i = #j - TRUNC(#j ÷ #k) × #k, TRUNC dropping the fraction "
        "(G65 H23 P#101 Q#4120 R100 gives the offset number of the T code)",
        "十进制取余数：#i = #j - TRUNC(#j ÷ #k) × #k，TRUNC为舍去小数部分"
        "（G65 H23 P#101 Q#4120 R100取得T代码的刀偏号）",
    ),
    FunctionDoc("H24", STATEMENT, "G65 H24 P#i Q#j", "BCD to binary: #i = BIN(#j)", "BCD码转换为二进制：#i = BIN(#j)"),
    FunctionDoc("H25", STATEMENT, "G65 H25 P#i Q#j", "Binary to BCD: #i = BCD(#j)", "二进制转换为BCD码：#i = BCD(#j)"),
    FunctionDoc(
        "H26",
        STATEMENT,
        "G65 H26 P#i Q#j R#k",
        "Multiply then divide: #i = #i × #j ÷ #k",
        "十进制乘除运算：#i = #i × #j ÷ #k",
    ),
    FunctionDoc(
        "H27",
        STATEMENT,
        "G65 H27 P#i Q#j R#k",
        "Compound square root: #i = √(#j² + #k²)",
        "复合平方根：#i = √(#j² + #k²)",
    ),
    FunctionDoc(
        "H31",
        STATEMENT,
        "G65 H31 P#i Q#j R#k",
        "Sine: #i = #j × sin(#k), #k in degrees",
        "正弦：#i = #j × sin(#k)，#k单位为度",
    ),
    FunctionDoc(
        "H32",
        STATEMENT,
        "G65 H32 P#i Q#j R#k",
        "Cosine: #i = #j × cos(#k), #k in degrees",
        "余弦：#i = #j × cos(#k)，#k单位为度",
    ),
    FunctionDoc(
        "H33",
        STATEMENT,
        "G65 H33 P#i Q#j R#k",
        "Tangent: #i = #j × tan(#k), #k in degrees",
        "正切：#i = #j × tan(#k)，#k单位为度",
    ),
    FunctionDoc(
        "H34",
        STATEMENT,
        "G65 H34 P#i Q#j R#k",
        "Arc tangent: #i = ATAN(#j ÷ #k), in degrees",
        "反正切：#i = ATAN(#j ÷ #k)，单位为度",
    ),
    FunctionDoc("H80", STATEMENT, "G65 H80 Pn", "Unconditional branch: go to block Nn", "无条件转移：跳转至Nn程序段"),
    FunctionDoc(
        "H81",
        STATEMENT,
        "G65 H81 Pn Q#j R#k",
        "Conditional branch: go to block Nn if #j = #k, else go on",
        "条件转移：#j = #k时跳转至Nn程序段，否则顺序执行",
    ),
    FunctionDoc(
        "H82",
        STATEMENT,
        "G65 H82 Pn Q#j R#k",
        "Conditional branch: go to block Nn if #j ≠ #k, else go on",
        "条件转移：#j ≠ #k时跳转至Nn程序段，否则顺序执行",
    ),
    FunctionDoc(
        "H83",
        STATEMENT,
        "G65 H83 Pn Q#j R#k",
        "Conditional branch: go to block Nn if #j > #k, else go on",
        "条件转移：#j > #k时跳转至Nn程序段，否则顺序执行",
    ),
    FunctionDoc(
        "H84",
        STATEMENT,
        "G65 H84 Pn Q#j R#k",
        "Conditional branch: go to block Nn if #j < #k, else go on",
        "条件转移：#j < #k时跳转至Nn程序段，否则顺序执行",
    ),
    FunctionDoc(
        "H85",
        STATEMENT,
        "G65 H85 Pn Q#j R#k",
        "Conditional branch: go to block Nn if #j ≥ #k, else go on",
        "条件转移：#j ≥ #k时跳转至Nn程序段，否则顺序执行",
    ),
    FunctionDoc(
        "H86",
        STATEMENT,
        "G65 H86 Pn Q#j R#k",
        "Conditional branch: go to block Nn if #j ≤ #k, else go on",
        "条件转移：#j ≤ #k时跳转至Nn程序段，否则顺序执行",
    ),
    FunctionDoc(
        "H99",
        STATEMENT,
        "G65 H99 Pn",
        "User alarm 5900+n (H99 P15 raises alarm 5915); a message may follow as (/text)",
        "产生用户报警 5900+n（H99 P15 产生报警 5915）；可用 (/报警内容) 附加报警信息",
    ),
)
