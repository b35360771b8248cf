; kaji.polar.degenerate corrected.vanishes.never-zero.xyh
(set-logic NRA)
(declare-const x Real)
(declare-const y Real)
(declare-const h Real)
(assert (forall ((t Real)) (and (> x 0) (> y 0) (> (+ (* (- 1) h h) (* x y)) 0) (or (not (= (+ (- 1) x) 0)) (not (= (+ (- 1) y) 0)) (not (= h 0))) (not (= (+ 1 (* (- 1) h h t t) (* (- 2) t) (* t x) (* t y) (* t t) (* (- 1) t t x) (* t t x y) (* (- 1) t t y)) 0)))))
(check-sat)
