; kaji.polar.degenerate printed.never-negative
(set-logic NRA)
(declare-const l1 Real)
(declare-const l2 Real)
(assert (forall ((t Real)) (and (> l1 0) (> l2 0) (or (not (= (+ (- 1) l1) 0)) (not (= (+ (- 1) l2) 0))) (>= (+ 1 (* l1 l2 t t) (* l1 t) (* (- 1) l1 t t) (* l2 t) (* (- 1) l2 t t) (* (- 2) t) (* t t)) 0))))
(check-sat)
