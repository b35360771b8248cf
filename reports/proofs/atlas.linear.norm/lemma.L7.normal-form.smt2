; atlas.linear.norm lemma.L7.normal-form
(set-logic NRA)
(declare-const a Real)
(declare-const b Real)
(declare-const c Real)
(declare-const d Real)
(assert (forall ((co Real) (si Real)) (or (not (= (+ (- 1) (* co co) (* si si)) 0)) (not (= (+ (* (- 2) a co si) (* b co co) (* (- 1) b si si) (* c co co) (* (- 1) c si si) (* 2 co d si)) 0)))))
(check-sat)
