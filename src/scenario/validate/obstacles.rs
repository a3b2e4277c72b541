//! The obstacles: boxes, meshes, spheres, ellipsoids, cylinders and cones, each with the fields
//! of its type, named uniquely, within [`MAX_OBSTACLES`] and [`MAX_TRIANGLES`].

use nalgebra::Vector3;
use std::collections::HashMap;
use std::f64::consts::FRAC_PI_2;

use super::{max_abs, num, positive, spd, vec3, MAX_OBSTACLES, MAX_TRIANGLES};
use crate::error::{Error, Result};
use crate::scenario::json::RawObstacle;
use crate::shape::{Mesh, Obstacle, Shape};

/// Obstacle types and the geometric fields each takes (besides `name` and `type`).
const OBSTACLE_FIELDS: [(&str, &[&str]); 6] = [
    ("box", &["center", "size"]),
    ("mesh", &["vertices", "triangles"]),
    ("sphere", &["center", "radius"]),
    ("ellipsoid", &["center", "matrix"]),
    ("cylinder", &["from", "to", "radius"]),
    ("cone", &["apex", "axis", "half_angle", "height"]),
];

/// A field that the obstacle's type requires.
fn required<'a, T>(path: &str, kind: &str, name: &str, v: &'a Option<T>) -> Result<&'a T> {
    v.as_ref()
        .ok_or_else(|| Error::new(format!("{path}.{name}"), format!("missing field `{name}` (required for a {kind})")))
}

/// The obstacles, in file order; an unnamed one is called `obstacle k`.
pub(super) fn obstacles(raw: &[RawObstacle]) -> Result<Vec<Obstacle>> {
    if raw.len() > MAX_OBSTACLES {
        return Err(Error::new(
            "obstacles",
            format!("at most {MAX_OBSTACLES} obstacles are supported, got {}", raw.len()),
        ));
    }
    let mut out = Vec::with_capacity(raw.len());
    let mut names: HashMap<String, usize> = HashMap::new();
    let mut triangles = 0usize;
    for (k, o) in raw.iter().enumerate() {
        let path = format!("obstacles[{k}]");
        let name = match &o.name {
            Some(s) if s.trim().is_empty() => {
                return Err(Error::new(format!("{path}.name"), "must not be empty"));
            }
            Some(s) => s.clone(),
            None => format!("obstacle {}", k + 1),
        };
        if let Some(j) = names.get(&name) {
            let field = if o.name.is_some() { format!("{path}.name") } else { path.clone() };
            return Err(Error::new(field, format!("duplicate obstacle name \"{name}\" (also obstacles[{j}])")));
        }
        names.insert(name.clone(), k);
        let Some((kind, allowed)) = OBSTACLE_FIELDS.iter().find(|(t, _)| *t == o.kind) else {
            let types: Vec<&str> = OBSTACLE_FIELDS.iter().map(|(t, _)| *t).collect();
            return Err(Error::new(
                format!("{path}.type"),
                format!("unknown obstacle type \"{}\"; expected one of {}", o.kind, types.join(", ")),
            ));
        };
        for f in o.present_fields() {
            if !allowed.contains(&f) {
                return Err(Error::new(
                    format!("{path}.{f}"),
                    format!("not a field of a {kind} obstacle (its fields: name, color, type, {})", allowed.join(", ")),
                ));
            }
        }
        let what = format!("{kind} obstacle");
        let shape = match *kind {
            "box" => {
                let center = vec3(&format!("{path}.center"), required(&path, &what, "center", &o.center)?)?;
                let size = vec3(&format!("{path}.size"), required(&path, &what, "size", &o.size)?)?;
                for i in 0..3 {
                    positive(&format!("{path}.size[{i}]"), size[i])?;
                }
                Shape::Mesh(Mesh::cuboid(center, size))
            }
            "mesh" => Shape::Mesh(mesh(&path, o)?),
            "sphere" => Shape::Sphere {
                center: vec3(&format!("{path}.center"), required(&path, &what, "center", &o.center)?)?,
                radius: positive(&format!("{path}.radius"), *required(&path, &what, "radius", &o.radius)?)?,
            },
            "ellipsoid" => {
                let center = vec3(&format!("{path}.center"), required(&path, &what, "center", &o.center)?)?;
                let m = required(&path, &what, "matrix", &o.matrix)?;
                Shape::Ellipsoid { center, matrix: spd(&format!("{path}.matrix"), m, "an ellipsoid {x : (x−c)ᵀM(x−c) ≤ 1} needs M with positive eigenvalues")? }
            }
            "cylinder" => {
                let from = vec3(&format!("{path}.from"), required(&path, &what, "from", &o.from)?)?;
                let to = vec3(&format!("{path}.to"), required(&path, &what, "to", &o.to)?)?;
                if from == to {
                    return Err(Error::new(format!("{path}.to"), "equals `from`: the cylinder axis has zero length"));
                }
                let radius = positive(&format!("{path}.radius"), *required(&path, &what, "radius", &o.radius)?)?;
                Shape::Cylinder { from, to, radius }
            }
            _ => {
                // "cone", the last entry of OBSTACLE_FIELDS.
                let apex = vec3(&format!("{path}.apex"), required(&path, &what, "apex", &o.apex)?)?;
                let axis = vec3(&format!("{path}.axis"), required(&path, &what, "axis", &o.axis)?)?;
                let m = max_abs(axis.as_slice());
                if m == 0.0 {
                    return Err(Error::new(format!("{path}.axis"), "zero vector: the cone axis needs a direction"));
                }
                let axis = (axis / m).normalize();
                let field = format!("{path}.half_angle");
                let half_angle = num(&field, *required(&path, &what, "half_angle", &o.half_angle)?)?;
                if !(half_angle > 0.0 && half_angle < FRAC_PI_2) {
                    return Err(Error::new(field, format!("must be in (0, π/2) radians, got {half_angle}")));
                }
                let height = positive(&format!("{path}.height"), *required(&path, &what, "height", &o.height)?)?;
                Shape::Cone { apex, axis, half_angle, height }
            }
        };
        if let Shape::Mesh(m) = &shape {
            triangles += m.triangles.len();
            if triangles > MAX_TRIANGLES {
                return Err(Error::new(
                    path,
                    format!(
                        "the scenario's meshes have more than {MAX_TRIANGLES} triangles in total (a box counts 12)"
                    ),
                ));
            }
        }
        let color = o.color.as_deref().map(|c| color(&format!("{path}.color"), c)).transpose()?;
        out.push(Obstacle { name, shape, color });
    }
    Ok(out)
}

