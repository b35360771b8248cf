; thesis.thm-2.2.5 printed.directions.prop-not-cond.D
(set-logic NRA)
(declare-const x Real)
(declare-const y Real)
(declare-const h Real)
(assert (forall ((m Real) (t Real) (t1 Real) (t2 Real) (t3 Real)) (and (> x 0) (> y 0) (> (+ (* (- 1) h h) (* x y)) 0) (or (< (+ 1 (* (- 1) h h) (* (- 1) x) (* x y) (* (- 1) y)) 0) (and (< (+ (- 2) x y) 0) (or (<= x 0) (> (+ (- 1) x) 0) (<= y 0) (> (+ (- 1) y) 0)))) (or (< t 0) (> (+ (- 1) t) 0) (>= (+ (- 2) (* 4 h m) (* (- 8) h m t) (* 4 h m t x) (* 4 h m t y) (* 2 h h m m t) (* 2 h h t) (* (- 2) m m) (* 2 m m t) (* (- 4) m m t y) (* 2 m m t y y) (* 2 m m y) (* 2 t) (* (- 4) t x) (* 2 t x x) (* 2 x)) 0) (< t1 0) (> (+ (- 1) t1) 0) (<= (+ (- 2) (* 4 h m) (* (- 8) h m t1) (* 4 h m t1 x) (* 4 h m t1 y) (* 2 h h m m t1) (* 2 h h t1) (* (- 2) m m) (* 2 m m t1) (* (- 4) m m t1 y) (* 2 m m t1 y y) (* 2 m m y) (* 2 t1) (* (- 4) t1 x) (* 2 t1 x x) (* 2 x)) 0)) (or (< t2 0) (> (+ (- 1) t2) 0) (>= (+ (- 2) (* 2 h h t2) (* 2 t2) (* (- 4) t2 y) (* 2 t2 y y) (* 2 y)) 0) (< t3 0) (> (+ (- 1) t3) 0) (<= (+ (- 2) (* 2 h h t3) (* 2 t3) (* (- 4) t3 y) (* 2 t3 y y) (* 2 y)) 0)))))
(check-sat)
