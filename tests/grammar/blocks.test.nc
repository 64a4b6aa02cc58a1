;; SYNTAX TEST "source.cnc-macro" "blocks: tape marks, block delete, end-of-block, program numbers, sequence numbers"
%
;; <- keyword.other.tape-mark.cnc-macro
O1234
;; <----- entity.name.function.program.cnc-macro
O1234 (TITLE)
;; <----- entity.name.function.program.cnc-macro
;;    ^^^^^^^ comment.line.parenthesized.cnc-macro
O0100; (MAIN)
;; <----- entity.name.function.program.cnc-macro
;;   ^ punctuation.terminator.end-of-block.cnc-macro
;;     ^^^^^^ comment.line.parenthesized.cnc-macro
o2000 G90
;; <----- entity.name.function.program.cnc-macro
;;    ^^^ keyword.other.g-code.cnc-macro
N100 G00 X0
;; <---- entity.name.tag.label.cnc-macro
;;   ^^^ keyword.other.g-code.motion.cnc-macro
N5 IF[#4 GT 0] GOTO 10
;; <-- entity.name.tag.label.cnc-macro
;; ^^ keyword.control.conditional.cnc-macro
N941#3000=1(MSG)
;; <---- entity.name.tag.label.cnc-macro
;;  ^^^^^ variable.language.system.cnc-macro
/ G00 X1
;; <- keyword.other.block-delete.cnc-macro
;; <~~--- keyword.other.g-code.motion.cnc-macro
/1 N10 G00 X1
;; <- keyword.other.block-delete.cnc-macro
;; <~- constant.numeric.integer.block-delete-switch.cnc-macro
;; ^^^ entity.name.tag.label.cnc-macro
  /9 #1=2
;; <~~- keyword.other.block-delete.cnc-macro
;; ^ constant.numeric.integer.block-delete-switch.cnc-macro
;;   ^^ variable.other.local.cnc-macro
/12 X1
;; <- keyword.other.block-delete.cnc-macro
;; <~-- constant.numeric.integer.cnc-macro - constant.numeric.integer.block-delete-switch.cnc-macro
G00 X1;
;;    ^ punctuation.terminator.end-of-block.cnc-macro
G00 X1 ；
;;     ^ punctuation.terminator.end-of-block.cnc-macro
G00 X1; G01 X2
;;    ^ punctuation.terminator.end-of-block.cnc-macro
;;      ^^^^^^ invalid.illegal.after-end-of-block.cnc-macro
G00 X1; (A COMMENT AFTER THE END) ;
;;    ^ punctuation.terminator.end-of-block.cnc-macro
;;      ^^^^^^^^^^^^^^^^^^^^^^^^^ comment.line.parenthesized.cnc-macro - invalid.illegal.after-end-of-block.cnc-macro
;;                                ^ punctuation.terminator.end-of-block.cnc-macro
G90 X1 / 2
;;     ^ keyword.operator.arithmetic.cnc-macro - keyword.other.block-delete.cnc-macro
%
;; <- keyword.other.tape-mark.cnc-macro
