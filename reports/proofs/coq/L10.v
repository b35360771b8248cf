(* L10: the exp-log homotopy A_E(t) = R_{t theta} S^t (LEMMAS.md, L10).
   S = Q diag(l1, l2) Q^T with Q = R_q a rotation and l1, l2 > 0 (every symmetric positive definite S has this
   form, L13); S^t = Q diag(l1^t, l2^t) Q^T with l^t = Rpower l t = exp(t ln l). *)
Require Import Reals Lra Psatz.
From Coquelicot Require Import Coquelicot.
Require Import Affinterp.Defs Affinterp.L1 Affinterp.L4 Affinterp.L5 Affinterp.L6.
Open Scope R_scope.

Definition S_pow (q l1 l2 t : R) : mat :=
  mmul (rot q) (mmul (Mat (Rpower l1 t) 0 0 (Rpower l2 t)) (transpose (rot q))).
Definition A_E (theta q l1 l2 : R) (t : R) : mat := mmul (rot (t * theta)) (S_pow q l1 l2 t).

Lemma det_transpose (A : mat) : det (transpose A) = det A.
Proof. destruct A; unfold det, transpose; simpl; ring. Qed.

(* (a) det A_E(t) = c^t with c = det S = l1 l2. *)
Theorem L10a_det (theta q l1 l2 t : R) :
  0 < l1 -> 0 < l2 -> det (A_E theta q l1 l2 t) = Rpower (l1 * l2) t.
Proof.
  intros H1 H2. unfold A_E, S_pow.
  rewrite !L5_det_product, det_transpose, !L5_det_rotation.
  unfold det; simpl. rewrite <- Rpower_mult_distr by assumption. ring.
Qed.

Theorem L10a_derivative (theta q l1 l2 t : R) :
  0 < l1 -> 0 < l2 ->
  is_derive (fun t => det (A_E theta q l1 l2 t)) t (ln (l1 * l2) * Rpower (l1 * l2) t).
Proof.
  intros H1 H2.
  apply (is_derive_ext (fun t => exp (t * ln (l1 * l2)))).
  { intros s. rewrite L10a_det by assumption. reflexivity. }
  unfold Rpower. auto_derive; [exact I | ring].
Qed.

(* The derivative (log c) c^t is identically 0 if c = 1, and otherwise never 0 and of the sign of c - 1. *)
Theorem L10a_derivative_sign (c t : R) :
  0 < c ->
  (c = 1 -> ln c * Rpower c t = 0) /\ (1 < c -> 0 < ln c * Rpower c t) /\
  (c < 1 -> ln c * Rpower c t < 0).
Proof.
  intros Hc. assert (0 < Rpower c t) by apply exp_pos.
  split; [intros ->; rewrite ln_1; ring | split; intros Hc1].
  - assert (0 < ln c) by (rewrite <- ln_1; apply ln_increasing; lra). nra.
  - assert (ln c < 0) by (rewrite <- ln_1; apply ln_increasing; lra). nra.
Qed.

(* Hence A_E is good for area (Def 2.2.1) for every S ... *)
Theorem L10a_good_for_area (theta q l1 l2 : R) :
  0 < l1 -> 0 < l2 -> good_for_area (A_E theta q l1 l2).
Proof.
  intros H1 H2. split.
  - rewrite (L1 _ _ (fun t _ => L10a_derivative theta q l1 l2 t H1 H2)).
    assert (Hc : 0 < l1 * l2) by nra.
    destruct (Rle_or_lt 1 (l1 * l2)) as [Hge | Hlt]; [left | right]; intros t _;
      destruct (L10a_derivative_sign (l1 * l2) t Hc) as [H0 [Hp Hn]].
    + destruct (Req_dec (l1 * l2) 1) as [E | E]; [rewrite (H0 E); lra | left; apply Hp; lra].
    + left. apply Hn, Hlt.
  - intros t _. rewrite L10a_det by assumption. apply exp_pos.
Qed.

(* ... and det A_E is strictly monotone unless det S = 1. *)
Theorem L10a_strict (theta q l1 l2 : R) :
  0 < l1 -> 0 < l2 -> l1 * l2 <> 1 ->
  forall s t, 0 <= s -> s < t -> t <= 1 -> det (A_E theta q l1 l2 s) <> det (A_E theta q l1 l2 t).
Proof.
  intros H1 H2 Hc s t _ Hst _. rewrite !L10a_det by assumption. unfold Rpower. intros E.
  apply exp_inv in E.
  assert (ln (l1 * l2) = 0) by (apply (Rmult_eq_reg_r (t - s)); [lra | lra]).
  apply Hc, ln_inv; [nra | lra | rewrite ln_1; assumption].
Qed.

