; thesis.thm-2.2.5 lemma.L3.affine-sign-change
(set-logic NRA)
(declare-const g0 Real)
(declare-const sl Real)
(declare-const ta Real)
(declare-const tb Real)
(assert (forall ((ta1 Real) (tb1 Real)) (and (>= sl 0) (or (and (>= ta 0) (<= (+ (- 1) ta) 0) (>= tb 0) (<= (+ (- 1) tb) 0) (< (+ g0 (* sl ta)) 0) (> (+ g0 (* sl tb)) 0) (or (>= g0 0) (<= (+ g0 sl) 0))) (and (or (< ta1 0) (> (+ (- 1) ta1) 0) (< tb1 0) (> (+ (- 1) tb1) 0) (>= (+ g0 (* sl ta1)) 0) (<= (+ g0 (* sl tb1)) 0)) (< g0 0) (> (+ g0 sl) 0))))))
(check-sat)
