(* L12: the worst time of the SVD norm is t = 1 (LEMMAS.md, L12). G is L9's. *)
Require Import Reals Lra Psatz.
Require Import Affinterp.L9.
Open Scope R_scope.

(* Identity L12.condition-is-G1. *)
Theorem L12_condition_is_G1 (x y beta : R) :
  G x y beta 1 = 4 * x * y * (x - 1) * (y - 1) - beta ^ 2 * (x - y) ^ 2 * (x + y) ^ 2.
Proof. unfold G. ring. Qed.

(* C of the statement, with sigma = x + y - 2 and pi = (x - 1)(y - 1). *)
Definition C (s p t : R) : R :=
  s ^ 3 * (t ^ 3 + t ^ 2 + t) + s ^ 2 * p * (t ^ 3 + t ^ 2) + s ^ 2 * (t ^ 3 + 5 * t ^ 2 + 5 * t + 1)
  + 4 * s * p * t ^ 2 + 4 * s * (t ^ 2 + 2 * t + 1) + 4 * t + 4.

(* C >= 0 for t in [0, 1] when pi > 0, sigma > -2 and sigma^2 > 4 pi (identities L12.C-affine-in-pi and
   L12.C-at-x-equals-y). *)
Lemma C_nonneg (s p t : R) : 0 < p -> -2 < s -> 4 * p < s ^ 2 -> 0 <= t <= 1 -> 0 <= C s p t.
Proof.
  intros Hp Hs Hd Ht.
  assert (0 <= t ^ 2) by (apply pow_le; lra). assert (0 <= t ^ 3) by (apply pow_le; lra).
  assert (0 <= s ^ 2) by apply pow2_ge_0.
  destruct (Rle_or_lt 0 s) as [Hs0 | Hs0].
  - unfold C.
    assert (0 <= s ^ 3 * (t ^ 3 + t ^ 2 + t)) by (apply Rmult_le_pos; [apply pow_le | nra]; lra).
    assert (0 <= s ^ 2 * p * (t ^ 3 + t ^ 2)) by (apply Rmult_le_pos; [| nra]; nra).
    assert (0 <= s ^ 2 * (t ^ 3 + 5 * t ^ 2 + 5 * t + 1)) by (apply Rmult_le_pos; [| nra]; nra).
    assert (0 <= 4 * s * p * t ^ 2) by (apply Rmult_le_pos; [| nra]; nra).
    assert (0 <= 4 * s * (t ^ 2 + 2 * t + 1)) by (apply Rmult_le_pos; nra).
    lra.
  - assert (Haff : C s p t = C s (s ^ 2 / 4) t + (p - s ^ 2 / 4) * (s * t ^ 2 * (s * (1 + t) + 4)))
      by (unfold C; field).
    assert (Hq : C s (s ^ 2 / 4) t = (1 + t) * (2 + t * s) ^ 2 * (2 + s) ^ 2 / 4) by (unfold C; field).
    assert (0 <= (1 + t) * (2 + t * s) ^ 2 * (2 + s) ^ 2 / 4).
    { unfold Rdiv. apply Rmult_le_pos; [| left; apply Rinv_0_lt_compat; lra].
      apply Rmult_le_pos; [apply Rmult_le_pos |]; [lra | apply pow2_ge_0 | apply pow2_ge_0]. }
    assert (0 <= (s ^ 2 / 4 - p) * (- s * t ^ 2 * (s * (1 + t) + 4))).
    { apply Rmult_le_pos; [lra |]. apply Rmult_le_pos; [apply Rmult_le_pos; lra | nra]. }
    rewrite Haff, Hq. nra.
Qed.

Theorem L12 (x y beta : R) :
  0 < x -> 0 < y ->
  ((forall t, 0 <= t <= 1 -> 0 <= G x y beta t) <->
   beta ^ 2 * (x - y) ^ 2 * (x + y) ^ 2 <= 4 * x * y * (x - 1) * (y - 1)).
Proof.
  intros Hx Hy. split.
  - intros H. specialize (H 1 ltac:(lra)). rewrite L12_condition_is_G1 in H. lra.
  - intros H1 t Ht.
    set (s := x + y - 2). set (p := (x - 1) * (y - 1)). set (B := beta ^ 2).
    assert (HB : 0 <= B) by (unfold B; nra).
    (* identities L12.svd-coordinates and L12.image *)
    assert (Hco : forall t, G x y beta t = 4 * p * (1 + t * s + t ^ 2 * p) - B * t ^ 2 * (s ^ 2 - 4 * p) * (2 + t * s) ^ 2)
      by (intros; unfold G, s, p, B; ring).
    assert (Hxy : 1 + s + p = x * y) by (unfold s, p; ring).
    assert (Hdisc : s ^ 2 - 4 * p = (x - y) ^ 2) by (unfold s, p; ring).
    assert (H2s : 2 + s = x + y) by (unfold s; ring).
    assert (HG1 : B * (x - y) ^ 2 * (x + y) ^ 2 <= 4 * p * (x * y)) by (unfold p, B; lra).
    rewrite Hco, Hdisc.
    assert (Hts : 0 <= t ^ 2 * (2 + t * s) ^ 2) by (apply Rmult_le_pos; apply pow2_ge_0).
    assert (HW : 0 < (x + y) ^ 2) by nra.
    assert (HBK0 : 0 <= B * (x - y) ^ 2) by (apply Rmult_le_pos; [lra | apply pow2_ge_0]).
    destruct (Rtotal_order p 0) as [Hp | [Hp | Hp]].
    + (* case 1: pi < 0 does not occur *)
      exfalso. assert (0 <= B * (x - y) ^ 2 * (x + y) ^ 2) by (apply Rmult_le_pos; lra).
      assert (0 < - p * (x * y)) by (apply Rmult_lt_0_compat; [lra | nra]). lra.
    + (* case 2: pi = 0, so B (x - y)^2 = 0 and G = 0 *)
      rewrite Hp in *.
      assert (E0 : B * (x - y) ^ 2 = 0).
      { assert (0 <= B * (x - y) ^ 2 * (x + y) ^ 2) by (apply Rmult_le_pos; lra).
        assert (B * (x - y) ^ 2 * (x + y) ^ 2 = 0) by lra.
        apply Rmult_integral in H0. destruct H0; [assumption | nra]. }
      replace (B * t ^ 2 * (x - y) ^ 2 * (2 + t * s) ^ 2) with (B * (x - y) ^ 2 * (t ^ 2 * (2 + t * s) ^ 2))
        by ring.
      rewrite E0. lra.
    + destruct (Req_dec x y) as [Exy | Exy].
      * (* case 3: x = y, G(t) = 4 pi (1 + t sigma + t^2 pi) *)
        assert (E3 : 1 + t * s + t ^ 2 * p = (1 + t * (x - 1)) ^ 2) by (unfold s, p; rewrite Exy; ring).
        rewrite E3, Exy. replace ((y - y) ^ 2) with 0 by ring.
        assert (0 <= (1 + t * (y - 1)) ^ 2) by apply pow2_ge_0. nra.
      * (* case 4: pi > 0, sigma^2 > 4 pi: G(t) (2 + sigma)^2 >= 4 pi (1 - t) C >= 0 (identity L12.C) *)
        assert (HK : 0 < (x - y) ^ 2) by (assert (x - y <> 0) by lra; nra).
        assert (HC : (1 - t) * C s p t =
                     (1 + t * s + t ^ 2 * p) * (x + y) ^ 2 - t ^ 2 * (2 + t * s) ^ 2 * (x * y))
          by (unfold C, s, p; ring).
        pose proof (C_nonneg s p t Hp ltac:(unfold s; lra) ltac:(lra) Ht) as HC0.
        assert (0 <= 4 * p * ((1 - t) * C s p t)) by (apply Rmult_le_pos; [lra | apply Rmult_le_pos; lra]).
        assert (Hmono : B * (x - y) ^ 2 * (x + y) ^ 2 * (t ^ 2 * (2 + t * s) ^ 2)
                        <= 4 * p * (x * y) * (t ^ 2 * (2 + t * s) ^ 2))
          by (apply Rmult_le_compat_r; assumption).
        apply (Rmult_le_reg_r ((x + y) ^ 2)); [exact HW |]. rewrite Rmult_0_l. nra.
Qed.
