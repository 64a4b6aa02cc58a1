;; SYNTAX TEST "source.cnc-macro" "gsk980tdi: C-style relations, #9 indirection, G65 H forms, bracketed program names"
(cncmacro: dialect=gsk980tdi)
;; <~-------- keyword.other.directive.cnc-macro
IF[#100<100]GOTO10;
;; ^^^^ variable.other.common.cnc-macro
;;     ^ keyword.operator.comparison.cnc-macro
;;      ^^^ constant.numeric.integer.cnc-macro
;;          ^^^^ keyword.control.goto.cnc-macro
;;              ^^ entity.name.tag.label.reference.cnc-macro
;;                ^ punctuation.terminator.end-of-block.cnc-macro
IF[#100==100]THEN #100=0;
;;     ^^ keyword.operator.comparison.cnc-macro - keyword.operator.assignment.cnc-macro
;;           ^^^^ keyword.control.conditional.cnc-macro
;;                    ^ keyword.operator.assignment.cnc-macro - keyword.operator.comparison.cnc-macro
IF[#1!=#2]GOTO1
;;   ^^ keyword.operator.comparison.cnc-macro
IF[3<>2]GOTO2
;;  ^^ keyword.operator.comparison.cnc-macro
IF[#1<=#2]GOTO1
;;   ^^ keyword.operator.comparison.cnc-macro
IF[#1>=#2]GOTO1
;;   ^^ keyword.operator.comparison.cnc-macro
IF[[#101>0] AND [#102>0]]GOTO3
;;      ^ keyword.operator.comparison.cnc-macro
;;          ^^^ keyword.operator.logical.cnc-macro
;;                   ^ keyword.operator.comparison.cnc-macro
#9102=#9102+#21;
;; <- variable.other.indirect.cnc-macro punctuation.definition.variable.cnc-macro
;; <~---- variable.other.indirect.cnc-macro
;;    ^^^^^ variable.other.indirect.cnc-macro
;;          ^^^ variable.other.local.cnc-macro
G65 H01 P#100 Q#101 R5
;; <--- meta.statement.h-code.cnc-macro keyword.control.call.macro.cnc-macro
;;  ^^^ support.function.h-code.cnc-macro
;;      ^ support.type.address.cnc-macro
;;       ^^^^ variable.other.common.cnc-macro
;;            ^ support.type.address.cnc-macro
;;             ^^^^ variable.other.common.cnc-macro
;;                  ^ support.type.address.cnc-macro
;;                   ^ constant.numeric.integer.cnc-macro
G65 H23 P#101 Q#4120 R100; (获取刀偏号)
;;  ^^^ support.function.h-code.cnc-macro
;;             ^^^^^ variable.language.system.cnc-macro
;;                       ^ punctuation.terminator.end-of-block.cnc-macro
;;                         ^^^^^^^ comment.line.parenthesized.cnc-macro
G65 H01 P#102 Q-#102
;;            ^ support.type.address.cnc-macro
;;             ^ keyword.operator.arithmetic.cnc-macro
;;              ^^^^ variable.other.common.cnc-macro
N25 G65 H86 P25 Q#101 R#102
;; <--- entity.name.tag.label.cnc-macro
;;  ^^^ keyword.control.call.macro.cnc-macro
;;      ^^^ support.function.h-code.cnc-macro
;;          ^ support.type.address.cnc-macro
;;           ^^ entity.name.tag.label.reference.cnc-macro
;;               ^^^^ variable.other.common.cnc-macro
G65 H80 P10
;;  ^^^ support.function.h-code.cnc-macro
;;       ^^ entity.name.tag.label.reference.cnc-macro
G65 H99 P15
;;  ^^^ support.function.h-code.cnc-macro
;;      ^ support.type.address.cnc-macro
;;       ^^ constant.numeric.integer.cnc-macro - entity.name.tag.label.reference.cnc-macro
g65 h02 p#101 q#101 r#106
;; <--- keyword.control.call.macro.cnc-macro
;;  ^^^ support.function.h-code.cnc-macro
;;      ^ support.type.address.cnc-macro
G65 P[CUT] L2 ;
;; <--- keyword.control.call.macro.cnc-macro
;;  ^ support.type.address.cnc-macro
;;   ^ punctuation.section.brackets.begin.cnc-macro
;;    ^^^ entity.name.function.program.cnc-macro
;;       ^ punctuation.section.brackets.end.cnc-macro
;;         ^ support.type.address.cnc-macro
;;          ^ constant.numeric.integer.cnc-macro
;;            ^ punctuation.terminator.end-of-block.cnc-macro
G65 P[螺纹切削] ;
;;    ^^^^ entity.name.function.program.cnc-macro
G66 P[O1004] L3
;; <--- keyword.control.call.macro.cnc-macro
;;    ^^^^^ entity.name.function.program.cnc-macro
G65 P[#100] L2
;;  ^ support.type.address.cnc-macro
;;   ^ punctuation.section.brackets.begin.cnc-macro
;;    ^^^^ variable.other.common.cnc-macro - entity.name.function.program.cnc-macro
M98 P[O0023] L3 ;
;; <--- keyword.control.call.subprogram.cnc-macro
;;    ^^^^^ entity.name.function.program.cnc-macro
G65 P9580 U-0.01 W-0.01; (调用宏程序补偿刀具磨损)
;;   ^^^^ entity.name.function.program.cnc-macro
;;        ^ variable.parameter.argument.cnc-macro
;;         ^^^^^ constant.numeric.decimal.cnc-macro
;;               ^ variable.parameter.argument.cnc-macro
;;                     ^ punctuation.terminator.end-of-block.cnc-macro
;;                       ^^^^^^^^^^^^^ comment.line.parenthesized.cnc-macro
G66 P0100 L2 A2 B20 C20 I30 J20 K20；
;; <--- keyword.control.call.macro.cnc-macro
;;   ^^^^ entity.name.function.program.cnc-macro
;;        ^ support.type.address.cnc-macro
;;           ^ variable.parameter.argument.cnc-macro
;;                              ^ variable.parameter.argument.cnc-macro
;;                                 ^ punctuation.terminator.end-of-block.cnc-macro
M98 P[#100] L3
;;  ^ support.type.address.cnc-macro
;;    ^^^^ variable.other.common.cnc-macro
#1=RAND[10]
;; ^^^^ support.function.math.cnc-macro
#2=SRAND[1,10]+#1
;; ^^^^^ support.function.math.cnc-macro
