; thesis.thm-2.2.5 printed.second-conjunct-implied
(set-logic QF_NRA)
(declare-const x Real)
(declare-const y Real)
(declare-const h Real)
(assert (and (> x 0) (> y 0) (> (+ (* (- 1) h h) (* x y)) 0) (>= (+ 1 (* (- 1) h h) (* (- 1) x) (* x y) (* (- 1) y)) 0) (< (+ (- 2) x y) 0) (or (> (+ (- 1) x) 0) (> (+ (- 1) y) 0))))
(check-sat)
