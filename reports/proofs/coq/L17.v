(* L17: the exp-log homotopy in 3D (LEMMAS.md, L17). A(t) = R^t S^t with R^t as in L14 (axis k, angle theta),
   S = O diag(l1, l2, l3) O^T with O orthogonal and l1, l2, l3 > 0, S^t = O diag(l1^t, l2^t, l3^t) O^T,
   l^t = Rpower l t. 3D Def 2.2.1 and Def 2.2.2 (every v, unit or not) as in LEMMAS.md. *)
Require Import Reals Lra Psatz.
From Coquelicot Require Import Coquelicot.
Require Import Affinterp.Defs Affinterp.Defs3 Affinterp.L1 Affinterp.L4 Affinterp.L10 Affinterp.L14
  Affinterp.L15.
Open Scope R_scope.

Definition S_pow3 (O : mat3) (l1 l2 l3 t : R) : mat3 :=
  mmul3 O (mmul3 (diag3 (Rpower l1 t) (Rpower l2 t) (Rpower l3 t)) (transpose3 O)).
Definition A_E3 (k1 k2 k3 theta : R) (O : mat3) (l1 l2 l3 : R) (t : R) : mat3 :=
  mmul3 (rpow k1 k2 k3 theta t) (S_pow3 O l1 l2 l3 t).

Definition good_for_volume3 (A : R -> mat3) : Prop :=
  monotone01 (fun t => det3 (A t)) /\ forall t, 0 <= t <= 1 -> 0 < det3 (A t).
Definition good_for_norm3 (A : R -> mat3) : Prop :=
  forall v, monotone01 (fun t => norm3 (mvec3 (A t) v)).

Lemma det3_transpose3 (A : mat3) : det3 (transpose3 A) = det3 A.
Proof. destruct A; unfold det3, transpose3; simpl; ring. Qed.

(* (a) det R^t S^t = (l1 l2 l3)^t. *)
Theorem L17a_det (k1 k2 k3 theta : R) (O : mat3) (l1 l2 l3 t : R) :
  k1 ^ 2 + k2 ^ 2 + k3 ^ 2 = 1 -> orthogonal3 O -> 0 < l1 -> 0 < l2 -> 0 < l3 ->
  det3 (A_E3 k1 k2 k3 theta O l1 l2 l3 t) = Rpower (l1 * l2 * l3) t.
Proof.
  intros Hk [HO _] H1 H2 H3. unfold A_E3, S_pow3. rewrite L14_det_left by exact Hk.
  rewrite !det3_mmul3, det3_transpose3.
  assert (HdO : det3 O * det3 O = 1).
  { rewrite <- det3_transpose3 at 1. rewrite <- det3_mmul3, HO. unfold det3, Id3; simpl; ring. }
  rewrite <- (Rpower_mult_distr (l1 * l2) l3 t), <- (Rpower_mult_distr l1 l2 t) by nra.
  transitivity (det3 O * det3 O * (Rpower l1 t * Rpower l2 t * Rpower l3 t));
    [unfold det3 at 2, diag3; simpl; ring | rewrite HdO; ring].
Qed.

Theorem L17a_good_for_volume (k1 k2 k3 theta : R) (O : mat3) (l1 l2 l3 : R) :
  k1 ^ 2 + k2 ^ 2 + k3 ^ 2 = 1 -> orthogonal3 O -> 0 < l1 -> 0 < l2 -> 0 < l3 ->
  good_for_volume3 (A_E3 k1 k2 k3 theta O l1 l2 l3).
Proof.
  intros Hk HO H1 H2 H3. set (c := l1 * l2 * l3). assert (Hc : 0 < c) by (unfold c; apply Rmult_lt_0_compat; [apply Rmult_lt_0_compat |]; assumption).
  assert (Hd : forall t, 0 <= t <= 1 ->
    is_derive (fun t => det3 (A_E3 k1 k2 k3 theta O l1 l2 l3 t)) t (ln c * Rpower c t)).
  { intros t _. apply (is_derive_ext (fun t => exp (t * ln c))).
    { intros s. rewrite L17a_det by assumption. reflexivity. }
    unfold Rpower. auto_derive; [exact I | ring]. }
  split.
  - rewrite (L1 _ _ Hd).
    destruct (Rle_or_lt 1 c) as [Hge | Hlt]; [left | right]; intros t _;
      destruct (L10a_derivative_sign c t Hc) as [H0 [Hp Hn]].
    + destruct (Req_dec c 1) as [E | E]; [rewrite (H0 E); lra | left; apply Hp; lra].
    + left. apply Hn, Hlt.
  - intros t _. rewrite L17a_det by assumption. apply exp_pos.
