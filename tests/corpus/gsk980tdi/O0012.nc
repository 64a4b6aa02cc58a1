(cncmacro: dialect=gsk980tdi)
O0012 (ONE ROUGHING PASS, INCREMENTAL U/W 外圆粗车一刀)
(起点: X 为上一刀直径, Z2; 每次调用直径减 3, 车到 Z-60)
G00 U-3
G01 W-62 F0.3
G00 U1
G00 W62
G00 U-1
M99
