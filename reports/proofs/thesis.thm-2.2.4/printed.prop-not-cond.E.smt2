; thesis.thm-2.2.4 printed.prop-not-cond.E
(set-logic QF_NRA)
(declare-const x Real)
(declare-const y Real)
(declare-const h Real)
(assert (and (> x 0) (> y 0) (> (+ (* (- 1) h h) (* x y)) 0) (< (+ (- 1) (* h h) x (* (- 1) x y) y) 0) (or (> (+ (* (- 2) h h) (* (- 1) x) (* 2 x y) (* (- 1) y)) 0) (>= (+ (- 2) x y) 0)) (or (> (+ 2 (* (- 1) x) (* (- 1) y)) 0) (>= (+ (* 2 h h) x (* (- 2) x y) y) 0)) (> (+ (* (- 1) h h) (* x y)) 0) (or (>= (+ (- 2) x y) 0) (<= (+ (* (- 2) h h) (* (- 1) x) (* 2 x y) (* (- 1) y)) 0)) (or (<= (+ (- 2) x y) 0) (>= (+ (* (- 2) h h) (* (- 1) x) (* 2 x y) (* (- 1) y)) 0))))
(check-sat)
