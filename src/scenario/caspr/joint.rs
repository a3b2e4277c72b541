//! How the coordinates q of a CASPR platform joint place the platform: `SPATIAL_EULER_XYZ`'s
//! x y z and XYZ Euler angles, `PLANAR_XY`'s x y θ (θ about z), `T_XYZ`'s x y z — for the
//! platform reader's initial pose and the trajectories' knots alike. There are as many
//! coordinates as the platform's degrees of freedom ([`Mobility::dof`]).

use crate::model::Mobility;

/// Where joint coordinates `q` put the platform: its position (`origin` plus the joint's
/// translation) and its XYZ Euler angles in radians (none for a point mass).
pub(super) fn place(mobility: Mobility, origin: [f64; 3], q: &[f64]) -> ([f64; 3], Option<[f64; 3]>) {
    match mobility {
        Mobility::Spatial => ([origin[0] + q[0], origin[1] + q[1], origin[2] + q[2]], Some([q[3], q[4], q[5]])),
        Mobility::Planar => ([origin[0] + q[0], origin[1] + q[1], origin[2]], Some([0.0, 0.0, q[2]])),
        Mobility::Point => ([origin[0] + q[0], origin[1] + q[1], origin[2] + q[2]], None),
    }
}

/// A joint rate (`q_dot`, `q_ddot`) split into its linear part, a 3-vector, and its angular
/// part.
pub(super) fn split_rate(mobility: Mobility, v: &[f64]) -> ([f64; 3], &[f64]) {
    match mobility {
        Mobility::Spatial => ([v[0], v[1], v[2]], &v[3..]),
        Mobility::Planar => ([v[0], v[1], 0.0], &v[2..]),
        Mobility::Point => ([v[0], v[1], v[2]], &[]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// CASPR's coordinates: PLANAR_XY's q = x y θ (θ about z), T_XYZ's q = x y z.
    #[test]
    fn coordinates_place_the_platform() {
        let o = [1.0, 2.0, 0.0];
        assert_eq!(place(Mobility::Planar, o, &[0.5, 0.25, 0.3]), ([1.5, 2.25, 0.0], Some([0.0, 0.0, 0.3])));
        assert_eq!(place(Mobility::Point, o, &[0.5, 0.25, 0.3]), ([1.5, 2.25, 0.3], None));
        assert_eq!(place(Mobility::Spatial, o, &[0.5, 0.25, 0.3, 0.1, 0.2, 0.3]), ([1.5, 2.25, 0.3], Some([0.1, 0.2, 0.3])));
        assert_eq!(split_rate(Mobility::Planar, &[1.0, 2.0, 3.0]), ([1.0, 2.0, 0.0], &[3.0][..]));
        assert_eq!(split_rate(Mobility::Point, &[1.0, 2.0, 3.0]), ([1.0, 2.0, 3.0], &[][..]));
    }
}
