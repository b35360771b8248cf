; atlas.svd.norm L12.slope-in-B-positive
(set-logic QF_NRA)
(declare-const sg Real)
(declare-const pi Real)
(declare-const t Real)
(assert (and (>= (+ (* (- 4) pi) (* sg sg)) 0) (>= t 0) (<= (+ (- 1) t) 0) (> (+ (* 16 pi sg t t t) (* 4 pi sg sg t t t t) (* 16 pi t t) (* (- 4) sg sg t t) (* (- 4) sg sg sg t t t) (* (- 1) sg sg sg sg t t t t)) 0)))
(check-sat)
