; atlas.svd.norm L12.C-negative
(set-logic QF_NRA)
(declare-const sg Real)
(declare-const pi Real)
(declare-const t Real)
(assert (and (> (+ (* (- 4) pi) (* sg sg)) 0) (> (+ 1 pi sg) 0) (> (+ 2 sg) 0) (> pi 0) (>= t 0) (<= (+ (- 1) t) 0) (< (+ 4 (* 4 pi sg t t) (* pi sg sg t t) (* pi sg sg t t t) (* 4 sg) (* 8 sg t) (* 4 sg t t) (* sg sg) (* 5 sg sg t) (* 5 sg sg t t) (* sg sg t t t) (* sg sg sg t) (* sg sg sg t t) (* sg sg sg t t t) (* 4 t)) 0)))
(check-sat)
