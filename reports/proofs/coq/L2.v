(* L2: an affine derivative is read at t = 0 and t = 1; positivity of the area (LEMMAS.md, L2). *)
Require Import Reals Lra Psatz FunctionalExtensionality.
From Coquelicot Require Import Coquelicot.
Require Import Affinterp.Defs Affinterp.L1.
Open Scope R_scope.

(* "g0 and g1 are not of opposite strict signs". *)
Definition not_opposite (g0 g1 : R) : Prop := ~ (g0 < 0 /\ 0 < g1) /\ ~ (g0 > 0 /\ 0 > g1).

(* (a) det((1 - t) I + t B) = 1 + (tr B - 2) t + (1 - tr B + det B) t^2, with derivative
   (tr B - 2) + 2 (1 - tr B + det B) t: tr B - 2 at t = 0 and 2 det B - tr B at t = 1. *)
Theorem L2a_det_of_blend (B : mat) (t : R) :
  det (blend B t) = 1 + (tr B - 2) * t + (1 - tr B + det B) * t ^ 2.
Proof. destruct B; unfold det, blend, tr, madd, mscale, Id2; simpl; ring. Qed.

Definition det_blend_derivative (B : mat) (t : R) : R := (tr B - 2) + 2 * (1 - tr B + det B) * t.

Theorem L2a_derivative (B : mat) (t : R) :
  is_derive (fun t => det (blend B t)) t (det_blend_derivative B t).
Proof.
  apply (is_derive_ext (fun t => 1 + (tr B - 2) * t + (1 - tr B + det B) * t ^ 2)).
  { intros s. symmetry. apply L2a_det_of_blend. }
  unfold det_blend_derivative. auto_derive; [exact I | ring].
Qed.

Theorem L2a_derivative_at_ends (B : mat) :
  det_blend_derivative B 0 = tr B - 2 /\ det_blend_derivative B 1 = 2 * det B - tr B.
Proof. unfold det_blend_derivative; split; ring. Qed.

(* (b) An affine g keeps one sign on [0, 1] iff g(0), g(1) are not of opposite strict signs. *)
Theorem L2b_affine_sign (g0 g1 : R) :
  let g t := (1 - t) * g0 + t * g1 in
  ((forall t, 0 <= t <= 1 -> 0 <= g t) \/ (forall t, 0 <= t <= 1 -> g t <= 0)) <->
  not_opposite g0 g1.
Proof.
  intros g. unfold g, not_opposite. split.
  - intros [H | H]; split; intros [Ha Hb].
    + specialize (H 0). lra.
    + specialize (H 1). lra.
    + specialize (H 1). lra.
    + specialize (H 0). lra.
  - intros [Hn Hp].
    destruct (Rle_or_lt 0 g0), (Rle_or_lt 0 g1).
    + left. intros t Ht.
      assert (0 <= (1 - t) * g0) by (apply Rmult_le_pos; lra).
      assert (0 <= t * g1) by (apply Rmult_le_pos; lra). lra.
    (* otherwise one end is < 0, and the other cannot be > 0 *)
    all: assert (g0 <= 0 /\ g1 <= 0) by (split; apply Rnot_lt_le; intro; lra).
    all: right; intros t Ht.
    all: assert (0 <= (1 - t) * - g0) by (apply Rmult_le_pos; lra).
    all: assert (0 <= t * - g1) by (apply Rmult_le_pos; lra); lra.
Qed.

(* (c) For f = 1 + c1 t + c2 t^2: f > 0 on [0, 1] and f monotone iff f(1) > 0 and f'(0) = c1,
   f'(1) = c1 + 2 c2 are not of opposite strict signs. *)
Theorem L2c_area_positivity (c1 c2 : R) :
  let f t := 1 + c1 * t + c2 * t ^ 2 in
  ((forall t, 0 <= t <= 1 -> 0 < f t) /\ monotone01 f) <->
  (0 < f 1 /\ not_opposite c1 (c1 + 2 * c2)).
Proof.
  intros f.
  assert (Hd : forall t, 0 <= t <= 1 -> is_derive f t ((1 - t) * c1 + t * (c1 + 2 * c2))).
  { intros t _. unfold f. auto_derive; [exact I | ring]. }
  rewrite (L1 f _ Hd), <- L2b_affine_sign. split.
  - intros [Hpos Hm]. split; [apply Hpos; lra | exact Hm].
  - intros [H1 Hm]. split; [| exact Hm].
    pose proof Hm as Hm'. rewrite <- (L1 f _ Hd) in Hm'.
    intros t Ht. destruct Hm' as [Hup | Hdown].
    + assert (f 0 <= f t) by (apply Hup; lra). unfold f in *. lra.
    + assert (f 1 <= f t) by (apply Hdown; lra). lra.
Qed.

(* The level-E form of Def 2.2.1 for the blend: det B > 0 and tr B - 2, 2 det B - tr B not of opposite
   strict signs. *)
Theorem L2_level_E (B : mat) :
  good_for_area (blend B) <-> 0 < det B /\ not_opposite (tr B - 2) (2 * det B - tr B).
Proof.
  unfold good_for_area.
  assert (Hf : (fun t => det (blend B t)) =
               (fun t => 1 + (tr B - 2) * t + (1 - tr B + det B) * t ^ 2)).
  { apply functional_extensionality. intros t. apply L2a_det_of_blend. }
  rewrite Hf.
  pose proof (L2c_area_positivity (tr B - 2) (1 - tr B + det B)) as H. cbv beta zeta in H.
  replace (tr B - 2 + 2 * (1 - tr B + det B)) with (2 * det B - tr B) in H by ring.
  replace (1 + (tr B - 2) * 1 + (1 - tr B + det B) * 1 ^ 2) with (det B) in H by ring.
  rewrite <- H. split; intros [H1 H2]; split; try assumption.
  - intros t Ht. rewrite <- L2a_det_of_blend. exact (H2 t Ht).
  - intros t Ht. rewrite L2a_det_of_blend. exact (H1 t Ht).
Qed.
