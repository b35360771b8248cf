; thesis.thm-2.2.2 corrected.cond-not-prop.E
(set-logic QF_NRA)
(declare-const x Real)
(declare-const y Real)
(assert (and (> x 0) (> y 0) (or (and (<= (+ (* (- 1) x) (* 2 x y) (* (- 1) y)) 0) (<= (+ (- 2) x y) 0)) (and (<= (+ 2 (* (- 1) x) (* (- 1) y)) 0) (<= (+ x (* (- 2) x y) y) 0))) (or (<= (* x y) 0) (and (< (+ (- 2) x y) 0) (> (+ (* (- 1) x) (* 2 x y) (* (- 1) y)) 0)) (and (> (+ (- 2) x y) 0) (< (+ (* (- 1) x) (* 2 x y) (* (- 1) y)) 0)))))
(check-sat)
