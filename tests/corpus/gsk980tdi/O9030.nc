(cncmacro: dialect=gsk980tdi)
O9030 (DRILL ONE CROSS HOLE WITH THE LIVE TOOL AT THIS Z - G66 模态调用 动力头钻孔)
(G66 P9030 X=孔底直径 R=安全直径 F=进给; 在 G66 与 G67 之间每次移动后钻一孔)
IF[#24==#0]THEN #3000=1(X 孔底直径未指定)
IF[#18==#0]THEN #18=#5001
G01 X#24 F#9
G04 X0.3
G00 X#18
#160=#160+1 (已钻孔数)
M99
