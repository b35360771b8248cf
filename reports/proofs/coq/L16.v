(* L16: the linear volume in the invariants of A - I (LEMMAS.md, L16). *)
Require Import Reals Lra.
Require Import Affinterp.Defs3.
Open Scope R_scope.

(* det(I + t M) = 1 + c1 t + c2 t^2 + c3 t^3 with c1 = tr M, c2 = sigma2(M), c3 = det M, for every t. *)
Theorem L16_det_expansion (M : mat3) (t : R) :
  det3 (madd3 Id3 (mscale3 t M)) = 1 + tr3 M * t + sigma2 M * t ^ 2 + det3 M * t ^ 3.
Proof. destruct M; unfold det3, madd3, mscale3, Id3, tr3, sigma2; simpl; ring. Qed.

(* The companion matrix C = [[0, 0, c3], [1, 0, -c2], [0, 1, c1]] realises every real triple. *)
Definition companion (c1 c2 c3 : R) : mat3 := Mat3 0 0 c3 1 0 (- c2) 0 1 c1.

Theorem L16_companion (c1 c2 c3 : R) :
  tr3 (companion c1 c2 c3) = c1 /\ sigma2 (companion c1 c2 c3) = c2 /\ det3 (companion c1 c2 c3) = c3.
Proof. unfold tr3, sigma2, det3, companion; simpl; repeat split; ring. Qed.

Theorem L16_every_triple (c1 c2 c3 : R) :
  exists M, tr3 M = c1 /\ sigma2 M = c2 /\ det3 M = c3.
Proof. exists (companion c1 c2 c3). apply L16_companion. Qed.

(* The linear homotopy (1 - t) I + t A = I + t M with M = A - I: its volume is 1 + c1 t + c2 t^2 + c3 t^3 in
   the invariants of M, and det A = 1 + c1 + c2 + c3 (t = 1). *)
Theorem L16_linear_volume (A : mat3) (t : R) :
  let M := madd3 A (mscale3 (-1) Id3) in
  det3 (madd3 (mscale3 (1 - t) Id3) (mscale3 t A)) = 1 + tr3 M * t + sigma2 M * t ^ 2 + det3 M * t ^ 3
  /\ det3 A = 1 + tr3 M + sigma2 M + det3 M.
Proof.
  destruct A; unfold det3, madd3, mscale3, Id3, tr3, sigma2; simpl; split; ring.
Qed.