/// A display colour: `#` and six hexadecimal digits (`#rrggbb`), kept as given.
fn color(field: &str, c: &str) -> Result<String> {
    let hex = c.strip_prefix('#').unwrap_or_default();
    if hex.len() != 6 || !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
        return Err(Error::new(field, format!("{c:?} is not a colour of the form \"#rrggbb\" (six hexadecimal digits)")));
    }
    Ok(c.to_owned())
}

/// A mesh obstacle: its vertices, and triangles of vertex indices with a non-zero area.
fn mesh(path: &str, o: &RawObstacle) -> Result<Mesh> {
    let what = "mesh obstacle";
    let raw_vertices = required(path, what, "vertices", &o.vertices)?;
    let raw_triangles = required(path, what, "triangles", &o.triangles)?;
    if raw_triangles.is_empty() {
        return Err(Error::new(format!("{path}.triangles"), "a mesh needs at least one triangle"));
    }
    if raw_triangles.len() > MAX_TRIANGLES {
        return Err(Error::new(
            format!("{path}.triangles"),
            format!("at most {MAX_TRIANGLES} triangles are supported, got {}", raw_triangles.len()),
        ));
    }
    let vertices = raw_vertices
        .iter()
        .enumerate()
        .map(|(i, v)| vec3(&format!("{path}.vertices[{i}]"), v))
        .collect::<Result<Vec<_>>>()?;
    let nv = vertices.len();
    let mut triangles = Vec::with_capacity(raw_triangles.len());
    for (t, tri) in raw_triangles.iter().enumerate() {
        let mut corners = [Vector3::zeros(); 3];
        for (c, &idx) in tri.0.iter().enumerate() {
            match vertices.get(idx) {
                Some(v) => corners[c] = *v,
                None => {
                    return Err(Error::new(
                        format!("{path}.triangles[{t}][{c}]"),
                        format!("vertex index {idx} out of range: the mesh has {nv} vertices (indices from 0)"),
                    ))
                }
            }
        }
        let [a, b, c] = corners;
        let scale = (b - a).norm().max((c - a).norm()).max((c - b).norm());
        let area2 = (b - a).cross(&(c - a)).norm();
        if area2.is_nan() || area2 <= 1e-12 * scale * scale {
            return Err(Error::new(
                format!("{path}.triangles[{t}]"),
                "degenerate triangle (zero area): its corners coincide or are collinear",
            ));
        }
        triangles.push(tri.0);
    }
    Ok(Mesh { vertices, triangles })
}
