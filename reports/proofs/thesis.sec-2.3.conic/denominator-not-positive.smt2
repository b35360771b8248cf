; thesis.sec-2.3.conic denominator-not-positive
(set-logic QF_NRA)
(declare-const x Real)
(declare-const y Real)
(assert (<= (+ 3 (* (- 2) x) (* 2 x y) (* x x) (* (- 2) y) (* y y)) 0))
(check-sat)
