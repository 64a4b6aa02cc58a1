;; SYNTAX TEST "source.cnc-macro" "lines from real programs that are easy to mis-colour"
O9100 (BOLT CIRCLE DRILLING MACRO)
;; <----- entity.name.function.program.cnc-macro
;;    ^^^^^^^^^^^^^^^^^^^^^^^^^^^^ comment.line.parenthesized.cnc-macro
IF[ABS[#2*[#11-1]] GE 360.] THEN #3000=8(HOLES OVERLAP)
;; ^^^ support.function.math.cnc-macro
;;                 ^^ keyword.operator.comparison.cnc-macro
;;                    ^^^^ constant.numeric.decimal.cnc-macro
;;                          ^^^^ keyword.control.conditional.cnc-macro
;;                                       ^^^^^^^^^^^^^ string.quoted.other.message.cnc-macro
#27=#4003 (SAVE G90/G91)
;; <--- variable.other.local.cnc-macro
;;  ^^^^^ variable.language.system.cnc-macro
;;        ^^^^^^^^^^^^^^ comment.line.parenthesized.cnc-macro - keyword.other.g-code.cnc-macro
G90 G98 G81 X#32 Y#33 Z#26 R#3 F#9
;;  ^^^ keyword.other.g-code.cnc-macro
;;      ^^^ keyword.other.g-code.cnc-macro
;;          ^ support.type.address.cnc-macro
N10 IF[[#2 GT 0] AND [#5 GT 0]] GOTO 20
;; <--- entity.name.tag.label.cnc-macro
;;               ^^^ keyword.operator.logical.cnc-macro
;;                                   ^^ entity.name.tag.label.reference.cnc-macro
N20 #10=[#1-#2]/2 (LARGEST TOOL-CENTRE RADIUS)
;; <--- entity.name.tag.label.cnc-macro
;;  ^^^ variable.other.local.cnc-macro
;;         ^ keyword.operator.arithmetic.cnc-macro
;;             ^ keyword.operator.arithmetic.cnc-macro
G03 X#23 Y0 I-#23 J0
;; <--- keyword.other.g-code.motion.cnc-macro
;;          ^ support.type.address.cnc-macro
;;           ^ keyword.operator.arithmetic.cnc-macro
;;            ^^^ variable.other.local.cnc-macro
;;                ^ support.type.address.cnc-macro
M98 P30040 (FIRST COLUMN: O0040 THREE TIMES, SLOTS AT Y10 Y22 Y34)
;;    ^^^^ entity.name.function.program.cnc-macro
;;                        ^^^^^ comment.line.parenthesized.cnc-macro - entity.name.function.program.cnc-macro
G00 X[#103+2] Z2
;;  ^ support.type.address.cnc-macro
;;   ^ punctuation.section.brackets.begin.cnc-macro
;;    ^^^^ variable.other.common.cnc-macro
;;            ^ support.type.address.cnc-macro
;;             ^ constant.numeric.integer.cnc-macro
#122=#101*SQRT[1-#121*#121/[#102*#102]]-#101 (本层终点 Z)
;;        ^^^^ support.function.math.cnc-macro
;;                                           ^^^^^^^^ comment.line.parenthesized.cnc-macro
G01 U1 W0.5 (斜向退刀)
;;  ^ support.type.address.cnc-macro
;;     ^ support.type.address.cnc-macro
;;      ^^^ constant.numeric.decimal.cnc-macro
N5 G65 H01 P#107 Q0.6 (#107: 直径余量, 第一遍粗车留 0.6)
;;     ^^^ support.function.h-code.cnc-macro
;;                ^^^ constant.numeric.decimal.cnc-macro
;;                    ^^^^^^^^^^^^^^^^^^^^^^^^ comment.line.parenthesized.cnc-macro - variable.other.common.cnc-macro
G65 H99 P1 (/半径步距必须大于 0)
;;         ^^^^^^^^^^^^^ comment.line.parenthesized.cnc-macro
N42 DPRNT[Z*ERROR*#140[2 3]]
;; <--- entity.name.tag.label.cnc-macro
;;  ^^^^^ support.function.output.cnc-macro
N50 IF[ABS[#140] LT 1.] GOTO 60
;;               ^^ keyword.operator.comparison.cnc-macro
;;                  ^^ constant.numeric.decimal.cnc-macro
;;                           ^^ entity.name.tag.label.reference.cnc-macro
T#4120; (调用新的刀偏值)
;; <- support.type.address.cnc-macro
;; <~----- variable.language.system.cnc-macro
;;    ^ punctuation.terminator.end-of-block.cnc-macro
N10 G100 Z0 D5. F60. W1 (TOP FACE)
;;  ^^^^ keyword.other.g-code.cnc-macro
;;          ^ support.type.address.cnc-macro
;;           ^^ constant.numeric.decimal.cnc-macro
