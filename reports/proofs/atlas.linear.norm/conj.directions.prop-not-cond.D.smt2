; atlas.linear.norm conj.directions.prop-not-cond.D
(set-logic NRA)
(declare-const p Real)
(declare-const r Real)
(declare-const k Real)
(assert (forall ((m Real) (t Real) (t1 Real) (t2 Real) (t3 Real)) (and (> (+ (* k k) (* p r)) 0) (or (< (+ (- 1) p) 0) (< (+ (- 1) r) 0) (< (+ 4 (* (- 4) p) (* 4 p r) (* (- 4) r)) 0)) (or (< (+ (* (- 1) k k) p (* (- 1) p p)) 0) (< (+ (* (- 1) k k) r (* (- 1) r r)) 0) (< (+ (* (- 4) k k p) (* 8 k k p r) (* (- 4) k k r) (* 4 k k k k) (* 4 p r) (* (- 4) p r r) (* (- 4) p p r) (* 4 p p r r)) 0)) (or (< t 0) (> (+ (- 1) t) 0) (>= (+ (- 2) (* (- 4) k m p t) (* 4 k m r t) (* 2 k k m m t) (* 2 k k t) (* (- 2) m m) (* 2 m m r) (* (- 4) m m r t) (* 2 m m r r t) (* 2 m m t) (* 2 p) (* (- 4) p t) (* 2 p p t) (* 2 t)) 0) (< t1 0) (> (+ (- 1) t1) 0) (<= (+ (- 2) (* (- 4) k m p t1) (* 4 k m r t1) (* 2 k k m m t1) (* 2 k k t1) (* (- 2) m m) (* 2 m m r) (* (- 4) m m r t1) (* 2 m m r r t1) (* 2 m m t1) (* 2 p) (* (- 4) p t1) (* 2 p p t1) (* 2 t1)) 0)) (or (< t2 0) (> (+ (- 1) t2) 0) (>= (+ (- 2) (* 2 k k t2) (* 2 r) (* (- 4) r t2) (* 2 r r t2) (* 2 t2)) 0) (< t3 0) (> (+ (- 1) t3) 0) (<= (+ (- 2) (* 2 k k t3) (* 2 r) (* (- 4) r t3) (* 2 r r t3) (* 2 t3)) 0)))))
(check-sat)
