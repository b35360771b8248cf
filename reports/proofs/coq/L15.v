(* L15: the eigenbasis, and the cone of per-axis slopes (LEMMAS.md, L15). *)
Require Import Reals Lra Psatz.
Require Import Affinterp.Defs3.
Open Scope R_scope.

(* (a) S = O diag(l1, l2, l3) O^T with O orthogonal; S^t = O diag(l1^t, l2^t, l3^t) O^T. *)
Lemma mvec3_mmul3 (A B : mat3) (v : vec3) : mvec3 (mmul3 A B) v = mvec3 A (mvec3 B v).
Proof. destruct A, B, v; unfold mvec3, mmul3; simpl; f_equal; ring. Qed.

Lemma norm2_3_orthogonal (O : mat3) (w : vec3) :
  mmul3 (transpose3 O) O = Id3 -> norm2_3 (mvec3 O w) = norm2_3 w.
Proof.
  intros H. destruct O as [o11 o12 o13 o21 o22 o23 o31 o32 o33], w as [w1 w2 w3].
  unfold mmul3, transpose3, Id3 in H; simpl in H. injection H as E11 E12 E13 E21 E22 E23 E31 E32 E33.
  unfold norm2_3, mvec3; simpl.
  transitivity (w1 * w1 * (o11 * o11 + o21 * o21 + o31 * o31) + w2 * w2 * (o12 * o12 + o22 * o22 + o32 * o32)
    + w3 * w3 * (o13 * o13 + o23 * o23 + o33 * o33) + 2 * w1 * w2 * (o11 * o12 + o21 * o22 + o31 * o32)
    + 2 * w1 * w3 * (o11 * o13 + o21 * o23 + o31 * o33) + 2 * w2 * w3 * (o12 * o13 + o22 * o23 + o32 * o33));
    [ring | rewrite E11, E12, E13, E22, E23, E33; ring].
Qed.

(* ||O D O^T v|| = ||D u|| with u = O^T v, for every matrix D. *)
Lemma conjugate_norm (O D : mat3) (v : vec3) :
  orthogonal3 O -> norm3 (mvec3 (mmul3 O (mmul3 D (transpose3 O))) v) = norm3 (mvec3 D (mvec3 (transpose3 O) v)).
Proof.
  intros [H _]. unfold norm3. rewrite !mvec3_mmul3, norm2_3_orthogonal by exact H. reflexivity.
Qed.

Lemma mmul3_madd3_l (A B C : mat3) : mmul3 A (madd3 B C) = madd3 (mmul3 A B) (mmul3 A C).
Proof. destruct A, B, C; unfold mmul3, madd3; simpl; f_equal; ring. Qed.
Lemma mmul3_madd3_r (A B C : mat3) : mmul3 (madd3 A B) C = madd3 (mmul3 A C) (mmul3 B C).
Proof. destruct A, B, C; unfold mmul3, madd3; simpl; f_equal; ring. Qed.
Lemma mmul3_scale_l (k : R) (A B : mat3) : mmul3 (mscale3 k A) B = mscale3 k (mmul3 A B).
Proof. destruct A, B; unfold mmul3, mscale3; simpl; f_equal; ring. Qed.
Lemma mmul3_scale_r (k : R) (A B : mat3) : mmul3 A (mscale3 k B) = mscale3 k (mmul3 A B).
Proof. destruct A, B; unfold mmul3, mscale3; simpl; f_equal; ring. Qed.
Lemma mmul3_Id_l (A : mat3) : mmul3 Id3 A = A.
Proof. destruct A; unfold mmul3, Id3; simpl; f_equal; ring. Qed.
Lemma blend3_conjugate (O D : mat3) (t : R) :
  mmul3 O (mmul3 (blend3 D t) (transpose3 O)) =
  madd3 (mscale3 (1 - t) (mmul3 O (transpose3 O))) (mscale3 t (mmul3 O (mmul3 D (transpose3 O)))).
Proof.
  unfold blend3. rewrite mmul3_madd3_r, mmul3_madd3_l, !mmul3_scale_l, !mmul3_scale_r, mmul3_Id_l. reflexivity.
Qed.

