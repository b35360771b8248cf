; thesis.thm-2.2.2 corrected.prop-not-cond.D
(set-logic NRA)
(declare-const x Real)
(declare-const y Real)
(assert (forall ((t Real) (t1 Real) (t2 Real)) (and (> x 0) (> y 0) (or (> (+ (* (- 1) x) (* 2 x y) (* (- 1) y)) 0) (> (+ (- 2) x y) 0)) (or (> (+ 2 (* (- 1) x) (* (- 1) y)) 0) (> (+ x (* (- 2) x y) y) 0)) (or (< t 0) (> (+ (- 1) t) 0) (> (+ 1 (* (- 2) t) (* t x) (* t y) (* t t) (* (- 1) t t x) (* t t x y) (* (- 1) t t y)) 0)) (or (< t1 0) (> (+ (- 1) t1) 0) (>= (+ (- 2) (* 2 t1) (* (- 2) t1 x) (* 2 t1 x y) (* (- 2) t1 y) x y) 0) (< t2 0) (> (+ (- 1) t2) 0) (<= (+ (- 2) (* 2 t2) (* (- 2) t2 x) (* 2 t2 x y) (* (- 2) t2 y) x y) 0)))))
(check-sat)
