(* Stored quantifier-free sentences that a proof needs to be empty (reports/proofs/<claim>/<name>.smt2), each
   stated as "for all reals the asserted formula fails" (checks/proofs/smt2_to_coq.py prints the statement from
   the stored sentence; coq_test.sh checks that each theorem here states exactly that) and closed by a
   Positivstellensatz certificate that the micromega tactics find and Coq's kernel checks. Written by
   checks/proofs/coq_certify.py; MANIFEST.json records every sentence tried, with the attempts that failed. *)
Require Import Reals Psatz Lra.
Open Scope R_scope.

(* atlas.exp-log.area/cond-not-prop.residue.smt2 *)
Theorem atlas_exp_log_area__cond_not_prop_residue : forall x y h : R, ~ (((x > 0) /\ (y > 0) /\ ((((- 1) * h * h) + (x * y)) > 0) /\ ((((- 1) * h * h) + (x * y)) <= 0))).
Proof. intros; nra. Qed.

(* atlas.exp-log.norm/cond-not-prop.eig.smt2 *)
Theorem atlas_exp_log_norm__cond_not_prop_eig : forall x y h l1 l2 : R, ~ (((x > 0) /\ (y > 0) /\ ((((- 1) * h * h) + (x * y)) > 0) /\ (l1 > 0) /\ (l2 > 0) /\ ((l1 + l2 + ((- 1) * x) + ((- 1) * y)) = 0) /\ (((h * h) + (l1 * l2) + ((- 1) * x * y)) = 0) /\ ((1 + ((- 1) * h * h) + ((- 1) * x) + (x * y) + ((- 1) * y)) >= 0) /\ ((1 + ((- 1) * l1) + (l1 * l2) + ((- 1) * l2)) < 0))).
Proof. intros; nra. Qed.

(* atlas.exp-log.norm/prop-not-cond.eig.smt2 *)
Theorem atlas_exp_log_norm__prop_not_cond_eig : forall x y h l1 l2 : R, ~ (((x > 0) /\ (y > 0) /\ ((((- 1) * h * h) + (x * y)) > 0) /\ (l1 > 0) /\ (l2 > 0) /\ ((l1 + l2 + ((- 1) * x) + ((- 1) * y)) = 0) /\ (((h * h) + (l1 * l2) + ((- 1) * x * y)) = 0) /\ ((1 + ((- 1) * h * h) + ((- 1) * x) + (x * y) + ((- 1) * y)) < 0) /\ ((1 + ((- 1) * l1) + (l1 * l2) + ((- 1) * l2)) >= 0))).
Proof. intros; nra. Qed.

(* atlas.linear.area/cond-not-prop.E.smt2 *)
Theorem atlas_linear_area__cond_not_prop_E : forall a b c d : R, ~ (((((a * d) + ((- 1) * b * c)) > 0) /\ ((((((- 1) * a) + (2 * a * d) + ((- 2) * b * c) + ((- 1) * d)) <= 0) /\ (((- 2) + a + d) <= 0)) \/ (((2 + ((- 1) * a) + ((- 1) * d)) <= 0) /\ ((a + ((- 2) * a * d) + (2 * b * c) + d) <= 0))) /\ ((((a * d) + ((- 1) * b * c)) <= 0) \/ ((((- 2) + a + d) < 0) /\ ((((- 1) * a) + (2 * a * d) + ((- 2) * b * c) + ((- 1) * d)) > 0)) \/ ((((- 2) + a + d) > 0) /\ ((((- 1) * a) + (2 * a * d) + ((- 2) * b * c) + ((- 1) * d)) < 0))))).
Proof. intros; nra. Qed.

(* atlas.linear.area/prop-not-cond.E.smt2 *)
Theorem atlas_linear_area__prop_not_cond_E : forall a b c d : R, ~ (((((a * d) + ((- 1) * b * c)) > 0) /\ (((((- 1) * a) + (2 * a * d) + ((- 2) * b * c) + ((- 1) * d)) > 0) \/ (((- 2) + a + d) > 0)) /\ (((2 + ((- 1) * a) + ((- 1) * d)) > 0) \/ ((a + ((- 2) * a * d) + (2 * b * c) + d) > 0)) /\ (((a * d) + ((- 1) * b * c)) > 0) /\ ((((- 2) + a + d) >= 0) \/ ((((- 1) * a) + (2 * a * d) + ((- 2) * b * c) + ((- 1) * d)) <= 0)) /\ ((((- 2) + a + d) <= 0) \/ ((((- 1) * a) + (2 * a * d) + ((- 2) * b * c) + ((- 1) * d)) >= 0)))).
Proof. intros; nra. Qed.

