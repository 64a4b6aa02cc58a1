O2002 (cncmacro: dialect=gsk980tdi)
#101=3
M99 P30
