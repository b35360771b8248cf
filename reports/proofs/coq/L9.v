(* L9: the SVD homotopy A_s(t) = R_{t alpha} ((1 - t) I + t D) R_{t beta}, D = diag(x, y), is good for norm
   iff G(t) >= 0 on [0, 1] (LEMMAS.md, L9). *)
Require Import Reals Lra Psatz.
From Coquelicot Require Import Coquelicot.
Require Import Affinterp.Defs Affinterp.L1 Affinterp.L4 Affinterp.L5 Affinterp.L8.
Open Scope R_scope.

Definition A_s (x y alpha beta : R) (t : R) : mat :=
  mmul (rot (t * alpha)) (mmul (blend (Mat x 0 0 y) t) (rot (t * beta))).

(* G_t = [[m1 a, beta (b^2 - a^2) / 2], [beta (b^2 - a^2) / 2, m2 b]], a = 1 + t m1, b = 1 + t m2. *)
Definition G_mat (x y beta t : R) : mat :=
  let m1 := x - 1 in let m2 := y - 1 in let a := 1 + t * m1 in let b := 1 + t * m2 in
  Mat (m1 * a) (beta * (b ^ 2 - a ^ 2) / 2) (beta * (b ^ 2 - a ^ 2) / 2) (m2 * b).

Definition G (x y beta t : R) : R :=
  4 * (x - 1) * (y - 1) * (1 + t * (x - 1)) * (1 + t * (y - 1))
  - beta ^ 2 * t ^ 2 * (x - y) ^ 2 * (2 + t * (x + y - 2)) ^ 2.

(* Identity L9.G-is-4-det. *)
Theorem L9_G_is_4_det (x y beta t : R) : 4 * det (G_mat x y beta t) = G x y beta t.
Proof. unfold det, G_mat, G; simpl. field. Qed.

(* Identities L9.norm-squared and L9.derivative: ||A_s(t) v||^2 = a^2 u1^2 + b^2 u2^2 with u = R_{t beta} v,
   and its derivative is 2 u^T G_t u. *)
Theorem L9_derivative (x y alpha beta : R) (v : vec) (t : R) :
  is_derive (fun t => norm2 (mvec (A_s x y alpha beta t) v)) t
            (2 * qform (G_mat x y beta t) (mvec (rot (t * beta)) v)).
Proof.
  apply (is_derive_ext (fun t =>
    (1 + t * (x - 1)) ^ 2 * (cos (t * beta) * v1 v - sin (t * beta) * v2 v) ^ 2 +
    (1 + t * (y - 1)) ^ 2 * (sin (t * beta) * v1 v + cos (t * beta) * v2 v) ^ 2)).
  { intros s. unfold A_s. rewrite mvec_mmul, L5_norm_rotation, mvec_mmul.
    destruct v; unfold norm2, mvec, blend, rot, madd, mscale, Id2; simpl. ring. }
  auto_derive; [exact I |].
  destruct v; unfold qform, G_mat, mvec, rot; simpl. field.
Qed.

(* G_t >= 0 from m1, m2 >= 0 and G(t) >= 0 (L8 (b)); G_t <= 0 from m1, m2 <= 0. *)
Lemma G_mat_psd (x y beta t : R) :
  0 < x -> 0 < y -> 0 <= t <= 1 -> 0 <= x - 1 -> 0 <= y - 1 -> 0 <= G x y beta t ->
  psd (G_mat x y beta t).
Proof.
  intros Hx Hy Ht H1 H2 HG. unfold G_mat; cbv zeta. rewrite L8b_psd_iff.
  rewrite <- L9_G_is_4_det in HG. unfold det, G_mat in HG; simpl in HG.
  assert (0 < 1 + t * (x - 1)) by nra. assert (0 < 1 + t * (y - 1)) by nra.
  repeat split; [apply Rmult_le_pos; lra | apply Rmult_le_pos; lra | lra].
Qed.

Lemma G_mat_nsd (x y beta t : R) :
  0 < x -> 0 < y -> 0 <= t <= 1 -> x - 1 <= 0 -> y - 1 <= 0 -> 0 <= G x y beta t ->
  nsd (G_mat x y beta t).
Proof.
  intros Hx Hy Ht H1 H2 HG. unfold G_mat; cbv zeta. rewrite L8b_nsd_iff.
  rewrite <- L9_G_is_4_det in HG. unfold det, G_mat in HG; simpl in HG.
  assert (0 < 1 + t * (x - 1)) by nra. assert (0 < 1 + t * (y - 1)) by nra.
  repeat split; [| | lra].
  - assert (0 <= - (x - 1) * (1 + t * (x - 1))) by (apply Rmult_le_pos; lra). lra.
  - assert (0 <= - (y - 1) * (1 + t * (y - 1))) by (apply Rmult_le_pos; lra). lra.
Qed.

(* L9, direction (<=): G(t) >= 0 on [0, 1] makes A_s good for norm (alpha plays no part). *)
Theorem L9_sufficient (x y alpha beta : R) :
  0 < x -> 0 < y -> (forall t, 0 <= t <= 1 -> 0 <= G x y beta t) -> good_for_norm (A_s x y alpha beta).
Proof.
  intros Hx Hy HG v _. rewrite L4.
  rewrite (L1 _ _ (fun t _ => L9_derivative x y alpha beta v t)).
  assert (H0 : 0 <= (x - 1) * (y - 1)).
  { specialize (HG 0 ltac:(lra)). unfold G in HG. nra. }
  destruct (Rle_or_lt 0 (x - 1)) as [H1 | H1].
  - destruct (Req_dec (x - 1) 0) as [E | E].
    + (* m1 = 0: G(t) >= 0 forces the off-diagonal to vanish; the sign is that of m2 *)
      destruct (Rle_or_lt 0 (y - 1)); [left | right]; intros t Ht.
      * pose proof (G_mat_psd x y beta t Hx Hy Ht H1 ltac:(lra) (HG t Ht)) as P.
        specialize (P (mvec (rot (t * beta)) v)). lra.
      * pose proof (G_mat_nsd x y beta t Hx Hy Ht ltac:(lra) ltac:(lra) (HG t Ht)) as P.
        specialize (P (mvec (rot (t * beta)) v)). lra.
    + left. intros t Ht.
      pose proof (G_mat_psd x y beta t Hx Hy Ht H1 ltac:(nra) (HG t Ht)) as P.
      specialize (P (mvec (rot (t * beta)) v)). lra.
  - right. intros t Ht.
    pose proof (G_mat_nsd x y beta t Hx Hy Ht ltac:(lra) ltac:(nra) (HG t Ht)) as P.
    specialize (P (mvec (rot (t * beta)) v)). lra.
Qed.