(* atlas.linear.norm/lemma.L4.norm-vs-square.smt2 *)
Theorem atlas_linear_norm__lemma_L4_norm_vs_square : forall a b : R, ~ (((a >= 0) /\ (b >= 0) /\ ((((a + ((- 1) * b)) <= 0) /\ (((a * a) + ((- 1) * b * b)) > 0)) \/ (((a + ((- 1) * b)) > 0) /\ (((a * a) + ((- 1) * b * b)) <= 0))))).
Proof. intros; nra. Qed.

(* atlas.polar.area/cond-not-prop.E.smt2 *)
Theorem atlas_polar_area__cond_not_prop_E : forall x y h : R, ~ (((x > 0) /\ (y > 0) /\ ((((- 1) * h * h) + (x * y)) > 0) /\ ((((((- 2) * h * h) + ((- 1) * x) + (2 * x * y) + ((- 1) * y)) <= 0) /\ (((- 2) + x + y) <= 0)) \/ (((2 + ((- 1) * x) + ((- 1) * y)) <= 0) /\ (((2 * h * h) + x + ((- 2) * x * y) + y) <= 0))) /\ (((((- 1) * h * h) + (x * y)) <= 0) \/ ((((- 2) + x + y) < 0) /\ ((((- 2) * h * h) + ((- 1) * x) + (2 * x * y) + ((- 1) * y)) > 0)) \/ ((((- 2) + x + y) > 0) /\ ((((- 2) * h * h) + ((- 1) * x) + (2 * x * y) + ((- 1) * y)) < 0))))).
Proof. intros; nra. Qed.

(* atlas.polar.area/prop-not-cond.E.smt2 *)
Theorem atlas_polar_area__prop_not_cond_E : forall x y h : R, ~ (((x > 0) /\ (y > 0) /\ ((((- 1) * h * h) + (x * y)) > 0) /\ (((((- 2) * h * h) + ((- 1) * x) + (2 * x * y) + ((- 1) * y)) > 0) \/ (((- 2) + x + y) > 0)) /\ (((2 + ((- 1) * x) + ((- 1) * y)) > 0) \/ (((2 * h * h) + x + ((- 2) * x * y) + y) > 0)) /\ ((((- 1) * h * h) + (x * y)) > 0) /\ ((((- 2) + x + y) >= 0) \/ ((((- 2) * h * h) + ((- 1) * x) + (2 * x * y) + ((- 1) * y)) <= 0)) /\ ((((- 2) + x + y) <= 0) \/ ((((- 2) * h * h) + ((- 1) * x) + (2 * x * y) + ((- 1) * y)) >= 0)))).
Proof. intros; nra. Qed.

(* atlas.polar.norm/lemma.L4.norm-vs-square.smt2 *)
Theorem atlas_polar_norm__lemma_L4_norm_vs_square : forall a b : R, ~ (((a >= 0) /\ (b >= 0) /\ ((((a + ((- 1) * b)) <= 0) /\ (((a * a) + ((- 1) * b * b)) > 0)) \/ (((a + ((- 1) * b)) > 0) /\ (((a * a) + ((- 1) * b * b)) <= 0))))).
Proof. intros; nra. Qed.

(* atlas.svd.area/cond-not-prop.E.smt2 *)
Theorem atlas_svd_area__cond_not_prop_E : forall x y : R, ~ (((x > 0) /\ (y > 0) /\ ((((((- 1) * x) + (2 * x * y) + ((- 1) * y)) <= 0) /\ (((- 2) + x + y) <= 0)) \/ (((2 + ((- 1) * x) + ((- 1) * y)) <= 0) /\ ((x + ((- 2) * x * y) + y) <= 0))) /\ (((x * y) <= 0) \/ ((((- 2) + x + y) < 0) /\ ((((- 1) * x) + (2 * x * y) + ((- 1) * y)) > 0)) \/ ((((- 2) + x + y) > 0) /\ ((((- 1) * x) + (2 * x * y) + ((- 1) * y)) < 0))))).
Proof. intros; nra. Qed.

(* atlas.svd.area/prop-not-cond.E.smt2 *)
Theorem atlas_svd_area__prop_not_cond_E : forall x y : R, ~ (((x > 0) /\ (y > 0) /\ (((((- 1) * x) + (2 * x * y) + ((- 1) * y)) > 0) \/ (((- 2) + x + y) > 0)) /\ (((2 + ((- 1) * x) + ((- 1) * y)) > 0) \/ ((x + ((- 2) * x * y) + y) > 0)) /\ ((x * y) > 0) /\ ((((- 2) + x + y) >= 0) \/ ((((- 1) * x) + (2 * x * y) + ((- 1) * y)) <= 0)) /\ ((((- 2) + x + y) <= 0) \/ ((((- 1) * x) + (2 * x * y) + ((- 1) * y)) >= 0)))).
Proof. intros; nra. Qed.

