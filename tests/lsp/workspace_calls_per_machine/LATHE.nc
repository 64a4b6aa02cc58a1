O3000 (cncmacro: dialect=gsk980tdi)
#101=4
M99
