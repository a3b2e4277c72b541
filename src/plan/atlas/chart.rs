//! One chart of a Henderson atlas: a centre on the manifold, an orthonormal tangent basis, and the
//! polytope in tangent coordinates that says which part of the chart's ball no neighbour covers yet.

use nalgebra::DMatrix;
use serde::{Deserialize, Serialize};

/// What the continuation may still do with a chart.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ChartState {
    /// Its polytope may still have vertices outside its ball: it can be expanded.
    Open,
    /// Expanded until no vertex of its polytope is outside its ball (Henderson's "closed").
    Expanded,
    /// Its centre is beyond the auxiliary bounds: never expanded, but a node of the search.
    OutOfBounds,
    /// Its centre fails a validity condition (interference): never expanded nor entered; its
    /// radius is the step at which it was found, so it claims only the region around it.
    Blocked,
}

/// A chart: centre x_c on the manifold, tangent basis Ψ (n × k, orthonormal columns), polytope.
#[derive(Debug, Clone)]
pub struct Chart {
    /// The centre, a point of the manifold.
    pub centre: Vec<f64>,
    /// Orthonormal basis of the tangent space at the centre, one column per tangent direction.
    pub basis: DMatrix<f64>,
    /// The part of the tangent space this chart is responsible for.
    pub polytope: Polytope,
    /// Indices of the neighbouring charts (mutual, cropping each other).
    pub neighbours: Vec<usize>,
    /// The radius of its ball (the atlas's r; smaller for a blocked chart found by shrinking).
    pub radius: f64,
    /// What may still be done with it.
    pub state: ChartState,
}

/// One vertex of a polytope: its position and the faces it lies on (sorted ids).
#[derive(Debug, Clone, Serialize, Deserialize)]
struct Vertex {
    position: Vec<f64>,
    faces: Vec<u32>,
}

/// A convex polytope in k dimensions held by its vertices, each labelled with the faces it lies
/// on. It starts as a cube and is only ever cut by half-spaces; two vertices are joined by an edge
/// when they share k − 1 faces (exact for simple polytopes; in degenerate cases the extra vertices
/// this may create lie inside the polytope, so they never enlarge it).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Polytope {
    dim: usize,
    vertices: Vec<Vertex>,
    next_face: u32,
}

/// Vertices within this distance of a cutting plane count as lying on it.
const ON_PLANE: f64 = 1e-10;

impl Polytope {
    /// The cube [−h, h]^k (2^k vertices; face 2j is x_j = −h, face 2j + 1 is x_j = h).
    pub fn cube(dim: usize, half: f64) -> Polytope {
        let vertices = (0..1usize << dim)
            .map(|bits| Vertex {
                position: (0..dim).map(|j| if bits >> j & 1 == 1 { half } else { -half }).collect(),
                faces: (0..dim).map(|j| (2 * j + (bits >> j & 1)) as u32).collect(),
            })
            .collect();
        Polytope { dim, vertices, next_face: 2 * dim as u32 }
    }

    /// The vertex farthest from the origin if it lies outside the ball of radius `radius`.
    pub fn open_vertex(&self, radius: f64) -> Option<&[f64]> {
        let norm2 = |v: &Vertex| v.position.iter().map(|a| a * a).sum::<f64>();
        self.vertices
            .iter()
            .map(|v| (norm2(v), v))
            .filter(|(n2, _)| *n2 > radius * radius)
            .max_by(|a, b| a.0.total_cmp(&b.0))
            .map(|(_, v)| v.position.as_slice())
    }

