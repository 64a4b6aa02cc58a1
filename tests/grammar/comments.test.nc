;; SYNTAX TEST "source.cnc-macro" "comments: ( ) anywhere, unclosed to the end of the line"
(A WHOLE LINE COMMENT)
;; <- comment.line.parenthesized.cnc-macro punctuation.definition.comment.begin.cnc-macro
;; <~-------------------- comment.line.parenthesized.cnc-macro
;;                   ^ comment.line.parenthesized.cnc-macro punctuation.definition.comment.end.cnc-macro
G00 X10. (AFTER WORDS) Y5.
;; <--- keyword.other.g-code.motion.cnc-macro
;;       ^ comment.line.parenthesized.cnc-macro punctuation.definition.comment.begin.cnc-macro
;;        ^^^^^^^^^^^ comment.line.parenthesized.cnc-macro
;;                   ^ comment.line.parenthesized.cnc-macro punctuation.definition.comment.end.cnc-macro
;;                     ^ support.type.address.cnc-macro - comment.line.parenthesized.cnc-macro
;;                      ^^ constant.numeric.decimal.cnc-macro
#111=600(BASE)
;; <---- variable.other.common.cnc-macro
;;   ^^^ constant.numeric.integer.cnc-macro
;;      ^ comment.line.parenthesized.cnc-macro punctuation.definition.comment.begin.cnc-macro
;;       ^^^^ comment.line.parenthesized.cnc-macro
;;           ^ comment.line.parenthesized.cnc-macro punctuation.definition.comment.end.cnc-macro
GOTO1(SKIP)
;; <---- keyword.control.goto.cnc-macro
;;  ^ entity.name.tag.label.reference.cnc-macro
;;   ^^^^^^ comment.line.parenthesized.cnc-macro
G01 X5 (UNCLOSED COMMENT RUNS TO THE END IF[#1 GT 2]
;;  ^^ - comment.line.parenthesized.cnc-macro
;;     ^ comment.line.parenthesized.cnc-macro punctuation.definition.comment.begin.cnc-macro - punctuation.definition.comment.end.cnc-macro
;;      ^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^ comment.line.parenthesized.unclosed.cnc-macro - keyword.control.conditional.cnc-macro
(IF WHILE GOTO #100 X10 ARE PLAIN TEXT IN A COMMENT)
;; <~-------------------------------------------------- comment.line.parenthesized.cnc-macro - keyword.control.conditional.cnc-macro variable.other.common.cnc-macro support.type.address.cnc-macro
G00 X100 Z100; (已连续加工了 100 个?)
;;           ^ punctuation.terminator.end-of-block.cnc-macro
;;             ^ comment.line.parenthesized.cnc-macro punctuation.definition.comment.begin.cnc-macro
;;              ^^^^^^^^^^^^^ comment.line.parenthesized.cnc-macro
;;                           ^ comment.line.parenthesized.cnc-macro punctuation.definition.comment.end.cnc-macro
(cncmacro: dialect=gsk980tdi)
;; <~-------- comment.line.parenthesized.cnc-macro keyword.other.directive.cnc-macro
;;         ^^^^^^^ comment.line.parenthesized.cnc-macro variable.other.setting.cnc-macro
;;                 ^^^^^^^^^ comment.line.parenthesized.cnc-macro constant.other.dialect.cnc-macro
(A) G01 (B) X1. (C)
;; <--- comment.line.parenthesized.cnc-macro
;;  ^^^ keyword.other.g-code.motion.cnc-macro
;;      ^^^ comment.line.parenthesized.cnc-macro
;;          ^ support.type.address.cnc-macro
;;              ^^^ comment.line.parenthesized.cnc-macro
((NESTED) X1
;; <--------- comment.line.parenthesized.cnc-macro
;;        ^ support.type.address.cnc-macro
