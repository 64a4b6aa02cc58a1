(cncmacro: dialect=gsk980tdi)
O0300 (FACING - A LATHE PART)
G00 X44. Z2.
G01 Z0 F0.2
G01 X-1.
G00 Z2.
M30
