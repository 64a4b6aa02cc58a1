(cncmacro: dialect=gsk980tdi)
O9020 (PART CATCHER AND COUNTER - CALLED BY M31 LIKE G65 零件收集与计数)
(#3901 已加工零件数, #3902 目标件数; #500 累计件数, 断电保持)
(#1 A = 1 时不计数: 试切件)
IF[#1==1]GOTO10
#3901=#3901+1
#500=#500+1
N10 M10 (接料器伸出 CATCHER OUT)
G04 X1.0
M11 (接料器收回 CATCHER IN)
IF[#3901<#3902]GOTO20
M00 (BATCH COMPLETE 本批零件已完成: 换料后按循环启动)
N20 M99