(* atlas.svd.norm/prop-not-cond.inst.smt2 *)
Theorem atlas_svd_norm__prop_not_cond_inst : forall x y beta : R, ~ (((x > 0) /\ (y > 0) /\ ((((- 2) * beta * beta * x * x * y * y) + (beta * beta * x * x * x * x) + (beta * beta * y * y * y * y) + ((- 4) * x * y) + (4 * x * y * y) + (4 * x * x * y) + ((- 4) * x * x * y * y)) > 0) /\ (((2 * beta * beta * x * x * y * y) + ((- 1) * beta * beta * x * x * x * x) + ((- 1) * beta * beta * y * y * y * y) + (4 * x * y) + ((- 4) * x * y * y) + ((- 4) * x * x * y) + (4 * x * x * y * y)) >= 0))).
Proof. intros; nra. Qed.

(* kaji.er.positive-definite/semidefinite.ER-negative.first-column-zero.smt2 *)
Theorem kaji_er_positive_definite__semidefinite_ER_negative_first_column_zero : forall b11 b12 b21 b22 : R, ~ ((((b11 * b11) + (b21 * b21)) < 0)).
Proof. intros; nra. Qed.

(* kaji.er.positive-definite/semidefinite.ER-negative.normal-form.smt2 *)
Theorem kaji_er_positive_definite__semidefinite_ER_negative_normal_form : forall p q b11 b12 b21 b22 : R, ~ (((((- 2) * b11 * b12 * p) + ((- 2) * b11 * b22 * q) + (b11 * b11 * p * p) + (b11 * b11 * q * q) + (2 * b12 * b21 * q) + (b12 * b12) + ((- 2) * b21 * b22 * p) + (b21 * b21 * p * p) + (b21 * b21 * q * q) + (b22 * b22)) < 0)).
Proof. intros; psatz R 2. Qed.

(* kaji.exp.det-monotone/derivative-sign-changes.smt2 *)
Theorem kaji_exp_det_monotone__derivative_sign_changes : forall c L E E2 : R, ~ (((c > 0) /\ (E > 0) /\ (E2 > 0) /\ (((L > 0) /\ (((- 1) + c) > 0)) \/ ((L <= 0) /\ (((- 1) + c) <= 0))) /\ (((L = 0) /\ (((- 1) + c) = 0)) \/ ((~ (L = 0)) /\ (~ (((- 1) + c) = 0)))) /\ (((L < 0) /\ (((- 1) + c) < 0)) \/ ((L >= 0) /\ (((- 1) + c) >= 0))) /\ ((E * L) < 0) /\ ((E2 * L) > 0))).
Proof. intros; nra. Qed.

(* kaji.exp.det-monotone/derivative-zero-iff-det1-fails.smt2 *)
Theorem kaji_exp_det_monotone__derivative_zero_iff_det1_fails : forall c L E : R, ~ (((c > 0) /\ (E > 0) /\ (((L > 0) /\ (((- 1) + c) > 0)) \/ ((L <= 0) /\ (((- 1) + c) <= 0))) /\ (((L = 0) /\ (((- 1) + c) = 0)) \/ ((~ (L = 0)) /\ (~ (((- 1) + c) = 0)))) /\ (((L < 0) /\ (((- 1) + c) < 0)) \/ ((L >= 0) /\ (((- 1) + c) >= 0))) /\ ((~ ((E * L) = 0)) \/ (~ (((- 1) + c) = 0))) /\ (((E * L) = 0) \/ (((- 1) + c) = 0)))).
Proof. intros; nra. Qed.

(* kaji.exp.det-positive/eigenvalue-not-positive.smt2 *)
Theorem kaji_exp_det_positive__eigenvalue_not_positive : forall x y h l1 l2 : R, ~ (((x > 0) /\ (y > 0) /\ ((((- 1) * h * h) + (x * y)) > 0) /\ ((l1 + l2 + ((- 1) * x) + ((- 1) * y)) = 0) /\ (((h * h) + (l1 * l2) + ((- 1) * x * y)) = 0) /\ ((l1 <= 0) \/ (l2 <= 0)))).
Proof. intros; nra. Qed.

