(cncmacro: dialect=gsk980tdi)
O0216 (M30X1.5 EXTERNAL AND M40X2 INTERNAL - G76 复合螺纹)
(外螺纹在轴端 长 25; 内螺纹在孔口 长 20, 底孔已镗至 D37.8)
(G76 P m r a: m 精车次数, r 倒角量 0.1L 单位, a 刀尖角; Q 最小切深 um; R 精车余量)
(第二段 P 牙高 um 半径值, Q 第一刀切深 um 半径值)
G00 X100 Z100
T0303 (外螺纹刀)
M03 S600
G99
G00 X32 Z5 M08
G76 P020560 Q50 R0.05
G76 X28.05 Z-25 P975 Q400 F1.5
G00 X100 Z100
T0404 (内螺纹刀)
M03 S500
G00 X36 Z5
G76 P020560 Q50 R0.05 (内螺纹)
G76 X40 Z-20 P1300 Q400 F2 (大径 D40, 牙高 1.3)
G00 Z10
G00 X100 Z100 M09
M05
M30
