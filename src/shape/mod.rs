//! Obstacles: what they are (this module) apart from what is asked of them (`query`, `conditions`).

use nalgebra::{Matrix3, Vector3};

/// A named obstacle.
#[derive(Debug, Clone, PartialEq)]
pub struct Obstacle {
    /// Its name in reports (`"cable 3 - plinth"`); defaults to `"obstacle N"`.
    pub name: String,
    /// Its geometry.
    pub shape: Shape,
    /// Its display colour, `#rrggbb`, if the scenario gives one (drawing only; no condition uses it).
    pub color: Option<String>,
}

/// The geometry of an obstacle. Every shape is a closed solid.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// A triangle mesh; a box is stored as its 12 triangles.
    Mesh(Mesh),
    /// A ball.
    Sphere {
        /// Centre.
        center: Vector3<f64>,
        /// Radius (> 0).
        radius: f64,
    },
    /// The solid {x : (x−c)ᵀ M (x−c) ≤ 1} for a symmetric positive definite M.
    Ellipsoid {
        /// Centre c.
        center: Vector3<f64>,
        /// The SPD matrix M.
        matrix: Matrix3<f64>,
    },
    /// A finite solid cylinder with flat ends.
    Cylinder {
        /// Centre of one end face.
        from: Vector3<f64>,
        /// Centre of the other end face.
        to: Vector3<f64>,
        /// Radius (> 0).
        radius: f64,
    },
    /// A solid right circular cone, truncated by its base plane.
    Cone {
        /// The apex.
        apex: Vector3<f64>,
        /// Unit vector from the apex towards the base.
        axis: Vector3<f64>,
        /// Half-angle at the apex, in (0, π/2) radians.
        half_angle: f64,
        /// Distance from the apex to the base plane (> 0).
        height: f64,
    },
}

/// A triangle mesh.
#[derive(Debug, Clone, PartialEq)]
pub struct Mesh {
    /// Vertex positions.
    pub vertices: Vec<Vector3<f64>>,
    /// Vertex indices of each triangle.
    pub triangles: Vec<[usize; 3]>,
}

impl Mesh {
    /// The axis-aligned box with the given centre and full side lengths, as 8 vertices and
    /// 12 outward-facing triangles.
    pub fn cuboid(center: Vector3<f64>, size: Vector3<f64>) -> Mesh {
        let h = size / 2.0;
        let vertices = (0..8)
            .map(|i| {
                let sx = if i & 1 == 0 { -1.0 } else { 1.0 };
                let sy = if i & 2 == 0 { -1.0 } else { 1.0 };
                let sz = if i & 4 == 0 { -1.0 } else { 1.0 };
                center + Vector3::new(sx * h.x, sy * h.y, sz * h.z)
            })
            .collect();
        let faces = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
        let triangles = faces.iter().flat_map(|f| [[f[0], f[1], f[2]], [f[0], f[2], f[3]]]).collect();
        Mesh { vertices, triangles }
    }

    /// The corner positions of triangle `k`.
    pub fn triangle(&self, k: usize) -> [Vector3<f64>; 3] {
        let [a, b, c] = self.triangles[k];
        [self.vertices[a], self.vertices[b], self.vertices[c]]
    }
}