(* thesis.ex-2.2.4/decompositions-wrong.smt2 *)
Theorem thesis_ex_2_2_4__decompositions_wrong : forall r3 : R, ~ (((((- 3) + (r3 * r3)) = 0) /\ (r3 > 0) /\ ((~ (((3 / 4) + ((- (1 / 4)) * r3 * r3)) = 0)) \/ (~ (((3 / 2) + ((- (1 / 2)) * r3 * r3)) = 0)) \/ (~ (((- (3 / 8)) + ((1 / 8) * r3 * r3)) = 0)) \/ (~ (((3 / 8) + ((- (1 / 8)) * r3 * r3)) = 0)) \/ (((35 / 16) + ((- (1 / 16)) * r3 * r3)) <= 0)))).
Proof. intros; nra. Qed.

(* thesis.ex-2.2.4/lemma.L4.norm-vs-square.smt2 *)
Theorem thesis_ex_2_2_4__lemma_L4_norm_vs_square : forall a b : R, ~ (((a >= 0) /\ (b >= 0) /\ ((((a + ((- 1) * b)) <= 0) /\ (((a * a) + ((- 1) * b * b)) > 0)) \/ (((a + ((- 1) * b)) > 0) /\ (((a * a) + ((- 1) * b * b)) <= 0))))).
Proof. intros; nra. Qed.

(* thesis.ex-2.2.4/polar-not-good-area.L.smt2 *)
Theorem thesis_ex_2_2_4__polar_not_good_area_L : forall r3 t ts tt ts1 tt1 : R, ~ (((((- 3) + (r3 * r3)) = 0) /\ (r3 > 0) /\ (((t >= 0) /\ (((- 1) + t) <= 0) /\ ((1 + ((- (1 / 16)) * r3 * r3 * t * t) + t + ((3 / 16) * t * t)) <= 0)) \/ ((ts >= 0) /\ ((ts + ((- 1) * tt)) <= 0) /\ (((- 1) + tt) <= 0) /\ ((((- (1 / 16)) * r3 * r3 * ts * ts) + ((1 / 16) * r3 * r3 * tt * tt) + ts + ((3 / 16) * ts * ts) + ((- 1) * tt) + ((- (3 / 16)) * tt * tt)) > 0) /\ (ts1 >= 0) /\ ((ts1 + ((- 1) * tt1)) <= 0) /\ (((- 1) + tt1) <= 0) /\ ((((- (1 / 16)) * r3 * r3 * ts1 * ts1) + ((1 / 16) * r3 * r3 * tt1 * tt1) + ts1 + ((3 / 16) * ts1 * ts1) + ((- 1) * tt1) + ((- (3 / 16)) * tt1 * tt1)) < 0))))).
Proof. intros; nra. Qed.

(* thesis.ex-2.2.4/polar-not-good-area.smt2 *)
Theorem thesis_ex_2_2_4__polar_not_good_area : forall r3 t t1 t2 : R, ~ (((((- 3) + (r3 * r3)) = 0) /\ (r3 > 0) /\ (((t >= 0) /\ (((- 1) + t) <= 0) /\ ((1 + ((- (1 / 16)) * r3 * r3 * t * t) + t + ((3 / 16) * t * t)) <= 0)) \/ ((t1 >= 0) /\ (((- 1) + t1) <= 0) /\ ((1 + ((- (1 / 8)) * r3 * r3 * t1) + ((3 / 8) * t1)) < 0) /\ (t2 >= 0) /\ (((- 1) + t2) <= 0) /\ ((1 + ((- (1 / 8)) * r3 * r3 * t2) + ((3 / 8) * t2)) > 0))))).
Proof. intros; nra. Qed.

(* thesis.ex-2.2.4/polar-not-good-norm.smt2 *)
Theorem thesis_ex_2_2_4__polar_not_good_norm : forall r3 v1 v2 : R, ~ (((((- 3) + (r3 * r3)) = 0) /\ (r3 > 0) /\ (((- 1) + (v1 * v1) + (v2 * v2)) = 0) /\ ((((((- 1) * r3 * v1 * v2) + ((1 / 2) * v1 * v1) + ((3 / 2) * v2 * v2)) < 0) /\ ((((- 2) * r3 * v1 * v2) + ((1 / 8) * r3 * r3 * v1 * v1) + ((1 / 8) * r3 * r3 * v2 * v2) + ((5 / 8) * v1 * v1) + ((21 / 8) * v2 * v2)) > 0)) \/ (((((- 1) * r3 * v1 * v2) + ((1 / 2) * v1 * v1) + ((3 / 2) * v2 * v2)) > 0) /\ ((((- 2) * r3 * v1 * v2) + ((1 / 8) * r3 * r3 * v1 * v1) + ((1 / 8) * r3 * r3 * v2 * v2) + ((5 / 8) * v1 * v1) + ((21 / 8) * v2 * v2)) < 0))))).
Proof. intros; nra. Qed.

