;; SYNTAX TEST "source.cnc-macro" "calls: G65 G66 G67, M98 M99, program numbers"
G65 P9100 X0 Y0 R40. A15. L2
;; <--- meta.call.macro.cnc-macro keyword.control.call.macro.cnc-macro
;;  ^ support.type.address.cnc-macro
;;   ^^^^ entity.name.function.program.cnc-macro
;;        ^ variable.parameter.argument.cnc-macro
;;         ^ constant.numeric.integer.cnc-macro
;;              ^ variable.parameter.argument.cnc-macro
;;               ^^^ constant.numeric.decimal.cnc-macro
;;                   ^ variable.parameter.argument.cnc-macro
;;                        ^ support.type.address.cnc-macro - variable.parameter.argument.cnc-macro
;;                         ^ constant.numeric.integer.cnc-macro
N10 G65 P9100 H6 Z-12. F120.
;; <--- entity.name.tag.label.cnc-macro
;;  ^^^ keyword.control.call.macro.cnc-macro
;;       ^^^^ entity.name.function.program.cnc-macro
;;            ^ variable.parameter.argument.cnc-macro - support.function.h-code.cnc-macro
;;             ^ constant.numeric.integer.cnc-macro
;;               ^ variable.parameter.argument.cnc-macro
;;                ^^^^ constant.numeric.decimal.cnc-macro
;;                     ^ variable.parameter.argument.cnc-macro
G65P9010X#24Y[#25+1]
;; <--- keyword.control.call.macro.cnc-macro
;; ^ support.type.address.cnc-macro
;;  ^^^^ entity.name.function.program.cnc-macro
;;      ^ variable.parameter.argument.cnc-macro
;;       ^^^ variable.other.local.cnc-macro
;;          ^ variable.parameter.argument.cnc-macro
;;           ^ punctuation.section.brackets.begin.cnc-macro
G65 P9100 X0 (CALL THE BOLT CIRCLE)
;;           ^^^^^^^^^^^^^^^^^^^^^^ comment.line.parenthesized.cnc-macro - variable.parameter.argument.cnc-macro
G65 P9100 A1. B2. I-3. I4. D5.;
;;                ^ variable.parameter.argument.cnc-macro
;;                 ^^^ constant.numeric.decimal.cnc-macro
;;                         ^ variable.parameter.argument.cnc-macro
;;                            ^ punctuation.terminator.end-of-block.cnc-macro - meta.call.macro.cnc-macro
G66 P9110 Z-10. R2. F100.
;; <--- keyword.control.call.macro.cnc-macro
;;   ^^^^ entity.name.function.program.cnc-macro
;;        ^ variable.parameter.argument.cnc-macro
;;              ^ variable.parameter.argument.cnc-macro
G00 X10. Y10.
;; <--- keyword.other.g-code.motion.cnc-macro - meta.call.macro.cnc-macro
;;  ^ support.type.address.cnc-macro - variable.parameter.argument.cnc-macro
G67
;; <--- keyword.control.call.macro.cancel.cnc-macro
M98 P0040
;; <--- meta.call.subprogram.cnc-macro keyword.control.call.subprogram.cnc-macro
;;  ^ support.type.address.cnc-macro
;;   ^^^^ entity.name.function.program.cnc-macro
M98 P30040 (O0040 THREE TIMES)
;;  ^ support.type.address.cnc-macro
;;   ^ constant.numeric.integer.repeat-count.cnc-macro
;;    ^^^^ entity.name.function.program.cnc-macro
;;         ^^^^^^^^^^^^^^^^^^^ comment.line.parenthesized.cnc-macro
M98 P40 L3
;;   ^^ entity.name.function.program.cnc-macro
;;      ^ support.type.address.cnc-macro
;;       ^ constant.numeric.integer.cnc-macro
M98 P1000 Q20
;;   ^^^^ entity.name.function.program.cnc-macro
;;        ^ support.type.address.cnc-macro
;;         ^^ entity.name.tag.label.reference.cnc-macro
M98P1234
;; <--- keyword.control.call.subprogram.cnc-macro
;; ^ support.type.address.cnc-macro
;;  ^^^^ entity.name.function.program.cnc-macro
M99
;; <--- meta.return.cnc-macro keyword.control.return.cnc-macro
M99 P20
;; <--- keyword.control.return.cnc-macro
;;  ^ support.type.address.cnc-macro
;;   ^^ entity.name.tag.label.reference.cnc-macro
N10 M99;
;; <--- entity.name.tag.label.cnc-macro
;;  ^^^ keyword.control.return.cnc-macro
;;     ^ punctuation.terminator.end-of-block.cnc-macro
G65 H01 P#100 Q#101 R5
;; <--- keyword.control.call.macro.cnc-macro
;;  ^^^ support.function.h-code.cnc-macro
