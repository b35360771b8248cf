; atlas.svd.norm L12.degenerate.pi-zero
(set-logic QF_NRA)
(declare-const B Real)
(declare-const sg Real)
(declare-const t Real)
(assert (and (>= B 0) (> (+ 1 sg) 0) (> (+ 2 sg) 0) (>= (+ (* (- 4) B sg sg) (* (- 4) B sg sg sg) (* (- 1) B sg sg sg sg)) 0) (>= t 0) (<= (+ (- 1) t) 0) (< (+ (* (- 4) B sg sg t t) (* (- 4) B sg sg sg t t t) (* (- 1) B sg sg sg sg t t t t)) 0)))
(check-sat)
