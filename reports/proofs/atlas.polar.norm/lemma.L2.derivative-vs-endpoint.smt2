; atlas.polar.norm lemma.L2.derivative-vs-endpoint
(set-logic NRA)
(declare-const c1 Real)
(declare-const c2 Real)
(declare-const t2 Real)
(declare-const t3 Real)
(assert (forall ((t Real) (t1 Real)) (or (and (or (< t 0) (> (+ (- 1) t) 0) (>= (+ c1 (* 2 c2 t)) 0) (< t1 0) (> (+ (- 1) t1) 0) (<= (+ c1 (* 2 c2 t1)) 0)) (or (and (< c1 0) (> (+ c1 (* 2 c2)) 0)) (and (> c1 0) (< (+ c1 (* 2 c2)) 0)))) (and (>= t2 0) (<= (+ (- 1) t2) 0) (< (+ c1 (* 2 c2 t2)) 0) (>= t3 0) (<= (+ (- 1) t3) 0) (> (+ c1 (* 2 c2 t3)) 0) (or (>= c1 0) (<= (+ c1 (* 2 c2)) 0)) (or (<= c1 0) (>= (+ c1 (* 2 c2)) 0))))))
(check-sat)
