O2000 (cncmacro: dialect=gsk980tdi)
#100=5
#500=6
M30
