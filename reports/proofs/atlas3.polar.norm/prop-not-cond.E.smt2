; atlas3.polar.norm prop-not-cond.E
(set-logic NRA)
(declare-const l1 Real)
(declare-const l2 Real)
(declare-const l3 Real)
(assert (forall ((v1 Real) (v2 Real) (v3 Real)) (and (> l1 0) (> l2 0) (> l3 0) (or (< (+ (- 1) l1) 0) (< (+ (- 1) l2) 0) (< (+ (- 1) l3) 0)) (or (> (+ (- 1) l1) 0) (> (+ (- 1) l2) 0) (> (+ (- 1) l3) 0)) (or (>= (+ (* 2 l1 v1 v1) (* 2 l2 v2 v2) (* 2 l3 v3 v3) (* (- 2) v1 v1) (* (- 2) v2 v2) (* (- 2) v3 v3)) 0) (<= (+ (* (- 2) l1 v1 v1) (* 2 l1 l1 v1 v1) (* (- 2) l2 v2 v2) (* 2 l2 l2 v2 v2) (* (- 2) l3 v3 v3) (* 2 l3 l3 v3 v3)) 0)) (or (<= (+ (* 2 l1 v1 v1) (* 2 l2 v2 v2) (* 2 l3 v3 v3) (* (- 2) v1 v1) (* (- 2) v2 v2) (* (- 2) v3 v3)) 0) (>= (+ (* (- 2) l1 v1 v1) (* 2 l1 l1 v1 v1) (* (- 2) l2 v2 v2) (* 2 l2 l2 v2 v2) (* (- 2) l3 v3 v3) (* 2 l3 l3 v3 v3)) 0)))))
(check-sat)