(* thesis.ex-2.2.4/svd-not-good-area.L.smt2 *)
Theorem thesis_ex_2_2_4__svd_not_good_area_L : forall r3 t ts tt ts1 tt1 : R, ~ (((((- 3) + (r3 * r3)) = 0) /\ (r3 > 0) /\ (((t >= 0) /\ (((- 1) + t) <= 0) /\ ((1 + t) <= 0)) \/ ((ts >= 0) /\ ((ts + ((- 1) * tt)) <= 0) /\ (((- 1) + tt) <= 0) /\ ((ts + ((- 1) * tt)) > 0) /\ (ts1 >= 0) /\ ((ts1 + ((- 1) * tt1)) <= 0) /\ (((- 1) + tt1) <= 0) /\ ((ts1 + ((- 1) * tt1)) < 0))))).
Proof. intros; nra. Qed.

(* thesis.ex-2.2.4/svd-not-good-area.smt2 *)
Theorem thesis_ex_2_2_4__svd_not_good_area : forall r3 t : R, ~ (((((- 3) + (r3 * r3)) = 0) /\ (r3 > 0) /\ (t >= 0) /\ (((- 1) + t) <= 0) /\ ((1 + t) <= 0))).
Proof. intros; nra. Qed.

(* thesis.sec-2.3.conic/corrected.on-conic-off-locus.smt2 *)
Theorem thesis_sec_2_3_conic__corrected_on_conic_off_locus : forall x y : R, ~ ((((x + ((- 4) * x * y) + (x * x) + y + (y * y)) = 0) /\ (~ ((((- (1 / 3)) * x) + ((4 / 3) * x * y) + ((- (1 / 3)) * x * x) + ((- (1 / 3)) * y) + ((- (1 / 3)) * y * y)) = 0)))).
Proof. intros; nra. Qed.

(* thesis.sec-2.3.conic/corrected.on-locus-off-conic.smt2 *)
Theorem thesis_sec_2_3_conic__corrected_on_locus_off_conic : forall x y : R, ~ ((((((- (1 / 3)) * x) + ((4 / 3) * x * y) + ((- (1 / 3)) * x * x) + ((- (1 / 3)) * y) + ((- (1 / 3)) * y * y)) = 0) /\ (~ ((x + ((- 4) * x * y) + (x * x) + y + (y * y)) = 0)))).
Proof. intros; nra. Qed.

(* thesis.sec-2.3.conic/denominator-not-positive.smt2 *)
Theorem thesis_sec_2_3_conic__denominator_not_positive : forall x y : R, ~ (((3 + ((- 2) * x) + (2 * x * y) + (x * x) + ((- 2) * y) + (y * y)) <= 0)).
Proof. intros; psatz R 2. Qed.

(* thesis.sec-2.3.min-energy/denominator-not-positive.smt2 *)
Theorem thesis_sec_2_3_min_energy__denominator_not_positive : forall x y : R, ~ (((3 + ((- 2) * x) + (2 * x * y) + (x * x) + ((- 2) * y) + (y * y)) <= 0)).
Proof. intros; psatz R 2. Qed.

(* thesis.sec-2.3.min-energy/hessian-not-positive-definite.smt2 *)
Theorem thesis_sec_2_3_min_energy__hessian_not_positive_definite : forall x y : R, ~ ((((6 + ((- 4) * x) + (4 * x * y) + (2 * x * x) + ((- 4) * y) + (2 * y * y)) <= 0) \/ ((32 + ((- 16) * x) + (32 * x * y) + ((- 24) * x * y * y) + (8 * x * y * y * y) + (12 * x * x) + ((- 8) * x * x * y) + (4 * x * x * y * y) + ((- 48) * y) + (40 * y * y) + ((- 16) * y * y * y) + (4 * y * y * y * y)) <= 0) \/ ((160 + ((- 192) * x) + (224 * x * y) + ((- 128) * x * y * y) + (32 * x * y * y * y) + (160 * x * x) + ((- 128) * x * x * y) + (32 * x * x * y * y) + ((- 64) * x * x * x) + (32 * x * x * x * y) + (16 * x * x * x * x) + ((- 192) * y) + (160 * y * y) + ((- 64) * y * y * y) + (16 * y * y * y * y)) <= 0) \/ ((192 + ((- 128) * x) + (128 * x * y) + (64 * x * x) + ((- 128) * y) + (64 * y * y)) <= 0))).
Proof. intros; psatz R 2. Qed.

