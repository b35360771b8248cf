; atlas.svd.norm L12.degenerate.x-equals-y
(set-logic QF_NRA)
(declare-const B Real)
(declare-const sg Real)
(declare-const t Real)
(assert (and (>= B 0) (> (+ 2 sg) 0) (>= t 0) (<= (+ (- 1) t) 0) (< (+ (* sg sg) (* sg sg sg t) (* (/ 1 4) sg sg sg sg t t)) 0)))
(check-sat)