(* ||((1 - t) I + t S) v|| = ||((1 - t) I + t diag(l)) u|| with u = O^T v. *)
Theorem L15a_polar (O : mat3) (l1 l2 l3 t : R) (v : vec3) :
  orthogonal3 O ->
  let S := mmul3 O (mmul3 (diag3 l1 l2 l3) (transpose3 O)) in
  norm3 (mvec3 (blend3 S t) v) = norm3 (mvec3 (blend3 (diag3 l1 l2 l3) t) (mvec3 (transpose3 O) v)).
Proof.
  intros HO S. rewrite <- conjugate_norm by exact HO.
  rewrite (blend3_conjugate O (diag3 l1 l2 l3) t). destruct HO as [_ HO]. rewrite HO. reflexivity.
Qed.

(* ||S^t v|| = ||diag(l_i^t) u|| with u = O^T v. *)
Theorem L15a_exp (O : mat3) (l1 l2 l3 t : R) (v : vec3) :
  orthogonal3 O ->
  let St := mmul3 O (mmul3 (diag3 (Rpower l1 t) (Rpower l2 t) (Rpower l3 t)) (transpose3 O)) in
  norm3 (mvec3 St v) = norm3 (mvec3 (diag3 (Rpower l1 t) (Rpower l2 t) (Rpower l3 t)) (mvec3 (transpose3 O) v)).
Proof. intros HO St. apply conjugate_norm. exact HO. Qed.

(* u = O^T v ranges over R^3 as v does. *)
Theorem L15a_onto (O : mat3) : orthogonal3 O -> forall u, exists v, mvec3 (transpose3 O) v = u.
Proof.
  intros [HO _] u. exists (mvec3 O u). rewrite <- mvec3_mmul3, HO.
  destruct u; unfold mvec3, Id3; simpl; f_equal; ring.
Qed.

Definition axis (i : nat) : Prop := (1 <= i <= 3)%nat.

(* a_i b_i > 0 or a_i = b_i = 0 for every axis. *)
Definition same_signs (a b : nat -> R) : Prop :=
  forall i, axis i -> a i * b i > 0 \/ (a i = 0 /\ b i = 0).

Definition wsum (w a : nat -> R) : R := w 1%nat * a 1%nat + w 2%nat * a 2%nat + w 3%nat * a 3%nat.

Definition cone_meets (a b : nat -> R) : Prop :=
  exists w : nat -> R, (forall i, axis i -> 0 <= w i) /\ wsum w a < 0 < wsum w b.

Definition mixed_pair (a b : nat -> R) : Prop :=
  exists i j, axis i /\ axis j /\ a i > 0 /\ a j < 0 /\ a i * b j - a j * b i > 0.

Lemma sign_pos (x y : R) : x * y > 0 \/ (x = 0 /\ y = 0) -> 0 < x -> 0 < y.
Proof. intros [H | [H _]] Hx; [nra | lra]. Qed.
Lemma sign_neg (x y : R) : x * y > 0 \/ (x = 0 /\ y = 0) -> x < 0 -> y < 0.
Proof. intros [H | [H _]] Hx; [nra | lra]. Qed.
Lemma sign_zero (x y : R) : x * y > 0 \/ (x = 0 /\ y = 0) -> x = 0 -> y = 0.
Proof. intros [H | [_ H]] Hx; [subst; lra | exact H]. Qed.

(* (<=): w_i = 1, w_j = r, w_k = 0 with r strictly between -a_i/a_j and -b_i/b_j. *)
Lemma pair_gives_cone (ai bi aj bj : R) :
  0 < ai -> 0 < bi -> aj < 0 -> bj < 0 -> ai * bj - aj * bi > 0 ->
  exists r, 0 <= r /\ ai + r * aj < 0 < bi + r * bj.
Proof.
  intros Hai Hbi Haj Hbj Hd.
  set (r1 := - ai / aj). set (r2 := - bi / bj).
  assert (Hr1 : r1 * aj = - ai) by (unfold r1; field; lra).
  assert (Hr2 : r2 * bj = - bi) by (unfold r2; field; lra).
  assert (0 < r1) by nra.
  assert (Hlt : r1 < r2).
  { apply (Rmult_lt_reg_r (aj * bj)); [nra |].
    replace (r1 * (aj * bj)) with (- ai * bj) by (rewrite <- Hr1; ring).
    replace (r2 * (aj * bj)) with (- bi * aj) by (rewrite <- Hr2; ring). lra. }
  exists ((r1 + r2) / 2). split; [lra | split; nra].
