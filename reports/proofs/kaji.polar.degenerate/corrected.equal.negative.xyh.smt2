; kaji.polar.degenerate corrected.equal.negative.xyh
(set-logic QF_NRA)
(declare-const x Real)
(declare-const y Real)
(declare-const h Real)
(declare-const t Real)
(assert (and (> x 0) (> y 0) (> (+ (* (- 1) h h) (* x y)) 0) (= (+ x (* (- 1) y)) 0) (= h 0) (< (+ 1 (* (- 1) h h t t) (* (- 2) t) (* t x) (* t y) (* t t) (* (- 1) t t x) (* t t x y) (* (- 1) t t y)) 0)))
(check-sat)
