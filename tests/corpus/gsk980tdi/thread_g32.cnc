(cncmacro: dialect=gsk980tdi)
O0203 (M24X2 外螺纹 G32, 调用 P[螺纹切削])
(工件零点在右端面中心; 螺纹 Z0 到 Z-30, 退刀槽在 Z-30 到 Z-34)
G00 X100 Z100
T0303 (3 号刀: 60 度螺纹刀)
M03 S500
G00 X28 Z5 (导入起点 Z5)
G65 P[螺纹切削] X24 Z-31 F2 Q7
IF[#150==7]GOTO10
#3000=20(螺纹走刀次数不对 WRONG NUMBER OF PASSES)
N10 G00 X100 Z100
M05
M30
