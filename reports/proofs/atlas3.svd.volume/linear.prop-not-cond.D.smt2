; atlas3.svd.volume linear.prop-not-cond.D
(set-logic NRA)
(declare-const c1 Real)
(declare-const c2 Real)
(declare-const c3 Real)
(assert (forall ((t Real) (t1 Real) (t2 Real)) (and (> (+ 1 c1 c2 c3) 0) (or (< c1 0) (< (+ c1 (* 2 c2) (* 3 c3)) 0) (and (> c3 0) (< c2 0) (> (+ c2 (* 3 c3)) 0) (> (+ (* (- 3) c1 c3) (* c2 c2)) 0))) (or (> c1 0) (> (+ c1 (* 2 c2) (* 3 c3)) 0) (and (< c3 0) (> c2 0) (< (+ c2 (* 3 c3)) 0) (> (+ (* (- 3) c1 c3) (* c2 c2)) 0))) (or (< t 0) (> (+ (- 1) t) 0) (> (+ 1 (* c1 t) (* c2 t t) (* c3 t t t)) 0)) (or (< t1 0) (> (+ (- 1) t1) 0) (>= (+ c1 (* 2 c2 t1) (* 3 c3 t1 t1)) 0) (< t2 0) (> (+ (- 1) t2) 0) (<= (+ c1 (* 2 c2 t2) (* 3 c3 t2 t2)) 0)))))
(check-sat)
