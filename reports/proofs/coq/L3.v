(* L3: the squared norm of a linear blend (LEMMAS.md, L3). M = B - I, P = sym M, Q = P + M^T M. *)
Require Import Reals Lra Psatz.
From Coquelicot Require Import Coquelicot.
Require Import Affinterp.Defs Affinterp.L1.
Open Scope R_scope.

Definition M_of (B : mat) : mat := madd B (mscale (-1) Id2).
Definition P_of (B : mat) : mat := sym (M_of B).
Definition Q_of (B : mat) : mat := madd (P_of B) (mmul (transpose (M_of B)) (M_of B)).

(* q(t) = ||v||^2 + 2 t P(v) + t^2 ||M v||^2 *)
Theorem L3_norm_squared_of_blend (B : mat) (v : vec) (t : R) :
  norm2 (mvec (blend B t) v) =
  norm2 v + 2 * t * qform (P_of B) v + t ^ 2 * norm2 (mvec (M_of B) v).
Proof.
  destruct B, v; unfold norm2, mvec, blend, qform, P_of, M_of, sym, transpose, madd, mscale, Id2;
  simpl; field.
Qed.

(* q'(t) / 2 = P(v) + t ||M v||^2: affine, with slope ||M v||^2 >= 0, P(v) at t = 0 and Q(v) at t = 1. *)
Theorem L3_half_derivative (B : mat) (v : vec) (t : R) :
  is_derive (fun t => norm2 (mvec (blend B t) v)) t
            (2 * (qform (P_of B) v + t * norm2 (mvec (M_of B) v))).
Proof.
  apply (is_derive_ext (fun t => norm2 v + 2 * t * qform (P_of B) v + t ^ 2 * norm2 (mvec (M_of B) v))).
  { intros s. symmetry. apply L3_norm_squared_of_blend. }
  auto_derive; [exact I | ring].
Qed.

Theorem L3_half_derivative_at_1 (B : mat) (v : vec) :
  qform (P_of B) v + 1 * norm2 (mvec (M_of B) v) = qform (Q_of B) v.
Proof.
  destruct B, v; unfold norm2, mvec, qform, Q_of, P_of, M_of, sym, transpose, mmul, madd, mscale, Id2;
  simpl; field.
Qed.

(* q is monotone on [0, 1] iff not P(v) < 0 < Q(v). *)
Theorem L3 (B : mat) (v : vec) :
  monotone01 (fun t => norm2 (mvec (blend B t) v)) <-> ~ (qform (P_of B) v < 0 < qform (Q_of B) v).
Proof.
  rewrite (L1 _ _ (fun t _ => L3_half_derivative B v t)), <- L3_half_derivative_at_1.
  set (p := qform (P_of B) v). set (k := norm2 (mvec (M_of B) v)).
  assert (Hk : 0 <= k) by (unfold k, norm2; nra).
  split.
  - intros [H | H] [Hp Hq].
    + specialize (H 0). lra.
    + specialize (H 1). lra.
  - intros Hn. destruct (Rle_or_lt 0 p) as [Hp | Hp].
    + left. intros t Ht. nra.
    + right. intros t Ht. assert (p + 1 * k <= 0) by lra. nra.
Qed.
