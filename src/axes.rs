//! Values built once per axis (x, y, z) or per wrench component (fx, fy, fz, mx, my, mz).
//!
//! `[0, 1, 2].map(f)`, `each_ref().map(f)` and `std::array::from_fn(f)` build their array through
//! a temporary and copy it out: for polynomials with their coefficients in place (about 200 bytes
//! each, [`crate::poly::Coeffs`]) those copies took about a tenth of a verification of CoGiRo's
//! `general_1` (docs/dynamics.md, "Speed"). The functions here write the values where they are
//! returned.

/// `[f(0), f(1), f(2)]`: f called for the axes in order, the array built in place.
#[inline(always)]
pub fn per_axis<T>(mut f: impl FnMut(usize) -> T) -> [T; 3] {
    [f(0), f(1), f(2)]
}

/// `[f(&a[0]), f(&a[1]), f(&a[2])]`: [`per_axis`] over the values of `a`.
#[inline(always)]
pub fn each_axis<T, U>(a: &[T; 3], mut f: impl FnMut(&T) -> U) -> [U; 3] {
    [f(&a[0]), f(&a[1]), f(&a[2])]
}

/// `[f(0), …, f(5)]`: f called for the six wrench components in order, the array built in place.
#[inline(always)]
pub fn per_component<T>(mut f: impl FnMut(usize) -> T) -> [T; 6] {
    [f(0), f(1), f(2), f(3), f(4), f(5)]
}

#[cfg(test)]
mod tests {
    use super::{each_axis, per_axis, per_component};

    #[test]
    fn the_axes_in_order() {
        let mut calls = Vec::new();
        let v = per_axis(|i| {
            calls.push(i);
            10 * i
        });
        assert_eq!(v, [0, 10, 20]);
        assert_eq!(calls, [0, 1, 2]);
        assert_eq!(each_axis(&["x", "yy", "zzz"], |s| s.len()), [1, 2, 3]);
        assert_eq!(per_component(|j| j * j), [0, 1, 4, 9, 16, 25]);
    }
}