(* thesis.sec-2.3.minimiser/hessian-not-positive-definite.smt2 *)
Theorem thesis_sec_2_3_minimiser__hessian_not_positive_definite : forall x y : R, ~ ((((6 + ((- 4) * x) + (4 * x * y) + (2 * x * x) + ((- 4) * y) + (2 * y * y)) <= 0) \/ ((32 + ((- 16) * x) + (32 * x * y) + ((- 24) * x * y * y) + (8 * x * y * y * y) + (12 * x * x) + ((- 8) * x * x * y) + (4 * x * x * y * y) + ((- 48) * y) + (40 * y * y) + ((- 16) * y * y * y) + (4 * y * y * y * y)) <= 0) \/ ((160 + ((- 192) * x) + (224 * x * y) + ((- 128) * x * y * y) + (32 * x * y * y * y) + (160 * x * x) + ((- 128) * x * x * y) + (32 * x * x * y * y) + ((- 64) * x * x * x) + (32 * x * x * x * y) + (16 * x * x * x * x) + ((- 192) * y) + (160 * y * y) + ((- 64) * y * y * y) + (16 * y * y * y * y)) <= 0) \/ ((192 + ((- 128) * x) + (128 * x * y) + (64 * x * x) + ((- 128) * y) + (64 * y * y)) <= 0))).
Proof. intros; psatz R 2. Qed.

(* thesis.thm-2.2.1/corrected.cond-not-prop.E.smt2 *)
Theorem thesis_thm_2_2_1__corrected_cond_not_prop_E : forall a b c d : R, ~ (((((a * d) + ((- 1) * b * c)) > 0) /\ ((((((- 1) * a) + (2 * a * d) + ((- 2) * b * c) + ((- 1) * d)) <= 0) /\ (((- 2) + a + d) <= 0)) \/ (((2 + ((- 1) * a) + ((- 1) * d)) <= 0) /\ ((a + ((- 2) * a * d) + (2 * b * c) + d) <= 0))) /\ ((((a * d) + ((- 1) * b * c)) <= 0) \/ ((((- 2) + a + d) < 0) /\ ((((- 1) * a) + (2 * a * d) + ((- 2) * b * c) + ((- 1) * d)) > 0)) \/ ((((- 2) + a + d) > 0) /\ ((((- 1) * a) + (2 * a * d) + ((- 2) * b * c) + ((- 1) * d)) < 0))))).
Proof. intros; nra. Qed.

(* thesis.thm-2.2.1/corrected.prop-not-cond.E.smt2 *)
Theorem thesis_thm_2_2_1__corrected_prop_not_cond_E : forall a b c d : R, ~ (((((a * d) + ((- 1) * b * c)) > 0) /\ (((((- 1) * a) + (2 * a * d) + ((- 2) * b * c) + ((- 1) * d)) > 0) \/ (((- 2) + a + d) > 0)) /\ (((2 + ((- 1) * a) + ((- 1) * d)) > 0) \/ ((a + ((- 2) * a * d) + (2 * b * c) + d) > 0)) /\ (((a * d) + ((- 1) * b * c)) > 0) /\ ((((- 2) + a + d) >= 0) \/ ((((- 1) * a) + (2 * a * d) + ((- 2) * b * c) + ((- 1) * d)) <= 0)) /\ ((((- 2) + a + d) <= 0) \/ ((((- 1) * a) + (2 * a * d) + ((- 2) * b * c) + ((- 1) * d)) >= 0)))).
Proof. intros; nra. Qed.

(* thesis.thm-2.2.1/printed.prop-not-cond.E.smt2 *)
Theorem thesis_thm_2_2_1__printed_prop_not_cond_E : forall a b c d : R, ~ (((((a * d) + ((- 1) * b * c)) > 0) /\ (((- 1) + a + ((- 1) * a * d) + (b * c) + d) < 0) /\ (((((- 1) * a) + (2 * a * d) + ((- 2) * b * c) + ((- 1) * d)) > 0) \/ (((- 2) + a + d) >= 0)) /\ (((2 + ((- 1) * a) + ((- 1) * d)) > 0) \/ ((a + ((- 2) * a * d) + (2 * b * c) + d) >= 0)) /\ (((a * d) + ((- 1) * b * c)) > 0) /\ ((((- 2) + a + d) >= 0) \/ ((((- 1) * a) + (2 * a * d) + ((- 2) * b * c) + ((- 1) * d)) <= 0)) /\ ((((- 2) + a + d) <= 0) \/ ((((- 1) * a) + (2 * a * d) + ((- 2) * b * c) + ((- 1) * d)) >= 0)))).
Proof. intros; nra. Qed.