Qed.

(* (b) ||R^t S^t v||^2 = sum_i l_i^{2t} u_i^2 with u = O^T v. *)
Definition g3 (a b c x y z t : R) : R := exp (2 * t * a) * x ^ 2 + exp (2 * t * b) * y ^ 2 + exp (2 * t * c) * z ^ 2.
Definition g3' (a b c x y z t : R) : R :=
  2 * (a * exp (2 * t * a) * x ^ 2 + b * exp (2 * t * b) * y ^ 2 + c * exp (2 * t * c) * z ^ 2).

Lemma g3_derivative (a b c x y z t : R) : is_derive (g3 a b c x y z) t (g3' a b c x y z t).
Proof. unfold g3, g3'. auto_derive; [exact I | ring]. Qed.

Lemma L17_spectral_norm (k1 k2 k3 theta : R) (O : mat3) (l1 l2 l3 t : R) (v : vec3) :
  k1 ^ 2 + k2 ^ 2 + k3 ^ 2 = 1 -> orthogonal3 O ->
  let u := mvec3 (transpose3 O) v in
  norm2_3 (mvec3 (A_E3 k1 k2 k3 theta O l1 l2 l3 t) v) = g3 (ln l1) (ln l2) (ln l3) (u1 u) (u2 u) (u3 u) t.
Proof.
  intros Hk [HO _] u. destruct (L14_rotation k1 k2 k3 theta t Hk) as [[HR _] _].
  unfold A_E3, S_pow3. rewrite !mvec3_mmul3, norm2_3_orthogonal, norm2_3_orthogonal by assumption.
  fold u. unfold g3. rewrite <- !Rpower_sq. unfold norm2_3, mvec3, diag3; simpl. ring.
Qed.

(* Permuting the axes. *)
Lemma g3_swap12 (a b c x y z t : R) : g3 a b c x y z t = g3 b a c y x z t.
Proof. unfold g3; ring. Qed.
Lemma g3_swap13 (a b c x y z t : R) : g3 a b c x y z t = g3 c b a z y x t.
Proof. unfold g3; ring. Qed.
Lemma g3_swap23 (a b c x y z t : R) : g3 a b c x y z t = g3 a c b x z y t.
Proof. unfold g3; ring. Qed.

(* a > 0 > b: some u = (1, y, 0) gives a non-monotone squared norm (L10's witness, L1). *)
Lemma witness3 (a b c : R) : 0 < a -> b < 0 -> exists y, ~ monotone01 (g3 a b c 1 y 0).
Proof.
  intros Ha Hb. destruct (L10_witness a b Ha Hb) as [y [Hy0 Hy1]]. exists y.
  assert (E : forall t, g3' a b c 1 y 0 t = g_norm' a b 1 y t) by (intros t; unfold g3', g_norm'; ring).
  apply (L1_consequence _ _ 1 0 (fun t _ => g3_derivative a b c 1 y 0 t)); [lra | rewrite E; exact Hy1 | lra |
    rewrite E; exact Hy0].
Qed.

Lemma L4_3 (A : R -> mat3) (v : vec3) :
  monotone01 (fun t => norm3 (mvec3 (A t) v)) <-> monotone01 (fun t => norm2_3 (mvec3 (A t) v)).
Proof.
  rewrite (L4_nonneg (fun t => norm3 (mvec3 (A t) v))) by (intros; apply sqrt_pos).
  assert (E : forall t, norm3 (mvec3 (A t) v) ^ 2 = norm2_3 (mvec3 (A t) v)).
  { intros t. unfold norm3. rewrite <- Rsqr_pow2. apply Rsqr_sqrt. unfold norm2_3. nra. }
  split; apply monotone01_ext; intros t; [rewrite E | rewrite <- E]; reflexivity.
Qed.

Lemma mono_ext_iff (f g : R -> R) : (forall t, f t = g t) -> (monotone01 f <-> monotone01 g).
Proof. intros E. split; apply monotone01_ext; intros t; [rewrite E | rewrite <- E]; reflexivity. Qed.

(* (b) good for norm iff S - I is semidefinite: all l_i >= 1 or all l_i <= 1. *)
Theorem L17b_good_for_norm (k1 k2 k3 theta : R) (O : mat3) (l1 l2 l3 : R) :
  k1 ^ 2 + k2 ^ 2 + k3 ^ 2 = 1 -> orthogonal3 O -> 0 < l1 -> 0 < l2 -> 0 < l3 ->
  (good_for_norm3 (A_E3 k1 k2 k3 theta O l1 l2 l3) <->
   (1 <= l1 /\ 1 <= l2 /\ 1 <= l3) \/ (l1 <= 1 /\ l2 <= 1 /\ l3 <= 1)).
Proof.
  intros Hk HO H1 H2 H3. unfold good_for_norm3.
  assert (Hg : forall v, monotone01 (fun t => norm3 (mvec3 (A_E3 k1 k2 k3 theta O l1 l2 l3 t) v)) <->
    monotone01 (g3 (ln l1) (ln l2) (ln l3) (u1 (mvec3 (transpose3 O) v)) (u2 (mvec3 (transpose3 O) v))
                   (u3 (mvec3 (transpose3 O) v)))).
  { intros v. rewrite L4_3. apply mono_ext_iff. intros t. apply L17_spectral_norm; assumption. }
  setoid_rewrite Hg.
  destruct (ln_sign l1 H1) as [P1 N1]. destruct (ln_sign l2 H2) as [P2 N2]. destruct (ln_sign l3 H3) as [P3 N3].
  set (a := ln l1) in *. set (b := ln l2) in *. set (c := ln l3) in *.
  split.
  - intros Hm.
    assert (Hu : forall x y z, monotone01 (g3 a b c x y z)).
    { intros x y z. destruct (L15a_onto O HO (Vec3 x y z)) as [v Hv]. specialize (Hm v). rewrite Hv in Hm.
      exact Hm. }
    destruct (Rle_or_lt 0 a) as [Ha | Ha]; destruct (Rle_or_lt 0 b) as [Hb | Hb];
      destruct (Rle_or_lt 0 c) as [Hc | Hc].
    + left. repeat split; [apply P1 | apply P2 | apply P3]; assumption.
    + (* b >= 0 > c; then a > 0 or b > 0 gives a witness, else a = b = 0 *)
      destruct (Req_dec b 0) as [Eb | Eb]; [destruct (Req_dec a 0) as [Ea | Ea] |].
      * right. repeat split; [apply N1 | apply N2 | apply N3]; lra.
      * exfalso. destruct (witness3 a c b ltac:(lra) Hc) as [y Hy]. apply Hy.
        apply (proj1 (mono_ext_iff _ _ (fun t => g3_swap23 a b c 1 0 y t))), Hu.
      * exfalso. destruct (witness3 b c a ltac:(lra) Hc) as [y Hy]. apply Hy.
        apply (proj1 (mono_ext_iff _ _ (fun t => eq_trans (g3_swap12 a b c 0 1 y t) (g3_swap23 b a c 1 0 y t)))), Hu.
    + destruct (Req_dec a 0) as [Ea | Ea]; [destruct (Req_dec c 0) as [Ec | Ec] |].
      * right. repeat split; [apply N1 | apply N2 | apply N3]; lra.
      * exfalso. destruct (witness3 c b a ltac:(lra) Hb) as [y Hy]. apply Hy.
        apply (proj1 (mono_ext_iff _ _ (fun t => eq_trans (g3_swap13 a b c 0 y 1 t) eq_refl))), Hu.
      * exfalso. destruct (witness3 a b c ltac:(lra) Hb) as [y Hy]. apply Hy. apply Hu.
    + destruct (Req_dec a 0) as [Ea | Ea].
      * right. repeat split; [apply N1 | apply N2 | apply N3]; lra.
      * exfalso. destruct (witness3 a b c ltac:(lra) Hb) as [y Hy]. apply Hy. apply Hu.
    + destruct (Req_dec b 0) as [Eb | Eb]; [destruct (Req_dec c 0) as [Ec | Ec] |].
      * right. repeat split; [apply N1 | apply N2 | apply N3]; lra.
      * exfalso. destruct (witness3 c a b ltac:(lra) Ha) as [y Hy]. apply Hy.
        apply (proj1 (mono_ext_iff _ _ (fun t => eq_trans (g3_swap13 a b c y 0 1 t) (g3_swap23 c b a 1 0 y t)))),
          Hu.
      * exfalso. destruct (witness3 b a c ltac:(lra) Ha) as [y Hy]. apply Hy.
        apply (proj1 (mono_ext_iff _ _ (fun t => g3_swap12 a b c y 1 0 t))), Hu.
    + destruct (Req_dec b 0) as [Eb | Eb].
      * right. repeat split; [apply N1 | apply N2 | apply N3]; lra.
      * exfalso. destruct (witness3 b a c ltac:(lra) Ha) as [y Hy]. apply Hy.
        apply (proj1 (mono_ext_iff _ _ (fun t => g3_swap12 a b c y 1 0 t))), Hu.
    + destruct (Req_dec c 0) as [Ec | Ec].
      * right. repeat split; [apply N1 | apply N2 | apply N3]; lra.
      * exfalso. destruct (witness3 c a b ltac:(lra) Ha) as [y Hy]. apply Hy.
        apply (proj1 (mono_ext_iff _ _ (fun t => eq_trans (g3_swap13 a b c y 0 1 t) (g3_swap23 c b a 1 0 y t)))),
          Hu.
    + right. repeat split; [apply N1 | apply N2 | apply N3]; lra.
  - intros Hc v.
    rewrite (L1 _ _ (fun t _ => g3_derivative _ _ _ _ _ _ t)). unfold g3'.
    set (x := u1 (mvec3 (transpose3 O) v)). set (y := u2 (mvec3 (transpose3 O) v)).
    set (z := u3 (mvec3 (transpose3 O) v)).
    assert (Hsame : (0 <= a /\ 0 <= b /\ 0 <= c) \/ (a <= 0 /\ b <= 0 /\ c <= 0)).
    { destruct Hc as [(A1 & A2 & A3) | (A1 & A2 & A3)]; [left | right];
        repeat split; [apply P1 | apply P2 | apply P3 | apply N1 | apply N2 | apply N3]; assumption. }
    assert (Hx : 0 <= x ^ 2) by nra. assert (Hy : 0 <= y ^ 2) by nra. assert (Hz : 0 <= z ^ 2) by nra.
    destruct Hsame as [(Ha & Hb & Hc') | (Ha & Hb & Hc')]; [left | right]; intros t _;
      pose proof (exp_pos (2 * t * a)); pose proof (exp_pos (2 * t * b)); pose proof (exp_pos (2 * t * c)).
    + assert (0 <= a * exp (2 * t * a) * x ^ 2) by (apply Rmult_le_pos; [apply Rmult_le_pos |]; lra).
      assert (0 <= b * exp (2 * t * b) * y ^ 2) by (apply Rmult_le_pos; [apply Rmult_le_pos |]; lra).
      assert (0 <= c * exp (2 * t * c) * z ^ 2) by (apply Rmult_le_pos; [apply Rmult_le_pos |]; lra).
      lra.
    + assert (0 <= - a * exp (2 * t * a) * x ^ 2) by (apply Rmult_le_pos; [apply Rmult_le_pos |]; lra).
      assert (0 <= - b * exp (2 * t * b) * y ^ 2) by (apply Rmult_le_pos; [apply Rmult_le_pos |]; lra).
      assert (0 <= - c * exp (2 * t * c) * z ^ 2) by (apply Rmult_le_pos; [apply Rmult_le_pos |]; lra).
      lra.
Qed.
