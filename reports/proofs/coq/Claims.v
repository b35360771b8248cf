(* Claims whose statements follow from the lemmas in a few lines, stated about Def 2.2.1 / Def 2.2.2 (Defs.v). *)
Require Import Reals Lra Psatz FunctionalExtensionality.
From Coquelicot Require Import Coquelicot.
Require Import Affinterp.Defs Affinterp.L2 Affinterp.L3 Affinterp.L4 Affinterp.L5 Affinterp.L6 Affinterp.L8 Affinterp.L9
  Affinterp.L10 Affinterp.L12 Affinterp.Thm225.
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

(* The area cells: det B > 0 and tr B - 2, 2 det B - tr B both <= 0 or both >= 0 (the corrected condition of
   thesis Thm 2.2.1, 2.2.2, 2.2.4 and the atlas's, as their sentences state it). *)
Definition area_condition (B : mat) : Prop :=
  0 < det B /\ ((2 * det B - tr B <= 0 /\ tr B - 2 <= 0) \/ (0 <= tr B - 2 /\ 0 <= 2 * det B - tr B)).

(* atlas.linear.area, thesis Thm 2.2.1 corrected: (1 - t) I + t A is good for area iff the condition holds for A. *)
Theorem atlas_linear_area (A : mat) : good_for_area (blend A) <-> area_condition A.
Proof.
  rewrite L2_level_E. unfold area_condition, not_opposite.
  split; intros [Hd H]; split; try exact Hd.
  - destruct H as [Hn1 Hn2].
    destruct (Rle_or_lt (2 * det A - tr A) 0), (Rle_or_lt (tr A - 2) 0); [left; split; lra | right | right | right].
    + split; [lra | apply Rnot_lt_le; intros Hn; apply Hn2; lra].
    + split; [apply Rnot_lt_le; intros Hn; apply Hn1; lra | lra].
    + split; lra.
  - destruct H as [[H1 H2] | [H1 H2]]; split; intros [H3 H4]; lra.
Qed.

Lemma good_for_area_det (A B : R -> mat) :
  (forall t, det (A t) = det (B t)) -> (good_for_area A <-> good_for_area B).
Proof.
  intros E. unfold good_for_area.
  replace (fun t => det (A t)) with (fun t => det (B t)) by (apply functional_extensionality; intros; symmetry; apply E).
  split; intros [Hm Hp]; split; try exact Hm; intros t Ht; [rewrite <- E | rewrite E]; apply Hp, Ht.
Qed.

(* atlas.svd.area, thesis Thm 2.2.2 corrected: with tr D and det D in place of tr A and det A (L5). *)
Theorem atlas_svd_area (x y alpha beta : R) : good_for_area (A_s x y alpha beta) <-> area_condition (Mat x 0 0 y).
Proof.
  rewrite <- atlas_linear_area. apply good_for_area_det. intros t. unfold A_s. apply L5_det_homotopy.
Qed.

(* atlas.polar.area, thesis Thm 2.2.4 corrected: with tr S and det S (L5). *)
Theorem atlas_polar_area (theta : R) (S : mat) : good_for_area (A_p theta S) <-> area_condition S.
Proof.
  rewrite <- atlas_linear_area. apply good_for_area_det. intros t. unfold A_p.
  rewrite L5_det_product, L5_det_rotation. ring.
Qed.

(* Level N (LEMMAS.md, "Level N" under L8): the linear blend is good for norm iff Q <= 0 or P - nu Q >= 0 for
   some nu >= 0, with P = sym(B - I), Q = P + (B - I)^T (B - I) (L6, L4, L3, L8). *)
Theorem level_N (B : mat) :
  good_for_norm (blend B) <->
  nsd (Q_of B) \/ exists nu, 0 <= nu /\ psd (madd (P_of B) (mscale (- nu) (Q_of B))).
Proof.
  assert (HP : symmetric (P_of B)) by (destruct B; unfold symmetric, P_of, M_of, sym, madd, mscale, transpose, Id2; simpl; ring).
  assert (HQ : symmetric (Q_of B)).
  { destruct B; unfold symmetric, Q_of, P_of, M_of, sym, madd, mscale, mmul, transpose, Id2; simpl; ring. }
  rewrite <- (L8 _ _ HP HQ). unfold good_for_norm. rewrite L6_unit_vs_all.
  setoid_rewrite L4. setoid_rewrite L3. split.
  - intros H [v Hv]. exact (H v Hv).
  - intros H v Hv. apply H. exists v. exact Hv.
Qed.