(* thesis.thm-2.2.2/corrected.cond-not-prop.E.smt2 *)
Theorem thesis_thm_2_2_2__corrected_cond_not_prop_E : forall x y : R, ~ (((x > 0) /\ (y > 0) /\ ((((((- 1) * x) + (2 * x * y) + ((- 1) * y)) <= 0) /\ (((- 2) + x + y) <= 0)) \/ (((2 + ((- 1) * x) + ((- 1) * y)) <= 0) /\ ((x + ((- 2) * x * y) + y) <= 0))) /\ (((x * y) <= 0) \/ ((((- 2) + x + y) < 0) /\ ((((- 1) * x) + (2 * x * y) + ((- 1) * y)) > 0)) \/ ((((- 2) + x + y) > 0) /\ ((((- 1) * x) + (2 * x * y) + ((- 1) * y)) < 0))))).
Proof. intros; nra. Qed.

(* thesis.thm-2.2.2/corrected.prop-not-cond.E.smt2 *)
Theorem thesis_thm_2_2_2__corrected_prop_not_cond_E : forall x y : R, ~ (((x > 0) /\ (y > 0) /\ (((((- 1) * x) + (2 * x * y) + ((- 1) * y)) > 0) \/ (((- 2) + x + y) > 0)) /\ (((2 + ((- 1) * x) + ((- 1) * y)) > 0) \/ ((x + ((- 2) * x * y) + y) > 0)) /\ ((x * y) > 0) /\ ((((- 2) + x + y) >= 0) \/ ((((- 1) * x) + (2 * x * y) + ((- 1) * y)) <= 0)) /\ ((((- 2) + x + y) <= 0) \/ ((((- 1) * x) + (2 * x * y) + ((- 1) * y)) >= 0)))).
Proof. intros; nra. Qed.

(* thesis.thm-2.2.2/printed.prop-not-cond.E.smt2 *)
Theorem thesis_thm_2_2_2__printed_prop_not_cond_E : forall x y : R, ~ (((x > 0) /\ (y > 0) /\ (((- 1) + x + ((- 1) * x * y) + y) < 0) /\ (((((- 1) * x) + (2 * x * y) + ((- 1) * y)) > 0) \/ (((- 2) + x + y) >= 0)) /\ (((2 + ((- 1) * x) + ((- 1) * y)) > 0) \/ ((x + ((- 2) * x * y) + y) >= 0)) /\ ((x * y) > 0) /\ ((((- 2) + x + y) >= 0) \/ ((((- 1) * x) + (2 * x * y) + ((- 1) * y)) <= 0)) /\ ((((- 2) + x + y) <= 0) \/ ((((- 1) * x) + (2 * x * y) + ((- 1) * y)) >= 0)))).
Proof. intros; nra. Qed.

(* thesis.thm-2.2.4/corrected.cond-not-prop.E.smt2 *)
Theorem thesis_thm_2_2_4__corrected_cond_not_prop_E : forall x y h : R, ~ (((x > 0) /\ (y > 0) /\ ((((- 1) * h * h) + (x * y)) > 0) /\ ((((((- 2) * h * h) + ((- 1) * x) + (2 * x * y) + ((- 1) * y)) <= 0) /\ (((- 2) + x + y) <= 0)) \/ (((2 + ((- 1) * x) + ((- 1) * y)) <= 0) /\ (((2 * h * h) + x + ((- 2) * x * y) + y) <= 0))) /\ (((((- 1) * h * h) + (x * y)) <= 0) \/ ((((- 2) + x + y) < 0) /\ ((((- 2) * h * h) + ((- 1) * x) + (2 * x * y) + ((- 1) * y)) > 0)) \/ ((((- 2) + x + y) > 0) /\ ((((- 2) * h * h) + ((- 1) * x) + (2 * x * y) + ((- 1) * y)) < 0))))).
Proof. intros; nra. Qed.

