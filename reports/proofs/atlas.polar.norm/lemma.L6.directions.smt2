; atlas.polar.norm lemma.L6.directions
(set-logic NRA)
(declare-const v1 Real)
(declare-const v2 Real)
(assert (forall ((l Real) (m Real) (l1 Real)) (and (= (+ (- 1) (* v1 v1) (* v2 v2)) 0) (or (= l 0) (not (= (+ (* (- 1) l) v1) 0)) (not (= (+ (* (- 1) l m) v2) 0))) (or (= l1 0) (not (= v1 0)) (not (= (+ (* (- 1) l1) v2) 0))))))
(check-sat)
