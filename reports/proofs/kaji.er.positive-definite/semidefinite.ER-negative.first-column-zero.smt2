; kaji.er.positive-definite semidefinite.ER-negative.first-column-zero
(set-logic QF_NRA)
(declare-const b11 Real)
(declare-const b12 Real)
(declare-const b21 Real)
(declare-const b22 Real)
(assert (< (+ (* b11 b11) (* b21 b21)) 0))
(check-sat)
