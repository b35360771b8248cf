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

(* Products, the transpose, vectors of R^3 and the squared norm. *)
Definition mmul3 (A B : mat3) : mat3 :=
  Mat3 (a11 A * a11 B + a12 A * a21 B + a13 A * a31 B) (a11 A * a12 B + a12 A * a22 B + a13 A * a32 B)
       (a11 A * a13 B + a12 A * a23 B + a13 A * a33 B)
       (a21 A * a11 B + a22 A * a21 B + a23 A * a31 B) (a21 A * a12 B + a22 A * a22 B + a23 A * a32 B)
       (a21 A * a13 B + a22 A * a23 B + a23 A * a33 B)
       (a31 A * a11 B + a32 A * a21 B + a33 A * a31 B) (a31 A * a12 B + a32 A * a22 B + a33 A * a32 B)
       (a31 A * a13 B + a32 A * a23 B + a33 A * a33 B).
Definition transpose3 (A : mat3) : mat3 :=
  Mat3 (a11 A) (a21 A) (a31 A) (a12 A) (a22 A) (a32 A) (a13 A) (a23 A) (a33 A).
Record vec3 := Vec3 { u1 : R; u2 : R; u3 : R }.
Definition mvec3 (A : mat3) (v : vec3) : vec3 :=
  Vec3 (a11 A * u1 v + a12 A * u2 v + a13 A * u3 v) (a21 A * u1 v + a22 A * u2 v + a23 A * u3 v)
       (a31 A * u1 v + a32 A * u2 v + a33 A * u3 v).
Definition norm2_3 (v : vec3) : R := u1 v * u1 v + u2 v * u2 v + u3 v * u3 v.
Definition norm3 (v : vec3) : R := sqrt (norm2_3 v).
Definition diag3 (l1 l2 l3 : R) : mat3 := Mat3 l1 0 0 0 l2 0 0 0 l3.
(* O is orthogonal: O^T O = I and O O^T = I. The linear blend (1 - t) I + t B. *)
Definition orthogonal3 (O : mat3) : Prop := mmul3 (transpose3 O) O = Id3 /\ mmul3 O (transpose3 O) = Id3.
Definition blend3 (B : mat3) (t : R) : mat3 := madd3 (mscale3 (1 - t) Id3) (mscale3 t B).
