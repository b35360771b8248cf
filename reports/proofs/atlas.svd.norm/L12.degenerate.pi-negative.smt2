; atlas.svd.norm L12.degenerate.pi-negative
(set-logic QF_NRA)
(declare-const B Real)
(declare-const sg Real)
(declare-const pi Real)
(assert (and (>= B 0) (>= (+ (* (- 4) pi) (* sg sg)) 0) (> (+ 1 pi sg) 0) (> (+ 2 sg) 0) (< pi 0) (>= (+ (* 16 B pi) (* 16 B pi sg) (* 4 B pi sg sg) (* (- 4) B sg sg) (* (- 4) B sg sg sg) (* (- 1) B sg sg sg sg) (* 4 pi) (* 4 pi sg) (* 4 pi pi)) 0)))
(check-sat)
