; atlas.svd.norm cond-not-prop.sym
(set-logic QF_NRA)
(declare-const B Real)
(declare-const pi Real)
(declare-const sg Real)
(declare-const t Real)
(assert (and (>= B 0) (>= (+ (* (- 4) pi) (* sg sg)) 0) (> (+ 1 pi sg) 0) (> (+ 2 sg) 0) (>= (+ (* 16 B pi) (* 16 B pi sg) (* 4 B pi sg sg) (* (- 4) B sg sg) (* (- 4) B sg sg sg) (* (- 1) B sg sg sg sg) (* 4 pi) (* 4 pi sg) (* 4 pi pi)) 0) (>= t 0) (<= (+ (- 1) t) 0) (< (+ (* 16 B pi sg t t t) (* 4 B pi sg sg t t t t) (* 16 B pi t t) (* (- 4) B sg sg t t) (* (- 4) B sg sg sg t t t) (* (- 1) B sg sg sg sg t t t t) (* 4 pi) (* 4 pi sg t) (* 4 pi pi t t)) 0)))
(check-sat)
