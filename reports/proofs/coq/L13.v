(* L13: the spectral theorem for 2x2 symmetric matrices (LEMMAS.md, L13). A rotation is a matrix Q with
   Q^T Q = I and det Q = 1. *)
Require Import Reals Lra Psatz.
Require Import Affinterp.Defs.
Open Scope R_scope.

Definition is_rotation (Q : mat) : Prop := mmul (transpose Q) Q = Id2 /\ det Q = 1.
Definition diag (l1 l2 : R) : mat := Mat l1 0 0 l2.
Definition pd (S : mat) : Prop := forall v, v <> Vec 0 0 -> 0 < qform S v.

(* Identity L13.discriminant: (tr S)^2 - 4 det S = (x - y)^2 + 4 h^2 >= 0, so the characteristic polynomial
   z^2 - (tr S) z + det S has real roots l1, l2 with sum tr S and product det S. *)
Theorem L13_eigenvalues_real (x h y : R) :
  exists l1 l2, l1 + l2 = x + y /\ l1 * l2 = x * y - h * h.
Proof.
  set (d := sqrt ((x - y) ^ 2 + 4 * h ^ 2)).
  assert (Hd : d * d = (x - y) ^ 2 + 4 * h ^ 2) by (unfold d; apply sqrt_sqrt; pose proof (pow2_ge_0 (x - y)); pose proof (pow2_ge_0 h); lra).
  exists ((x + y + d) / 2), ((x + y - d) / 2). split; [field | nra].
Qed.

(* Q diag(l1, l2) Q^T for Q = [[c, -s], [s, c]] is [[l1 c^2 + l2 s^2, (l1 - l2) c s], [..., l1 s^2 + l2 c^2]]. *)
Lemma conjugate_diag (c s l1 l2 : R) :
  mmul (Mat c (- s) s c) (mmul (diag l1 l2) (transpose (Mat c (- s) s c))) =
  Mat (l1 * c ^ 2 + l2 * s ^ 2) ((l1 - l2) * c * s) ((l1 - l2) * c * s) (l1 * s ^ 2 + l2 * c ^ 2).
Proof. unfold mmul, diag, transpose; simpl; f_equal; ring. Qed.

Lemma rotation_cs (c s : R) : c ^ 2 + s ^ 2 = 1 -> is_rotation (Mat c (- s) s c).
Proof.
  intros E. unfold is_rotation, mmul, transpose, det, Id2; simpl. split; [f_equal | ]; nra.
Qed.

(* Any reals l1, l2 with l1 + l2 = tr S and l1 l2 = det S are S's eigenvalues: S = Q diag(l1, l2) Q^T for a
   rotation Q (its first column the unit eigenvector along (h, l1 - x), or Q = I when that is 0). *)
Theorem L13_spectral (x h y l1 l2 : R) :
  l1 + l2 = x + y -> l1 * l2 = x * y - h * h ->
  exists Q, is_rotation Q /\ Mat x h h y = mmul Q (mmul (diag l1 l2) (transpose Q)).
Proof.
  intros Hsum Hprod.
  assert (Hl2 : l2 = x + y - l1) by lra. subst l2.
  assert (Hchar : (l1 - x) * (l1 - y) = h ^ 2).
  { replace ((l1 - x) * (l1 - y)) with (h ^ 2 - (l1 * (x + y - l1) - (x * y - h * h))) by ring.
    rewrite Hprod. ring. }
  set (r2 := h ^ 2 + (l1 - x) ^ 2).
  destruct (Req_dec r2 0) as [Hr | Hr].
  - pose proof (pow2_ge_0 h). pose proof (pow2_ge_0 (l1 - x)). unfold r2 in Hr.
    assert (Hh2 : h ^ 2 = 0) by lra. assert (Hl12 : (l1 - x) ^ 2 = 0) by lra.
    rewrite <- Rsqr_pow2 in Hh2, Hl12. apply Rsqr_eq_0 in Hh2. apply Rsqr_eq_0 in Hl12.
    assert (l1 = x) by lra. subst.
    exists Id2. split; [unfold is_rotation, mmul, transpose, det, Id2; simpl; split; [f_equal |] ; ring |].
    unfold mmul, diag, transpose, Id2; simpl; f_equal; ring.
  - assert (Hr0 : 0 < r2) by (pose proof (pow2_ge_0 h); pose proof (pow2_ge_0 (l1 - x)); unfold r2 in *; lra).
    set (r := sqrt r2). assert (Hrr : r * r = r2) by (unfold r; apply sqrt_sqrt; lra).
    assert (Hrp : 0 < r) by (unfold r; apply sqrt_lt_R0; lra).
    set (c := h / r). set (s := (l1 - x) / r).
    assert (Hc2 : c ^ 2 = h ^ 2 / r2) by (unfold c; rewrite <- Hrr; field; lra).
    assert (Hs2 : s ^ 2 = (l1 - x) ^ 2 / r2) by (unfold s; rewrite <- Hrr; field; lra).
    assert (Hcs : c * s = h * (l1 - x) / r2) by (unfold c, s; rewrite <- Hrr; field; lra).
    exists (Mat c (- s) s c). split.
    + apply rotation_cs. rewrite Hc2, Hs2. unfold r2. field. fold r2. lra.
    + rewrite conjugate_diag.
      replace ((l1 - (x + y - l1)) * c * s) with ((l1 - (x + y - l1)) * (c * s)) by ring.
      rewrite Hc2, Hs2, Hcs.
      assert (N11 : l1 * h ^ 2 + (x + y - l1) * (l1 - x) ^ 2 = x * r2).
      { unfold r2. transitivity (x * (h ^ 2 + (l1 - x) ^ 2) - (l1 - x) * ((l1 - x) * (l1 - y) - h ^ 2));
          [ring | rewrite Hchar; ring]. }
      assert (N12 : (l1 - (x + y - l1)) * (h * (l1 - x)) = h * r2).
      { unfold r2. transitivity (h * (h ^ 2 + (l1 - x) ^ 2) + h * ((l1 - x) * (l1 - y) - h ^ 2));
          [ring | rewrite Hchar; ring]. }
      assert (N22 : l1 * (l1 - x) ^ 2 + (x + y - l1) * h ^ 2 = y * r2).
      { unfold r2. transitivity (y * (h ^ 2 + (l1 - x) ^ 2) + (l1 - x) * ((l1 - x) * (l1 - y) - h ^ 2));
          [ring | rewrite Hchar; ring]. }
      f_equal; apply (Rmult_eq_reg_r r2); try lra.
      * rewrite <- N11. field. lra.
      * rewrite <- N12. field. lra.
      * rewrite <- N12. field. lra.
      * rewrite <- N22. field. lra.