Qed.

Theorem L15b (a b : nat -> R) : same_signs a b -> (cone_meets a b <-> mixed_pair a b).
Proof.
  intros Hs. unfold same_signs, axis in Hs.
  pose proof (Hs 1%nat ltac:(lia)) as S1. pose proof (Hs 2%nat ltac:(lia)) as S2.
  pose proof (Hs 3%nat ltac:(lia)) as S3.
  split.
  - intros [w [Hw [HA HB]]]. unfold wsum in HA, HB. unfold axis in Hw.
    pose proof (Hw 1%nat ltac:(lia)) as W1. pose proof (Hw 2%nat ltac:(lia)) as W2. pose proof (Hw 3%nat ltac:(lia)) as W3.
    destruct (Classical_Prop.classic (mixed_pair a b)) as [P | NP]; [exact P | exfalso].
    assert (N : forall i j, axis i -> axis j -> a i > 0 -> a j < 0 -> a i * b j - a j * b i <= 0).
    { intros i j Hi Hj Hai Haj. apply Rnot_lt_le. intros Hd. apply NP. exists i, j. exact (conj Hi (conj Hj (conj Hai (conj Haj Hd)))). }
    unfold axis in N.
    pose proof (N 1%nat 2%nat ltac:(lia) ltac:(lia)) as N12. pose proof (N 1%nat 3%nat ltac:(lia) ltac:(lia)) as N13.
    pose proof (N 2%nat 1%nat ltac:(lia) ltac:(lia)) as N21. pose proof (N 2%nat 3%nat ltac:(lia) ltac:(lia)) as N23.
    pose proof (N 3%nat 1%nat ltac:(lia) ltac:(lia)) as N31. pose proof (N 3%nat 2%nat ltac:(lia) ltac:(lia)) as N32.
    clear N NP Hw Hs.
    set (a1 := a 1%nat) in *. set (a2 := a 2%nat) in *. set (a3 := a 3%nat) in *.
    set (b1 := b 1%nat) in *. set (b2 := b 2%nat) in *. set (b3 := b 3%nat) in *.
    set (w1 := w 1%nat) in *. set (w2 := w 2%nat) in *. set (w3 := w 3%nat) in *.
    clearbody a1 a2 a3 b1 b2 b3 w1 w2 w3.
    destruct (total_order_T a1 0) as [[H1 | H1] | H1];
    [pose proof (sign_neg _ _ S1 H1) | pose proof (sign_zero _ _ S1 H1) | pose proof (sign_pos _ _ S1 H1)];
    (destruct (total_order_T a2 0) as [[H2 | H2] | H2];
    [pose proof (sign_neg _ _ S2 H2) | pose proof (sign_zero _ _ S2 H2) | pose proof (sign_pos _ _ S2 H2)]);
    (destruct (total_order_T a3 0) as [[H3 | H3] | H3];
    [pose proof (sign_neg _ _ S3 H3) | pose proof (sign_zero _ _ S3 H3) | pose proof (sign_pos _ _ S3 H3)]);
    clear S1 S2 S3; try subst;
    repeat match goal with
      | H : ?x > 0 -> ?y < 0 -> _ |- _ => first [specialize (H ltac:(lra) ltac:(lra)) | clear H]
    end; nra.
  - intros [i [j [Hi [Hj [Hai [Haj Hd]]]]]].
    assert (Hbi : 0 < b i) by (apply (sign_pos (a i)); auto).
    assert (Hbj : b j < 0) by (apply (sign_neg (a j)); auto).
    destruct (pair_gives_cone (a i) (b i) (a j) (b j) Hai Hbi Haj Hbj Hd) as [r [Hr [HA HB]]].
    exists (fun k => if Nat.eq_dec k i then 1 else if Nat.eq_dec k j then r else 0).
    split.
    + intros k _. destruct (Nat.eq_dec k i); [lra | destruct (Nat.eq_dec k j); lra].
    + unfold axis in Hi, Hj. unfold wsum.
      assert (i <> j) by (intros ->; lra).
      destruct (Nat.eq_dec 1 i), (Nat.eq_dec 2 i), (Nat.eq_dec 3 i), (Nat.eq_dec 1 j), (Nat.eq_dec 2 j),
        (Nat.eq_dec 3 j); subst; try lia; lra.
Qed.
