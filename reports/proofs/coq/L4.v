(* L4: the norm and its square (LEMMAS.md, L4). *)
Require Import Reals Lra Psatz.
Require Import Affinterp.Defs.
Open Scope R_scope.

(* For a function n >= 0 on [0, 1]: n is monotone iff n^2 is (u -> u^2 increases strictly on [0, oo)). *)
Theorem L4_nonneg (n : R -> R) :
  (forall t, 0 <= t <= 1 -> 0 <= n t) -> (monotone01 n <-> monotone01 (fun t => n t ^ 2)).
Proof.
  intros Hn. unfold monotone01, nondecreasing01, nonincreasing01.
  assert (Hsq : forall s t, 0 <= s <= 1 -> 0 <= t <= 1 -> (n s <= n t <-> n s ^ 2 <= n t ^ 2)).
  { intros s t Hs Ht. pose proof (Hn s Hs). pose proof (Hn t Ht). split; intros; nra. }
  split; intros [H | H]; [left | right | left | right]; intros s t Hs Hst Ht;
    specialize (H s t Hs Hst Ht).
  - apply Hsq; lra.
  - apply (Hsq t s); lra.
  - apply Hsq; lra.
  - apply (Hsq t s); lra.
Qed.

(* L4 as LEMMAS.md states it: ||A(t) v|| is monotone on [0, 1] iff ||A(t) v||^2 is. *)
Theorem L4 (A : R -> mat) (v : vec) :
  monotone01 (fun t => norm (mvec (A t) v)) <-> monotone01 (fun t => norm2 (mvec (A t) v)).
Proof.
  rewrite (L4_nonneg (fun t => norm (mvec (A t) v))) by (intros; apply sqrt_pos).
  assert (E : forall t, norm (mvec (A t) v) ^ 2 = norm2 (mvec (A t) v)).
  { intros t. unfold norm. rewrite <- Rsqr_pow2. apply Rsqr_sqrt. unfold norm2. nra. }
  unfold monotone01, nondecreasing01, nonincreasing01. setoid_rewrite E. tauto.
Qed.