(* thesis.thm-2.2.4/corrected.prop-not-cond.E.smt2 *)
Theorem thesis_thm_2_2_4__corrected_prop_not_cond_E : forall x y h : R, ~ (((x > 0) /\ (y > 0) /\ ((((- 1) * h * h) + (x * y)) > 0) /\ (((((- 2) * h * h) + ((- 1) * x) + (2 * x * y) + ((- 1) * y)) > 0) \/ (((- 2) + x + y) > 0)) /\ (((2 + ((- 1) * x) + ((- 1) * y)) > 0) \/ (((2 * h * h) + x + ((- 2) * x * y) + y) > 0)) /\ ((((- 1) * h * h) + (x * y)) > 0) /\ ((((- 2) + x + y) >= 0) \/ ((((- 2) * h * h) + ((- 1) * x) + (2 * x * y) + ((- 1) * y)) <= 0)) /\ ((((- 2) + x + y) <= 0) \/ ((((- 2) * h * h) + ((- 1) * x) + (2 * x * y) + ((- 1) * y)) >= 0)))).
Proof. intros; nra. Qed.

(* thesis.thm-2.2.4/printed.prop-not-cond.E.smt2 *)
Theorem thesis_thm_2_2_4__printed_prop_not_cond_E : forall x y h : R, ~ (((x > 0) /\ (y > 0) /\ ((((- 1) * h * h) + (x * y)) > 0) /\ (((- 1) + (h * h) + x + ((- 1) * x * y) + y) < 0) /\ (((((- 2) * h * h) + ((- 1) * x) + (2 * x * y) + ((- 1) * y)) > 0) \/ (((- 2) + x + y) >= 0)) /\ (((2 + ((- 1) * x) + ((- 1) * y)) > 0) \/ (((2 * h * h) + x + ((- 2) * x * y) + y) >= 0)) /\ ((((- 1) * h * h) + (x * y)) > 0) /\ ((((- 2) + x + y) >= 0) \/ ((((- 2) * h * h) + ((- 1) * x) + (2 * x * y) + ((- 1) * y)) <= 0)) /\ ((((- 2) + x + y) <= 0) \/ ((((- 2) * h * h) + ((- 1) * x) + (2 * x * y) + ((- 1) * y)) >= 0)))).
Proof. intros; nra. Qed.

(* thesis.thm-2.2.5/lemma.L4.norm-vs-square.smt2 *)
Theorem thesis_thm_2_2_5__lemma_L4_norm_vs_square : forall a b : R, ~ (((a >= 0) /\ (b >= 0) /\ ((((a + ((- 1) * b)) <= 0) /\ (((a * a) + ((- 1) * b * b)) > 0)) \/ (((a + ((- 1) * b)) > 0) /\ (((a * a) + ((- 1) * b * b)) <= 0))))).
Proof. intros; nra. Qed.

(* thesis.thm-2.2.5/printed.second-conjunct-implied.smt2 *)
Theorem thesis_thm_2_2_5__printed_second_conjunct_implied : forall x y h : R, ~ (((x > 0) /\ (y > 0) /\ ((((- 1) * h * h) + (x * y)) > 0) /\ ((1 + ((- 1) * h * h) + ((- 1) * x) + (x * y) + ((- 1) * y)) >= 0) /\ (((- 2) + x + y) < 0) /\ ((((- 1) + x) > 0) \/ (((- 1) + y) > 0)))).
Proof. intros; nra. Qed.

(* thesis.viete/eigen.k-outside-unit-interval.smt2 *)
Theorem thesis_viete__eigen_k_outside_unit_interval : forall m1 m2 m3 : R, ~ ((((2 * m1 * m2 * m3 * m3 * m3 * m3) + ((- 2) * m1 * m2 * m2 * m3 * m3 * m3) + ((- 2) * m1 * m2 * m2 * m2 * m3 * m3) + (2 * m1 * m2 * m2 * m2 * m2 * m3) + ((- 2) * m1 * m1 * m2 * m3 * m3 * m3) + (6 * m1 * m1 * m2 * m2 * m3 * m3) + ((- 2) * m1 * m1 * m2 * m2 * m2 * m3) + ((- 1) * m1 * m1 * m2 * m2 * m2 * m2) + ((- 1) * m1 * m1 * m3 * m3 * m3 * m3) + ((- 2) * m1 * m1 * m1 * m2 * m3 * m3) + ((- 2) * m1 * m1 * m1 * m2 * m2 * m3) + (2 * m1 * m1 * m1 * m2 * m2 * m2) + (2 * m1 * m1 * m1 * m3 * m3 * m3) + (2 * m1 * m1 * m1 * m1 * m2 * m3) + ((- 1) * m1 * m1 * m1 * m1 * m2 * m2) + ((- 1) * m1 * m1 * m1 * m1 * m3 * m3) + ((- 1) * m2 * m2 * m3 * m3 * m3 * m3) + (2 * m2 * m2 * m2 * m3 * m3 * m3) + ((- 1) * m2 * m2 * m2 * m2 * m3 * m3)) > 0)).
Proof. intros; psatz R 2. Qed.
