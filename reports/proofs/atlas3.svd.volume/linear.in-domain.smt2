; atlas3.svd.volume linear.in-domain
(set-logic QF_NRA)
(declare-const l1 Real)
(declare-const l2 Real)
(declare-const l3 Real)
(assert (and (> l1 0) (> l2 0) (> l3 0) (<= (* l1 l2 l3) 0)))
(check-sat)
