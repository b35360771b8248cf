(* L22: the singular values of A = R S are the eigenvalues of S, 2x2 (LEMMAS.md, L22). As in L13, the
   eigenvalues of a symmetric matrix G are the reals with sum tr G and product det G, and the singular values of
   A are the non-negative s1, s2 whose squares are the eigenvalues of A^T A. *)
Require Import Reals Lra Psatz.
Require Import Affinterp.Defs Affinterp.L13.
Open Scope R_scope.

(* A^T A = S^T (R^T R) S = S^2 for a rotation R and a symmetric S. *)
Theorem L22_gram (Q : mat) (x h y : R) :
  is_rotation Q ->
  mmul (transpose (mmul Q (Mat x h h y))) (mmul Q (Mat x h h y)) = mmul (Mat x h h y) (Mat x h h y).
Proof.
  intros [HR _]. destruct Q as [r11 r12 r21 r22].
  unfold mmul, transpose, Id2 in *; simpl in *. injection HR as E11 E12 E21 E22.
  f_equal.
  - transitivity (x * x * (r11 * r11 + r21 * r21) + 2 * x * h * (r11 * r12 + r21 * r22)
      + h * h * (r12 * r12 + r22 * r22)); [ring | rewrite E11, E12, E22; ring].
  - transitivity (x * h * (r11 * r11 + r21 * r21) + (x * y + h * h) * (r11 * r12 + r21 * r22)
      + h * y * (r12 * r12 + r22 * r22)); [ring | rewrite E11, E12, E22; ring].
  - transitivity (x * h * (r11 * r11 + r21 * r21) + (x * y + h * h) * (r11 * r12 + r21 * r22)
      + h * y * (r12 * r12 + r22 * r22)); [ring | rewrite E11, E12, E22; ring].
  - transitivity (h * h * (r11 * r11 + r21 * r21) + 2 * h * y * (r11 * r12 + r21 * r22)
      + y * y * (r12 * r12 + r22 * r22)); [ring | rewrite E11, E12, E22; ring].
Qed.

(* For a rotation R and S = [[x, h], [h, y]] positive definite with eigenvalues l1, l2 (L13): non-negative
   s1, s2 are the singular values of A = R S (s1^2, s2^2 the eigenvalues of A^T A, which is symmetric) iff
   they are l1, l2 in some order. *)
Theorem L22 (Q : mat) (x h y l1 l2 s1 s2 : R) :
  is_rotation Q -> pd (Mat x h h y) -> l1 + l2 = x + y -> l1 * l2 = x * y - h * h ->
  0 <= s1 -> 0 <= s2 ->
  let G := mmul (transpose (mmul Q (Mat x h h y))) (mmul Q (Mat x h h y)) in
  symmetric G /\
  (s1 ^ 2 + s2 ^ 2 = tr G /\ s1 ^ 2 * s2 ^ 2 = det G <-> (s1 = l1 /\ s2 = l2) \/ (s1 = l2 /\ s2 = l1)).
Proof.
  intros HR Hpd Hsum Hprod Hs1 Hs2 G.
  destruct (proj1 (L13_pd x h y l1 l2 Hsum Hprod) Hpd) as [Hl1 Hl2].
  unfold G. rewrite (L22_gram Q x h y HR). unfold symmetric, tr, det, mmul; cbn [m11 m12 m21 m22].
  assert (Ht : x * x + h * h + (h * h + y * y) = l1 ^ 2 + l2 ^ 2).
  { transitivity ((x + y) ^ 2 - 2 * (x * y - h * h)); [ring | rewrite <- Hsum, <- Hprod; ring]. }
  assert (Hd : (x * x + h * h) * (h * h + y * y) - (x * h + h * y) * (h * x + y * h) = l1 ^ 2 * l2 ^ 2).
  { transitivity ((x * y - h * h) ^ 2); [ring | rewrite <- Hprod; ring]. }
  rewrite Ht, Hd. split; [ring |]. split.
  - intros [E1 E2].
    assert (Hp : s1 * s2 = l1 * l2).
    { assert (0 <= s1 * s2) by nra. assert (0 < l1 * l2) by nra.
      assert (Hsq : (s1 * s2) ^ 2 = (l1 * l2) ^ 2) by (rewrite !Rpow_mult_distr; exact E2).
      nra. }
    assert (Hs : s1 + s2 = l1 + l2).
    { assert (Hsq : (s1 + s2) ^ 2 = (l1 + l2) ^ 2).
      { transitivity (s1 ^ 2 + s2 ^ 2 + 2 * (s1 * s2)); [ring | rewrite E1, Hp; ring]. }
      nra. }
    assert (Hroot : (s1 - l1) * (s1 - l2) = 0).
    { transitivity (s1 * s1 - s1 * (l1 + l2) + l1 * l2); [ring | rewrite <- Hs, <- Hp; ring]. }
    destruct (Rmult_integral _ _ Hroot) as [H | H]; [left | right]; lra.
  - intros [[-> ->] | [-> ->]]; split; ring.
Qed.
