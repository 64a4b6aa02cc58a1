%
O10100 (MACRO - TURN A PIN: A DIAMETER, B LENGTH, C CHAMFER)
(宏程序：车销轴。A 直径，B 长度，C 倒角；F 可选)
IF [#1 EQ #0] THEN #3000 = 1 (NO DIAMETER A)
IF [#2 EQ #0] THEN #3000 = 2 (NO LENGTH B)
IF [#3 EQ #0] THEN #3 = 0.5
IF [#9 EQ #0] THEN #9 = 0.15
#10 = #1 + 6.
G00 X#10 Z2. M08
G90 X[#1 + 2.] Z-#2 F[#9 * 1.5]
G01 X[#1 - 2. * #3] Z0.2 F#9
Z0.
X#1 Z-#3
Z-#2
X#10
G00 Z2.
M99
%
