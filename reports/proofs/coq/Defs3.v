(* 3x3 matrices by their entries, for the 3D lemmas (LEMMAS.md, L14-L21): [[a11, a12, a13], [a21, a22, a23],
   [a31, a32, a33]]. det3 is the Leibniz (Sarrus) determinant, sigma2 the sum of the principal 2x2 minors. *)
Require Import Reals.
Open Scope R_scope.

Record mat3 := Mat3 {
  a11 : R; a12 : R; a13 : R;
  a21 : R; a22 : R; a23 : R;
  a31 : R; a32 : R; a33 : R }.

Definition det3 (M : mat3) : R :=
  a11 M * (a22 M * a33 M - a23 M * a32 M)
  - a12 M * (a21 M * a33 M - a23 M * a31 M)
  + a13 M * (a21 M * a32 M - a22 M * a31 M).
Definition tr3 (M : mat3) : R := a11 M + a22 M + a33 M.
Definition sigma2 (M : mat3) : R :=
  (a11 M * a22 M - a12 M * a21 M) + (a11 M * a33 M - a13 M * a31 M) + (a22 M * a33 M - a23 M * a32 M).
Definition Id3 : mat3 := Mat3 1 0 0 0 1 0 0 0 1.
Definition madd3 (A B : mat3) : mat3 :=
  Mat3 (a11 A + a11 B) (a12 A + a12 B) (a13 A + a13 B)
       (a21 A + a21 B) (a22 A + a22 B) (a23 A + a23 B)
       (a31 A + a31 B) (a32 A + a32 B) (a33 A + a33 B).
Definition mscale3 (k : R) (A : mat3) : mat3 :=
  Mat3 (k * a11 A) (k * a12 A) (k * a13 A)
       (k * a21 A) (k * a22 A) (k * a23 A)
       (k * a31 A) (k * a32 A) (k * a33 A).
Definition symmetric3 (M : mat3) : Prop := a12 M = a21 M /\ a13 M = a31 M /\ a23 M = a32 M.
(* The squared Frobenius norm ||M||_F^2, the sum of the squared entries. *)
Definition frob2 (M : mat3) : R :=
  a11 M ^ 2 + a12 M ^ 2 + a13 M ^ 2 + a21 M ^ 2 + a22 M ^ 2 + a23 M ^ 2 + a31 M ^ 2 + a32 M ^ 2 + a33 M ^ 2.