    /// Cuts the polytope by the half-space normal·x ≤ offset. Returns whether a vertex was
    /// removed.
    pub fn cut(&mut self, normal: &[f64], offset: f64) -> bool {
        let scale = normal.iter().map(|a| a * a).sum::<f64>().sqrt();
        if !(scale > 0.0) || !offset.is_finite() {
            return false;
        }
        let side: Vec<f64> =
            self.vertices.iter().map(|v| (v.position.iter().zip(normal).map(|(a, b)| a * b).sum::<f64>() - offset) / scale).collect();
        if side.iter().all(|&d| d <= ON_PLANE) {
            return false;
        }
        let face = self.next_face;
        self.next_face += 1;
        let mut added = Vec::new();
        for (o, i) in self.crossing_edges(&side) {
            let (d_in, d_out) = (side[i], side[o]);
            let lambda = d_in / (d_in - d_out);
            let (a, b) = (&self.vertices[i].position, &self.vertices[o].position);
            let position = a.iter().zip(b).map(|(p, q)| p + lambda * (q - p)).collect();
            let mut faces = shared_faces(&self.vertices[o].faces, &self.vertices[i].faces);
            faces.push(face);
            added.push(Vertex { position, faces });
        }
        let mut kept: Vec<Vertex> = Vec::with_capacity(self.vertices.len() + added.len());
        for (mut v, &d) in std::mem::take(&mut self.vertices).into_iter().zip(&side) {
            if d > ON_PLANE {
                continue;
            }
            if d >= -ON_PLANE {
                v.faces.push(face);
            }
            kept.push(v);
        }
        kept.extend(added);
        self.vertices = kept;
        true
    }
}

impl Polytope {
    /// Its dimension k.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// Whether it is well formed (as read from a file): every vertex has k coordinates, all
    /// finite, and sorted face ids below the next face's.
    pub fn is_consistent(&self) -> bool {
        self.vertices.iter().all(|v| {
            v.position.len() == self.dim && v.position.iter().all(|x| x.is_finite()) && v.faces.windows(2).all(|w| w[0] < w[1]) && v.faces.iter().all(|&f| f < self.next_face)
        })
    }

    /// The vertices' positions (tangent coordinates), in no particular order.
    pub fn vertices(&self) -> impl Iterator<Item = &[f64]> {
        self.vertices.iter().map(|v| v.position.as_slice())
    }

    /// Each face's vertices (indices into [`Polytope::vertices`], in no particular order): the
    /// vertices that lie on one cutting plane or cube side, for the faces that have at least k.
    pub fn faces(&self) -> Vec<Vec<usize>> {
        let mut by_face: std::collections::BTreeMap<u32, Vec<usize>> = std::collections::BTreeMap::new();
        for (i, v) in self.vertices.iter().enumerate() {
            for &f in &v.faces {
                by_face.entry(f).or_default().push(i);
            }
        }
        by_face.into_values().filter(|vs| vs.len() >= self.dim).collect()
    }

    /// The edges (outside vertex, inside vertex) that a plane with signed distances `side` crosses:
    /// pairs sharing at least k − 1 faces. Each simple vertex (k faces) gets k keys, one per
    /// (k − 1)-subset of its faces (a sum of mixed face ids); sorting the keys brings the vertices
    /// of each edge together, so a cut costs O(V·k·log) rather than O(V²). Matches are confirmed
    /// on the face lists (keys may collide); degenerate vertices are compared directly.
    fn crossing_edges(&self, side: &[f64]) -> Vec<(usize, usize)> {
        let k = self.dim;
        let outside = |v: usize| side[v] > ON_PLANE;
        let inside = |v: usize| side[v] < -ON_PLANE;
        let mix = |f: u32| {
            let mut z = (f as u64).wrapping_add(0x9E37_79B9_7F4A_7C15);
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z ^ (z >> 27)
        };
        let mut keys: Vec<(u64, usize)> = Vec::new();
        let mut degenerate = Vec::new();
        for (v, vertex) in self.vertices.iter().enumerate() {
            if !(outside(v) || inside(v)) {
                continue;
            }
            if vertex.faces.len() != k {
                degenerate.push(v);
                continue;
            }
            let total = vertex.faces.iter().fold(0u64, |a, &f| a.wrapping_add(mix(f)));
            keys.extend(vertex.faces.iter().map(|&f| (total.wrapping_sub(mix(f)), v)));
        }
        keys.sort_unstable();
        let mut edges = Vec::new();
        let adjacent = |o: usize, i: usize| shared_faces(&self.vertices[o].faces, &self.vertices[i].faces).len() + 1 >= k;
        for group in keys.chunk_by(|a, b| a.0 == b.0) {
            for &(_, o) in group.iter().filter(|e| outside(e.1)) {
                for &(_, i) in group.iter().filter(|e| inside(e.1)) {
                    if adjacent(o, i) {
                        edges.push((o, i));
                    }
                }
            }
        }
        for &d in &degenerate {
            for v in 0..self.vertices.len() {
                let pair = if outside(d) && inside(v) { (d, v) } else if inside(d) && outside(v) { (v, d) } else { continue };
                if adjacent(pair.0, pair.1) {
                    edges.push(pair);
                }
            }
        }
        edges.sort_unstable();
        edges.dedup();
        edges
    }
}

