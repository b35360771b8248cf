(* Claims whose statements follow from the lemmas in a few lines, stated about Def 2.2.1 / Def 2.2.2 (Defs.v). *)
Require Import Reals Lra Psatz.
From Coquelicot Require Import Coquelicot.
Require Import Affinterp.Defs Affinterp.L9 Affinterp.L10 Affinterp.L12.
Open Scope R_scope.

(* atlas.svd.norm: R_{t alpha}((1 - t) I + t D) R_{t beta}, D = diag(x, y), x, y > 0, is good for norm iff
   beta^2 (x - y)^2 (x + y)^2 <= 4 x y (x - 1)(y - 1) (L9, L12). *)
Theorem atlas_svd_norm (x y alpha beta : R) :
  0 < x -> 0 < y ->
  (good_for_norm (A_s x y alpha beta) <-> beta ^ 2 * (x - y) ^ 2 * (x + y) ^ 2 <= 4 * x * y * (x - 1) * (y - 1)).
Proof. intros Hx Hy. rewrite L9 by assumption. apply L12; assumption. Qed.

(* thesis Thm 2.2.3 with beta = 0: good for norm iff (x >= 1 and y >= 1) or (0 < x <= 1 and 0 < y <= 1). *)
Theorem thesis_thm_2_2_3_beta0 (x y alpha : R) :
  0 < x -> 0 < y ->
  (good_for_norm (A_s x y alpha 0) <-> (x >= 1 /\ y >= 1) \/ (0 < x <= 1 /\ 0 < y <= 1)).
Proof.
  intros Hx Hy. rewrite atlas_svd_norm by assumption.
  replace (0 ^ 2 * (x - y) ^ 2 * (x + y) ^ 2) with 0 by ring.
  assert (Hxy : 0 < 4 * x * y) by nra.
  split.
  - intros H. assert (0 <= (x - 1) * (y - 1)).
    { destruct (Rle_or_lt 0 ((x - 1) * (y - 1))) as [| Hn]; [assumption |].
      assert (0 < 4 * x * y * - ((x - 1) * (y - 1))) by (apply Rmult_lt_0_compat; lra). nra. }
    destruct (Rlt_or_le 1 x); [left; split; nra |].
    destruct (Rlt_or_le x 1); [right; split; split; nra |].
    destruct (Rle_or_lt 1 y); [left | right]; split; try split; lra.
  - intros [[H1 H2] | [[_ H1] [_ H2]]].
    + assert (0 <= (x - 1) * (y - 1)) by nra. nra.
    + assert (0 <= (x - 1) * (y - 1)) by nra. nra.
Qed.

(* kaji.exp.det-positive: det A_E(t) > 0 for every real t (L10 (a)). *)
Theorem kaji_exp_det_positive (theta q l1 l2 : R) :
  0 < l1 -> 0 < l2 -> forall t, 0 < det (A_E theta q l1 l2 t).
Proof. intros H1 H2 t. rewrite L10a_det by assumption. apply exp_pos. Qed.

(* kaji.exp.det-monotone: det A_E(t) is monotone on all of R (non-decreasing if l1 l2 >= 1, non-increasing if
   l1 l2 <= 1); its derivative is identically 0 when l1 l2 = 1 and never 0 otherwise (L10 (a)). *)
Theorem kaji_exp_det_monotone (theta q l1 l2 : R) :
  0 < l1 -> 0 < l2 ->
  ((1 <= l1 * l2 -> forall s t, s <= t -> det (A_E theta q l1 l2 s) <= det (A_E theta q l1 l2 t)) /\
   (l1 * l2 <= 1 -> forall s t, s <= t -> det (A_E theta q l1 l2 t) <= det (A_E theta q l1 l2 s))) /\
  (l1 * l2 = 1 -> forall t, ln (l1 * l2) * Rpower (l1 * l2) t = 0) /\
  (l1 * l2 <> 1 -> forall t, ln (l1 * l2) * Rpower (l1 * l2) t <> 0).
Proof.
  intros H1 H2. assert (Hc : 0 < l1 * l2) by nra.
  split; [split |].
  - intros Hge s t Hst. rewrite !L10a_det by assumption. unfold Rpower.
    assert (0 <= ln (l1 * l2)) by (rewrite <- ln_1; apply ln_le; lra).
    assert (Hm : s * ln (l1 * l2) <= t * ln (l1 * l2)) by nra.
    destruct (Rle_lt_or_eq_dec _ _ Hm) as [Hlt | E]; [left; apply exp_increasing, Hlt | rewrite E; lra].
  - intros Hle s t Hst. rewrite !L10a_det by assumption. unfold Rpower.
    assert (ln (l1 * l2) <= 0) by (rewrite <- ln_1; apply ln_le; lra).
    assert (Hm : t * ln (l1 * l2) <= s * ln (l1 * l2)) by nra.
    destruct (Rle_lt_or_eq_dec _ _ Hm) as [Hlt | E]; [left; apply exp_increasing, Hlt | rewrite E; lra].
  - split.
    + intros E t. apply (proj1 (L10a_derivative_sign (l1 * l2) t Hc)), E.
    + intros E t. destruct (Rlt_or_le 1 (l1 * l2)).
      * pose proof (proj1 (proj2 (L10a_derivative_sign (l1 * l2) t Hc)) ltac:(lra)). lra.
      * pose proof (proj2 (proj2 (L10a_derivative_sign (l1 * l2) t Hc)) ltac:(lra)). lra.
Qed.
