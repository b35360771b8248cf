(* L14: 3D rotations leave det and the norm alone (LEMMAS.md, L14). R^t = e^{t theta K} for R = e^{theta K}, K the
   skew matrix of a unit axis k, is written in Rodrigues' closed form I + sin(t theta) K + (1 - cos(t theta)) K^2
   (as theory/local3/rotation3.hpp computes it). *)
Require Import Reals Lra Psatz.
Require Import Affinterp.Defs3 Affinterp.L15.
Open Scope R_scope.

Definition skew (k1 k2 k3 : R) : mat3 := Mat3 0 (- k3) k2 k3 0 (- k1) (- k2) k1 0.

(* K^2 = k k^T - |k|^2 I, and I + s K + a K^2, entry by entry. *)
Definition skew2 (k1 k2 k3 : R) : mat3 :=
  Mat3 (- k2 * k2 - k3 * k3) (k1 * k2) (k1 * k3)
       (k1 * k2) (- k1 * k1 - k3 * k3) (k2 * k3)
       (k1 * k3) (k2 * k3) (- k1 * k1 - k2 * k2).

Lemma skew2_square (k1 k2 k3 : R) : mmul3 (skew k1 k2 k3) (skew k1 k2 k3) = skew2 k1 k2 k3.
Proof. unfold mmul3, skew, skew2; cbn [a11 a12 a13 a21 a22 a23 a31 a32 a33]; f_equal; ring. Qed.

Definition rod (k1 k2 k3 s a : R) : mat3 :=
  Mat3 (1 + a * (- k2 * k2 - k3 * k3)) (- s * k3 + a * (k1 * k2)) (s * k2 + a * (k1 * k3))
       (s * k3 + a * (k1 * k2)) (1 + a * (- k1 * k1 - k3 * k3)) (- s * k1 + a * (k2 * k3))
       (- s * k2 + a * (k1 * k3)) (s * k1 + a * (k2 * k3)) (1 + a * (- k1 * k1 - k2 * k2)).

Lemma rod_is (k1 k2 k3 s a : R) :
  rod k1 k2 k3 s a = madd3 Id3 (madd3 (mscale3 s (skew k1 k2 k3)) (mscale3 a (mmul3 (skew k1 k2 k3) (skew k1 k2 k3)))).
Proof.
  rewrite skew2_square. unfold rod, madd3, mscale3, Id3, skew, skew2; cbn [a11 a12 a13 a21 a22 a23 a31 a32 a33].
  f_equal; ring.
Qed.

(* R^t for R = e^{theta K}. *)
Definition rpow (k1 k2 k3 theta t : R) : mat3 := rod k1 k2 k3 (sin (t * theta)) (1 - cos (t * theta)).

Definition rotation3 (O : mat3) : Prop := orthogonal3 O /\ det3 O = 1.

(* For any axis k, with m = |k|^2: (I + sK + aK^2)^T (I + sK + aK^2) = I + (2a - s^2 - a^2 m) K^2, the same for
   the product in the other order, and det(I + sK + aK^2) = (1 - a m)^2 + s^2 m. *)
Lemma rod_gram (k1 k2 k3 s a : R) :
  mmul3 (transpose3 (rod k1 k2 k3 s a)) (rod k1 k2 k3 s a) =
  madd3 Id3 (mscale3 (2 * a - s ^ 2 - a ^ 2 * (k1 ^ 2 + k2 ^ 2 + k3 ^ 2)) (skew2 k1 k2 k3)).
Proof.
  unfold rod, skew2, mmul3, madd3, mscale3, transpose3, Id3; cbn [a11 a12 a13 a21 a22 a23 a31 a32 a33].
  f_equal; ring.
Qed.

Lemma rod_gram' (k1 k2 k3 s a : R) :
  mmul3 (rod k1 k2 k3 s a) (transpose3 (rod k1 k2 k3 s a)) =
  madd3 Id3 (mscale3 (2 * a - s ^ 2 - a ^ 2 * (k1 ^ 2 + k2 ^ 2 + k3 ^ 2)) (skew2 k1 k2 k3)).
Proof.
  unfold rod, skew2, mmul3, madd3, mscale3, transpose3, Id3; cbn [a11 a12 a13 a21 a22 a23 a31 a32 a33].
  f_equal; ring.
Qed.