Qed.

(* S > 0 iff l1, l2 > 0, for the l1, l2 above. *)
Theorem L13_pd (x h y l1 l2 : R) :
  l1 + l2 = x + y -> l1 * l2 = x * y - h * h -> (pd (Mat x h h y) <-> 0 < l1 /\ 0 < l2).
Proof.
  intros Hsum Hprod. split.
  - intros H. pose proof (H (Vec 1 0) ltac:(intros E; injection E; lra)) as Hx.
    pose proof (H (Vec (- h) x)) as Hv. unfold qform in Hx, Hv; simpl in Hx, Hv.
    assert (0 < x) by lra.
    assert (0 < x * (x * y - h * h)).
    { replace (x * (x * y - h * h)) with (- h * (x * - h + h * x) + x * (h * - h + y * x)) by ring.
      apply Hv. intros E; injection E; lra. }
    assert (Hd : 0 < x * y - h * h).
    { destruct (Rle_or_lt (x * y - h * h) 0); [| assumption]. nra. }
    pose proof (H (Vec 0 1) ltac:(intros E; injection E; lra)) as Hy. unfold qform in Hy; simpl in Hy.
    assert (0 < l1 * l2) by lra.
    destruct (Rle_or_lt l1 0); [exfalso; nra | split; [assumption | nra]].
  - intros [H1 H2] v Hv. destruct v as [a b].
    assert (Hab : 0 < a ^ 2 + b ^ 2) by (destruct (Req_dec a 0), (Req_dec b 0); subst; [congruence | nra ..]).
    assert (0 < x) by nra.
    assert (E : x * qform (Mat x h h y) (Vec a b) = (x * a + h * b) ^ 2 + (x * y - h * h) * b ^ 2)
      by (unfold qform; simpl; ring).
    assert (0 < x * qform (Mat x h h y) (Vec a b)).
    { rewrite E. destruct (Req_dec b 0) as [-> | Hb].
      - assert (a <> 0) by (intros ->; lra).
        assert (x * a <> 0) by (apply Rmult_integral_contrapositive_currified; lra).
        replace ((x * a + h * 0) ^ 2 + (x * y - h * h) * 0 ^ 2) with (Rsqr (x * a)) by (unfold Rsqr; ring).
        apply Rsqr_pos_lt. assumption.
      - assert (0 < b ^ 2) by (rewrite <- Rsqr_pow2; apply Rsqr_pos_lt; exact Hb).
        assert (0 < (x * y - h * h) * b ^ 2) by (apply Rmult_lt_0_compat; nra).
        pose proof (pow2_ge_0 (x * a + h * b)). lra. }
    apply (Rmult_lt_reg_l x); [assumption |]. lra.
Qed.

(* l1, l2 are the roots of the characteristic polynomial: det(S - l I) = 0 (Viete). *)
Theorem L13_roots (x h y l1 l2 : R) :
  l1 + l2 = x + y -> l1 * l2 = x * y - h * h ->
  det (madd (Mat x h h y) (mscale (- l1) Id2)) = 0 /\ det (madd (Mat x h h y) (mscale (- l2) Id2)) = 0.
Proof.
  intros Hs Hp. assert (Hl2 : l2 = x + y - l1) by lra. subst l2.
  unfold det, madd, mscale, Id2; simpl. split.
  - transitivity (- (l1 * (x + y - l1) - (x * y - h * h))); [ring | rewrite Hp; ring].
  - transitivity (- (l1 * (x + y - l1) - (x * y - h * h))); [ring | rewrite Hp; ring].
Qed.
