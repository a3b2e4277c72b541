//! Certified univariate polynomial machinery on the unit interval.
//!
//! * [`Bern`] — a polynomial in Bernstein form on [0, 1] with a rigorous bound on the error of its
//!   coefficients, carried through every arithmetic operation.
//! * `signs` — where a polynomial is certainly positive, certainly negative, or too close to
//!   zero to tell (root isolation by Bernstein subdivision with error control).
//! * [`Minors`] — the cofactors of a matrix of polynomials on many column sets at once.
//! * [`Partition`] — three-valued truth over [0, 1], combined with and/or, which is how the
//!   conditions' semi-algebraic sets are computed.

mod bernstein;
mod minors;
mod partition;
mod signs;

pub use bernstein::{binomial, halve, Bern};
pub use minors::Minors;
pub use partition::{Partition, Truth};
pub use signs::{sign_pieces, sign_pieces_outside, Sign};