/// The ids present in both sorted lists.
fn shared_faces(a: &[u32], b: &[u32]) -> Vec<u32> {
    let (mut i, mut j, mut out) = (0, 0, Vec::new());
    while i < a.len() && j < b.len() {
        match a[i].cmp(&b[j]) {
            std::cmp::Ordering::Less => i += 1,
            std::cmp::Ordering::Greater => j += 1,
            std::cmp::Ordering::Equal => {
                out.push(a[i]);
                i += 1;
                j += 1;
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Cutting the square by x + y ≤ 1 leaves a pentagon; by x ≤ 0.5 and y ≤ 0.5 a square.
    #[test]
    fn square_cuts_match_hand_computed_vertices() {
        let mut p = Polytope::cube(2, 1.0);
        assert!(p.cut(&[1.0, 1.0], 1.0));
        assert_eq!(p.vertices.len(), 5);
        let mut q = Polytope::cube(2, 1.0);
        q.cut(&[1.0, 0.0], 0.5);
        q.cut(&[0.0, 1.0], 0.5);
        let mut v: Vec<(i64, i64)> = q.vertices.iter().map(|v| ((v.position[0] * 4.0).round() as i64, (v.position[1] * 4.0).round() as i64)).collect();
        v.sort();
        assert_eq!(v, vec![(-4, -4), (-4, 2), (2, -4), (2, 2)]);
        assert!(!q.cut(&[1.0, 0.0], 3.0), "a plane beyond every vertex cuts nothing");
    }

    /// A cube cut by many random half-spaces through a ball of radius 0.5 keeps exactly the
    /// vertices a brute-force enumeration (every k-subset of planes) finds.
    #[test]
    fn cube_cuts_agree_with_brute_force_in_3d() {
        let mut seed = 7u64;
        let mut rnd = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        let mut planes: Vec<(Vec<f64>, f64)> = (0..3).flat_map(|j| [-1.0, 1.0].map(|s| {
            let mut n = vec![0.0; 3];
            n[j] = s;
            (n, 1.0)
        })).collect();
        let mut p = Polytope::cube(3, 1.0);
        for _ in 0..6 {
            let n = [rnd(), rnd(), rnd()];
            let len = n.iter().map(|a| a * a).sum::<f64>().sqrt();
            let n: Vec<f64> = n.iter().map(|a| a / len).collect();
            p.cut(&n, 0.5);
            planes.push((n, 0.5));
        }
        let mut brute = 0;
        for a in 0..planes.len() {
            for b in a + 1..planes.len() {
                for c in b + 1..planes.len() {
                    let m = nalgebra::Matrix3::from_rows(&[a, b, c].map(|i| nalgebra::RowVector3::from_row_slice(&planes[i].0)));
                    let Some(inv) = m.try_inverse() else { continue };
                    let x = inv * nalgebra::Vector3::new(planes[a].1, planes[b].1, planes[c].1);
                    if planes.iter().all(|(n, o)| n[0] * x[0] + n[1] * x[1] + n[2] * x[2] <= o + 1e-9) {
                        brute += 1;
                        assert!(p.vertices.iter().any(|v| (0..3).all(|j| (v.position[j] - x[j]).abs() < 1e-9)), "vertex {x:?} missing");
                    }
                }
            }
        }
        assert_eq!(p.vertices.len(), brute);
    }
}
