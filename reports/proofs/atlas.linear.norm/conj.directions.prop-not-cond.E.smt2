; atlas.linear.norm conj.directions.prop-not-cond.E
(set-logic NRA)
(declare-const p Real)
(declare-const r Real)
(declare-const k Real)
(assert (forall ((m Real)) (and (> (+ (* k k) (* p r)) 0) (or (< (+ (- 1) p) 0) (< (+ (- 1) r) 0) (< (+ 4 (* (- 4) p) (* 4 p r) (* (- 4) r)) 0)) (or (< (+ (* (- 1) k k) p (* (- 1) p p)) 0) (< (+ (* (- 1) k k) r (* (- 1) r r)) 0) (< (+ (* (- 4) k k p) (* 8 k k p r) (* (- 4) k k r) (* 4 k k k k) (* 4 p r) (* (- 4) p r r) (* (- 4) p p r) (* 4 p p r r)) 0)) (or (>= (+ (- 2) (* (- 2) m m) (* 2 m m r) (* 2 p)) 0) (<= (+ (* (- 4) k m p) (* 4 k m r) (* 2 k k) (* 2 k k m m) (* (- 2) m m r) (* 2 m m r r) (* (- 2) p) (* 2 p p)) 0)) (or (<= (+ (- 2) (* (- 2) m m) (* 2 m m r) (* 2 p)) 0) (>= (+ (* (- 4) k m p) (* 4 k m r) (* 2 k k) (* 2 k k m m) (* (- 2) m m r) (* 2 m m r r) (* (- 2) p) (* 2 p p)) 0)) (or (>= (+ (- 2) (* 2 r)) 0) (<= (+ (* 2 k k) (* (- 2) r) (* 2 r r)) 0)) (or (<= (+ (- 2) (* 2 r)) 0) (>= (+ (* 2 k k) (* (- 2) r) (* 2 r r)) 0)))))
(check-sat)
