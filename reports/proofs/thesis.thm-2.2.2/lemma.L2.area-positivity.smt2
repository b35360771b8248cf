; thesis.thm-2.2.2 lemma.L2.area-positivity
(set-logic NRA)
(declare-const c1 Real)
(declare-const c2 Real)
(declare-const t3 Real)
(declare-const t4 Real)
(declare-const t5 Real)
(assert (forall ((t Real) (t1 Real) (t2 Real)) (or (and (or (< t 0) (> (+ (- 1) t) 0) (> (+ 1 (* c1 t) (* c2 t t)) 0)) (or (< t1 0) (> (+ (- 1) t1) 0) (>= (+ c1 (* 2 c2 t1)) 0) (< t2 0) (> (+ (- 1) t2) 0) (<= (+ c1 (* 2 c2 t2)) 0)) (or (<= (+ 1 c1 c2) 0) (and (< c1 0) (> (+ c1 (* 2 c2)) 0)) (and (> c1 0) (< (+ c1 (* 2 c2)) 0)))) (and (or (and (>= t3 0) (<= (+ (- 1) t3) 0) (<= (+ 1 (* c1 t3) (* c2 t3 t3)) 0)) (and (>= t4 0) (<= (+ (- 1) t4) 0) (< (+ c1 (* 2 c2 t4)) 0) (>= t5 0) (<= (+ (- 1) t5) 0) (> (+ c1 (* 2 c2 t5)) 0))) (> (+ 1 c1 c2) 0) (or (>= c1 0) (<= (+ c1 (* 2 c2)) 0)) (or (<= c1 0) (>= (+ c1 (* 2 c2)) 0))))))
(check-sat)
