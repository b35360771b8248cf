; atlas.exp-log.area cond-not-prop.residue
(set-logic QF_NRA)
(declare-const x Real)
(declare-const y Real)
(declare-const h Real)
(assert (and (> x 0) (> y 0) (> (+ (* (- 1) h h) (* x y)) 0) (<= (+ (* (- 1) h h) (* x y)) 0)))
(check-sat)
