; kaji.polar.det eigenvalues-exist-positive
(set-logic NRA)
(declare-const x Real)
(declare-const y Real)
(declare-const h Real)
(assert (forall ((l1 Real) (l2 Real)) (and (> x 0) (> y 0) (> (+ (* (- 1) h h) (* x y)) 0) (or (<= l1 0) (<= l2 0) (not (= (+ l1 l2 (* (- 1) x) (* (- 1) y)) 0)) (not (= (+ (* h h) (* l1 l2) (* (- 1) x y)) 0))))))
(check-sat)
