; thesis.thm-2.2.3 beta0.prop-not-cond.D
(set-logic NRA)
(declare-const x Real)
(declare-const y Real)
(assert (forall ((v1 Real) (v2 Real) (t Real) (t1 Real)) (and (> x 0) (> y 0) (or (< (+ (- 1) x) 0) (< (+ (- 1) y) 0)) (or (<= x 0) (> (+ (- 1) x) 0) (<= y 0) (> (+ (- 1) y) 0)) (or (not (= (+ (- 1) (* v1 v1) (* v2 v2)) 0)) (< t 0) (> (+ (- 1) t) 0) (>= (+ (* 2 t v1 v1) (* (- 4) t v1 v1 x) (* 2 t v1 v1 x x) (* 2 t v2 v2) (* (- 4) t v2 v2 y) (* 2 t v2 v2 y y) (* (- 2) v1 v1) (* 2 v1 v1 x) (* (- 2) v2 v2) (* 2 v2 v2 y)) 0) (< t1 0) (> (+ (- 1) t1) 0) (<= (+ (* 2 t1 v1 v1) (* (- 4) t1 v1 v1 x) (* 2 t1 v1 v1 x x) (* 2 t1 v2 v2) (* (- 4) t1 v2 v2 y) (* 2 t1 v2 v2 y y) (* (- 2) v1 v1) (* 2 v1 v1 x) (* (- 2) v2 v2) (* 2 v2 v2 y)) 0)))))
(check-sat)
