; atlas.linear.norm conj.prop-not-cond.N
(set-logic QF_NRA)
(declare-const p Real)
(declare-const r Real)
(declare-const k Real)
(declare-const nu Real)
(assert (and (> (+ (* k k) (* p r)) 0) (or (< (+ (- 1) p) 0) (< (+ (- 1) r) 0) (< (+ 4 (* (- 4) p) (* 4 p r) (* (- 4) r)) 0)) (or (< (+ (* (- 1) k k) p (* (- 1) p p)) 0) (< (+ (* (- 1) k k) r (* (- 1) r r)) 0) (< (+ (* (- 4) k k p) (* 8 k k p r) (* (- 4) k k r) (* 4 k k k k) (* 4 p r) (* (- 4) p r r) (* (- 4) p p r) (* 4 p p r r)) 0)) (or (and (>= (+ (* (- 1) k k) p (* (- 1) p p)) 0) (>= (+ (* (- 1) k k) r (* (- 1) r r)) 0) (>= (+ (* (- 1) k k p) (* 2 k k p r) (* (- 1) k k r) (* k k k k) (* p r) (* (- 1) p r r) (* (- 1) p p r) (* p p r r)) 0)) (and (>= nu 0) (>= (+ (- 1) (* (- 1) k k nu) (* nu p) (* (- 1) nu p p) p) 0) (>= (+ (- 1) (* (- 1) k k nu) (* nu r) (* (- 1) nu r r) r) 0) (>= (+ 1 (* 2 k k nu) (* (- 1) k k nu p) (* (- 1) k k nu r) (* (- 1) k k nu nu p) (* 2 k k nu nu p r) (* (- 1) k k nu nu r) (* k k k k nu nu) (* (- 1) nu p) (* 2 nu p r) (* (- 1) nu p r r) (* nu p p) (* (- 1) nu p p r) (* (- 1) nu r) (* nu r r) (* nu nu p r) (* (- 1) nu nu p r r) (* (- 1) nu nu p p r) (* nu nu p p r r) (* (- 1) p) (* p r) (* (- 1) r)) 0)))))
(check-sat)