(* (b) ||S^t v||^2 = l1^{2t} w1^2 + l2^{2t} w2^2 with w = Q^T v (identity L10.spectral-norm). *)
Definition g_norm (a b x y t : R) : R := exp (2 * t * a) * x ^ 2 + exp (2 * t * b) * y ^ 2.
Definition g_norm' (a b x y t : R) : R := 2 * (a * exp (2 * t * a) * x ^ 2 + b * exp (2 * t * b) * y ^ 2).

Lemma g_norm_derivative (a b x y t : R) : is_derive (g_norm a b x y) t (g_norm' a b x y t).
Proof. unfold g_norm, g_norm'. auto_derive; [exact I | ring]. Qed.

Lemma Rpower_sq (l t : R) : Rpower l t ^ 2 = exp (2 * t * ln l).
Proof.
  unfold Rpower. replace (exp (t * ln l) ^ 2) with (exp (t * ln l) * exp (t * ln l)) by ring.
  rewrite <- exp_plus. f_equal. ring.
Qed.

Lemma L10_spectral_norm (theta q l1 l2 t : R) (v : vec) :
  let w := mvec (transpose (rot q)) v in
  norm2 (mvec (A_E theta q l1 l2 t) v) = g_norm (ln l1) (ln l2) (v1 w) (v2 w) t.
Proof.
  intros w. unfold A_E, S_pow. rewrite !mvec_mmul, !L5_norm_rotation.
  unfold g_norm. rewrite <- !Rpower_sq. fold w. unfold norm2, mvec; simpl. ring.
Qed.

Lemma rot_transpose_mvec (q : R) (w : vec) : mvec (transpose (rot q)) (mvec (rot q) w) = w.
Proof.
  destruct w as [x y]. pose proof (sin2_cos2 q) as E. unfold Rsqr in E.
  unfold mvec, transpose, rot; simpl. f_equal.
  - transitivity (x * (sin q * sin q + cos q * cos q)); [ring | rewrite E; ring].
  - transitivity (y * (sin q * sin q + cos q * cos q)); [ring | rewrite E; ring].
Qed.

(* With l1 > 0 > l2 the witness w1 = 1, w2^2 = -l1 (1 + E) / (2 l2), E = e^{2 (l1 - l2)} (identity
   L10.witness) has g'(0) < 0 < g'(1). *)
Lemma L10_witness (a b : R) :
  0 < a -> b < 0 -> exists y, g_norm' a b 1 y 0 < 0 /\ 0 < g_norm' a b 1 y 1.
Proof.
  intros Ha Hb. set (E := exp (2 * (a - b))).
  assert (HE : 1 < E) by (unfold E; rewrite <- exp_0; apply exp_increasing; lra).
  set (Y := - a * (1 + E) / (2 * b)).
  assert (Hy : 0 <= Y).
  { unfold Y. replace (- a * (1 + E) / (2 * b)) with (a * (1 + E) * / (- 2 * b)) by (field; lra).
    apply Rmult_le_pos; [nra | left; apply Rinv_0_lt_compat; lra]. }
  assert (HbY : b * Y = - a * (1 + E) / 2) by (unfold Y; field; lra).
  assert (Hexp : exp (2 * 1 * a) = E * exp (2 * 1 * b)) by (unfold E; rewrite <- exp_plus; f_equal; ring).
  pose proof (exp_pos (2 * 1 * b)) as Hb1.
  exists (sqrt Y). unfold g_norm'.
  rewrite <- (Rsqr_pow2 (sqrt Y)), Rsqr_sqrt by exact Hy.
  replace (2 * 0 * a) with 0 by ring. replace (2 * 0 * b) with 0 by ring. rewrite exp_0, Hexp. split.
  - replace (2 * (a * 1 * 1 ^ 2 + b * 1 * Y)) with (2 * a + 2 * (b * Y)) by ring. rewrite HbY. nra.
  - replace (2 * (a * (E * exp (2 * 1 * b)) * 1 ^ 2 + b * exp (2 * 1 * b) * Y))
      with (exp (2 * 1 * b) * (2 * a * E + 2 * (b * Y))) by ring.
    rewrite HbY. apply Rmult_lt_0_compat; nra.
Qed.

Lemma ln_sign (l : R) : 0 < l -> (0 <= ln l <-> 1 <= l) /\ (ln l <= 0 <-> l <= 1).
Proof.
  intros Hl. split; split; intros H.
  - destruct (Rlt_or_le l 1) as [Hl1 | ]; [| assumption].
    assert (ln l < ln 1) by (apply ln_increasing; lra). rewrite ln_1 in *. lra.
  - rewrite <- ln_1. apply ln_le; lra.
  - destruct (Rlt_or_le 1 l) as [Hl1 | ]; [| assumption].
    assert (ln 1 < ln l) by (apply ln_increasing; lra). rewrite ln_1 in *. lra.
  - rewrite <- ln_1. apply ln_le; lra.
Qed.

Theorem L10b_good_for_norm (theta q l1 l2 : R) :
  0 < l1 -> 0 < l2 -> (good_for_norm (A_E theta q l1 l2) <-> 0 <= (l1 - 1) * (l2 - 1)).
Proof.
  intros H1 H2. unfold good_for_norm.
  rewrite L6_unit_vs_all. setoid_rewrite L4.
  assert (Hg : forall v, monotone01 (fun t => norm2 (mvec (A_E theta q l1 l2 t) v)) <->
                         let w := mvec (transpose (rot q)) v in
                         monotone01 (g_norm (ln l1) (ln l2) (v1 w) (v2 w))).
  { intros v. split; apply monotone01_ext; intros t; rewrite L10_spectral_norm; reflexivity. }
  setoid_rewrite Hg.
  destruct (ln_sign l1 H1) as [P1 N1]. destruct (ln_sign l2 H2) as [P2 N2].
  split.
  - intros Hm. destruct (Rle_or_lt 0 ((l1 - 1) * (l2 - 1))) as [| Hneg]; [assumption | exfalso].
    assert (Hcase : (0 < ln l1 /\ ln l2 < 0) \/ (ln l1 < 0 /\ 0 < ln l2)).
    { destruct (Rlt_or_le 1 l1).
      - left. split; [apply Rnot_le_lt; intros Hl; apply N1 in Hl | apply Rnot_le_lt; intros Hl; apply P2 in Hl]; nra.
      - right. split; [apply Rnot_le_lt; intros Hl; apply P1 in Hl | apply Rnot_le_lt; intros Hl; apply N2 in Hl]; nra. }
    destruct Hcase as [[Ha Hb] | [Ha Hb]].
    + destruct (L10_witness _ _ Ha Hb) as [y [Hy0 Hy1]].
      specialize (Hm (mvec (rot q) (Vec 1 y))). cbv zeta in Hm. rewrite rot_transpose_mvec in Hm.
      exact (L1_consequence _ _ 1 0 (fun t _ => g_norm_derivative _ _ _ _ t)
               ltac:(lra) Hy1 ltac:(lra) Hy0 Hm).
    + destruct (L10_witness _ _ Hb Ha) as [y [Hy0 Hy1]].
      specialize (Hm (mvec (rot q) (Vec y 1))). cbv zeta in Hm. rewrite rot_transpose_mvec in Hm.
      simpl in Hm.
      assert (Hswap : forall t, g_norm (ln l1) (ln l2) y 1 t = g_norm (ln l2) (ln l1) 1 y t).
      { intros t. unfold g_norm. ring. }
      apply (monotone01_ext _ _ Hswap) in Hm.
      exact (L1_consequence _ _ 1 0 (fun t _ => g_norm_derivative _ _ _ _ t)
               ltac:(lra) Hy1 ltac:(lra) Hy0 Hm).
  - intros Hc v. cbv zeta.
    rewrite (L1 _ _ (fun t _ => g_norm_derivative _ _ _ _ t)). unfold g_norm'.
    assert (Hsame : (0 <= ln l1 /\ 0 <= ln l2) \/ (ln l1 <= 0 /\ ln l2 <= 0)).
    { destruct (Rle_or_lt 1 l1), (Rle_or_lt 1 l2).
      - left. split; [apply P1 | apply P2]; lra.
      - destruct (Req_dec l1 1) as [E |]; [right; split; [apply N1 | apply N2]; lra | nra].
      - destruct (Req_dec l2 1) as [E |]; [right; split; [apply N1 | apply N2]; lra | nra].
      - right. split; [apply N1 | apply N2]; lra. }
    set (x := v1 (mvec (transpose (rot q)) v)). set (y := v2 (mvec (transpose (rot q)) v)).
    destruct Hsame as [[Ha Hb] | [Ha Hb]]; [left | right]; intros t _;
      pose proof (exp_pos (2 * t * ln l1)); pose proof (exp_pos (2 * t * ln l2));
      assert (0 <= x ^ 2) by nra; assert (0 <= y ^ 2) by nra.
    + assert (0 <= ln l1 * exp (2 * t * ln l1) * x ^ 2) by (apply Rmult_le_pos; [apply Rmult_le_pos |]; lra).
      assert (0 <= ln l2 * exp (2 * t * ln l2) * y ^ 2) by (apply Rmult_le_pos; [apply Rmult_le_pos |]; lra).
      lra.
    + assert (0 <= - ln l1 * exp (2 * t * ln l1) * x ^ 2) by (apply Rmult_le_pos; [apply Rmult_le_pos |]; lra).
      assert (0 <= - ln l2 * exp (2 * t * ln l2) * y ^ 2) by (apply Rmult_le_pos; [apply Rmult_le_pos |]; lra).
      lra.
Qed.