Lemma rod_det (k1 k2 k3 s a : R) :
  det3 (rod k1 k2 k3 s a) = (1 - a * (k1 ^ 2 + k2 ^ 2 + k3 ^ 2)) ^ 2 + s ^ 2 * (k1 ^ 2 + k2 ^ 2 + k3 ^ 2).
Proof. unfold rod, det3; cbn [a11 a12 a13 a21 a22 a23 a31 a32 a33]. ring. Qed.

Lemma add_zero_scale (M : mat3) : madd3 Id3 (mscale3 0 M) = Id3.
Proof. destruct M; unfold madd3, mscale3, Id3; simpl; f_equal; ring. Qed.

(* Every R^t is a rotation. *)
Theorem L14_rotation (k1 k2 k3 theta t : R) :
  k1 ^ 2 + k2 ^ 2 + k3 ^ 2 = 1 -> rotation3 (rpow k1 k2 k3 theta t).
Proof.
  intros Hk. unfold rpow. pose proof (sin2_cos2 (t * theta)) as Hsc. unfold Rsqr in Hsc.
  assert (Z : 2 * (1 - cos (t * theta)) - sin (t * theta) ^ 2
              - (1 - cos (t * theta)) ^ 2 * (k1 ^ 2 + k2 ^ 2 + k3 ^ 2) = 0) by (rewrite Hk; nra).
  split; [split |].
  - rewrite rod_gram, Z. apply add_zero_scale.
  - rewrite rod_gram', Z. apply add_zero_scale.
  - rewrite rod_det, Hk. nra.
Qed.

Theorem L14_at_0 (k1 k2 k3 theta : R) : rpow k1 k2 k3 theta 0 = Id3.
Proof.
  unfold rpow. rewrite Rmult_0_l, sin_0, cos_0. unfold rod, Id3. f_equal; ring.
Qed.

Theorem L14_at_1 (k1 k2 k3 theta : R) :
  rpow k1 k2 k3 theta 1 = rod k1 k2 k3 (sin theta) (1 - cos theta).
Proof. unfold rpow. rewrite Rmult_1_l. reflexivity. Qed.

Lemma det3_mmul3 (A B : mat3) : det3 (mmul3 A B) = det3 A * det3 B.
Proof. destruct A, B; unfold det3, mmul3; simpl; ring. Qed.

(* det(R^t B) = det B, det(B W^t) = det B, ||R^t B v|| = ||B v||. *)
Theorem L14_det_left (k1 k2 k3 theta t : R) (B : mat3) :
  k1 ^ 2 + k2 ^ 2 + k3 ^ 2 = 1 -> det3 (mmul3 (rpow k1 k2 k3 theta t) B) = det3 B.
Proof. intros Hk. rewrite det3_mmul3, (proj2 (L14_rotation k1 k2 k3 theta t Hk)). ring. Qed.

Theorem L14_det_right (k1 k2 k3 theta t : R) (B : mat3) :
  k1 ^ 2 + k2 ^ 2 + k3 ^ 2 = 1 -> det3 (mmul3 B (rpow k1 k2 k3 theta t)) = det3 B.
Proof. intros Hk. rewrite det3_mmul3, (proj2 (L14_rotation k1 k2 k3 theta t Hk)). ring. Qed.

Theorem L14_norm (k1 k2 k3 theta t : R) (B : mat3) (v : vec3) :
  k1 ^ 2 + k2 ^ 2 + k3 ^ 2 = 1 -> norm3 (mvec3 (mmul3 (rpow k1 k2 k3 theta t) B) v) = norm3 (mvec3 B v).
Proof.
  intros Hk. destruct (L14_rotation k1 k2 k3 theta t Hk) as [[HO _] _].
  unfold norm3. rewrite mvec3_mmul3, norm2_3_orthogonal by exact HO. reflexivity.
Qed.

(* The SVD homotopy's volume: det((1 - t) I + t diag(l1, l2, l3)) = prod (1 + t (l_i - 1)). *)
Theorem L14_svd_det (l1 l2 l3 t : R) :
  det3 (blend3 (diag3 l1 l2 l3) t) = (1 + t * (l1 - 1)) * (1 + t * (l2 - 1)) * (1 + t * (l3 - 1)).
Proof. unfold det3, blend3, diag3, madd3, mscale3, Id3; simpl; ring. Qed.
