; thesis.ex-2.2.4 svd-good-norm-some-beta
(set-logic NRA)
(declare-const beta Real)
(assert (forall ((t Real)) (and (not (= beta 0)) (or (< t 0) (> (+ (- 1) t) 0) (>= (+ (* (- 4) beta beta t t) (* (- 4) beta beta t t t) (* (- 1) beta beta t t t t)) 0)))))
(check-sat)
