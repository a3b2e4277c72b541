//! cablenav's fastest safe timing side by side with batotp (Barnett & Gosselin, "A Bisection
//! Algorithm for Time-Optimal Trajectory Planning Along Fully Specified Paths", IEEE T-RO 37(1),
//! 2021) on batotp's own CSPR3DOF case: Laval's large 3-cable point-mass suspended robot.
//!
//!     cargo run --release --example bench -- batotp-preset  # writes static/scenarios/laval-cspr3dof.json
//!     cargo run --release --example bench -- batotp         # builds and runs batotp, then cablenav
//!
//! The peer is ../shared/peers/batotp (its PEER.md): it is only built and run here, from a copy in
//! a temporary directory, and its files are read as data; none of its code is in this project.
//!
//! **The preset** (`batotp-preset`) holds batotp's robot, limits and path:
//!
//! * the three base anchors `findCSPR3DOFpmat` computes (batotp/robot.cpp): three survey points
//!   of the Laval robot, each a target plus an offset for the first two, taken in the order
//!   (−y, −x, −z) and centred on their centroid — the same double arithmetic in the same order,
//!   so the numbers are batotp's to the last bit. That frame has z **down** (the path runs at
//!   z ≈ 2 to 5 m below the anchors at z ≈ 0), and `dynCSPR3DOF` balances A·τ = −ẍ + (0, 0, g)
//!   with g = 9.81 (batotp/config.h) for a unit point mass: gravity (0, 0, +9.81);
//! * the limits of input/CSPR3DOF/config.dat, read from it: cable speed and acceleration (one
//!   winch limit, all three cables equal there), tension bounds per unit mass, the Cartesian speed;
//!   no length bounds (batotp has none);
//! * the path input/CSPR3DOF/CSPR3DOFspline.dat (3801 float32 points, 0.005 apart in its
//!   parameter) as a C² uniform cubic spline of Bézier pieces (format 2 `pieces`): the
//!   least-squares uniform cubic B-spline with the fewest pieces that reproduces every point at its
//!   own parameter to 1 µm. batotp's generator (generatePathPointsCSPR.m) made the path as a cubic
//!   spline through 20 random points at s = 0, 1, …, 19, so 19 uniform pieces hold it exactly, to
//!   the data's float32 rounding. The pieces share their join points (the same doubles, written
//!   in shortest round-trip form), and the B-spline makes the velocity per unit t continuous
//!   across them, so the timing sees no corner;
//! * poses `start` and `end` at the path's ends. The format has no description field: the
//!   scenario's name says where it all comes from and how close the fit is, as the thesis
//!   presets' names do.
//!
//! The fit's deviation is the distance from each of the 3801 points to the nearest point of the
//! curve: seeded by the nearest of 100 samples per piece and by the point's own parameter, refined
//! by Newton's method on |C(u) − p|²; every distance reported is to a point of the curve, so it
//! bounds the true distance from above.
//!
//! **The benchmark** (`batotp`) copies the peer to a temporary directory, builds it as PEER.md
//! says (`compile.sh`: g++ and Eigen, `scripts/install.sh --batotp`), runs `Release/batest` five
//! times (its printed duration and computation times, and the wall time of the process), then
//! times the preset's `batotp-path` with `cablenav::plan::timing::fastest` (the library call of
//! `cablenav time`, median of five runs) on its default 400 cells and on 2000 and 4000 (about as
//! many cells as batotp's 0.01 s integration takes steps, and twice that). It then reads batotp's output `output/traj_out.dat` (997
//! positions 0.02 s apart, as the file says) into a timed quintic spline through knots (format 4),
//! `batotp-output`, each knot with the velocity and acceleration of the natural cubic spline
//! through the positions — the interpolation batotp itself uses for the tensions it writes, so the
//! quintic through those knots is that cubic spline exactly — and verifies it exactly (where it
//! leaves the limits between its grid points, each stretch named by what cablenav's per-pose check
//! finds violated just inside its start), and point-wise at its knots (cablenav's
//! per-pose check, and the tensions computed here independently, against the ones batotp writes),
//! and samples it 100 times per step for how far past each limit it goes.
//!
//! It prints the body of the "Fastest safe timing against batotp" section of docs/benchmarks.md
//! (markdown) on stdout; `scripts/bench.sh --batotp` adds the header and writes it.

use cablenav::plan::timing::{fastest, TimingOptions};
use cablenav::report::{PoseReport, TimingReport, VerifyReport};
use cablenav::verify::{check_along, verify_trajectory};
use cablenav::Scenario;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

/// The peer's checkout (read only).
fn peer_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/peers/batotp")
}

/// The preset this module writes.
fn preset_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("static/scenarios/laval-cspr3dof.json")
}

/// The trajectory the preset's path is called.
pub const PATH_NAME: &str = "batotp-path";

/// The trajectory batotp's output becomes (in memory only).
pub const OUTPUT_NAME: &str = "batotp-output";

/// The fit's tolerance at each point's own parameter: the fewest pieces within it are taken.
const FIT_TOL: f64 = 1e-6;

/// Most pieces tried.
const MAX_PIECES: usize = 400;

/// Runs batest and cablenav's timing this many times each.
const RUNS: usize = 5;

// ---------------------------------------------------------------------------------------------
// batotp's files

fn f32_at(b: &[u8], at: usize) -> f32 {
    f32::from_le_bytes(b[at..at + 4].try_into().expect("4 bytes"))
}

fn i32_at(b: &[u8], at: usize) -> i32 {
    i32::from_le_bytes(b[at..at + 4].try_into().expect("4 bytes"))
}

/// A float32 as the decimal it was written from (0.005 rather than 0.004999999888241291).
fn short(x: f32) -> f64 {
    format!("{x}").parse().expect("a float prints as a number")
}

/// A path file of batotp with Cartesian data only (input/CSPR3DOF/CSPR3DOFspline.dat): float32
/// step, int32 n, int32 joint-data flag (0), int32 Cartesian flag (1), then x[n], y[n], z[n] as
/// float32, little-endian.
#[derive(Debug, Clone)]
pub struct PathFile {
    /// The parameter step between points.
    pub step: f64,
    /// The points.
    pub points: Vec<[f64; 3]>,
}

/// Reads a path file (see [`PathFile`]).
pub fn read_path(b: &[u8]) -> Result<PathFile, String> {
    if b.len() < 16 {
        return Err(format!("{} bytes: too short for the header", b.len()));
    }
    let (step, n, joints, cart) = (f32_at(b, 0), i32_at(b, 4), i32_at(b, 8), i32_at(b, 12));
    if joints != 0 || cart != 1 {
        return Err(format!("joint data flag {joints}, Cartesian flag {cart}: only Cartesian paths (0, 1) are read"));
    }
    let n = usize::try_from(n).ok().filter(|&n| n >= 4).ok_or(format!("{n} points"))?;
    if b.len() != 16 + 12 * n {
        return Err(format!("{} bytes for {n} points: expected {}", b.len(), 16 + 12 * n));
    }
    let coord = |c: usize, i: usize| f32_at(b, 16 + 4 * (c * n + i)) as f64;
    Ok(PathFile { step: short(step), points: (0..n).map(|i| [coord(0, i), coord(1, i), coord(2, i)]).collect() })
}

/// batotp's output trajectory `output/traj_out.dat` (`BA::trajWriteBIN`): float32 time step,
/// int32 n, int32 1, the joint positions (cable lengths) [3][n], int32 Cartesian flag and the
/// positions [3][n], int32 torque flag and the generalised forces (tensions) [3][n], all float32.
#[derive(Debug, Clone)]
pub struct Output {
    /// The time step the file states (s).
    pub step: f64,
    /// Cable lengths per point.
    pub lengths: Vec<[f64; 3]>,
    /// Positions per point.
    pub positions: Vec<[f64; 3]>,
    /// The tensions batotp computed at each point, if written.
    pub tensions: Option<Vec<[f64; 3]>>,
}

/// Reads batotp's output trajectory of a 3-joint, 3-coordinate robot (see [`Output`]).
pub fn read_output(b: &[u8]) -> Result<Output, String> {
    let short_file = || format!("{} bytes: the file ends early", b.len());
    if b.len() < 12 {
        return Err(short_file());
    }
    let step = short(f32_at(b, 0));
    let n = usize::try_from(i32_at(b, 4)).ok().filter(|&n| n >= 3).ok_or(format!("{} points", i32_at(b, 4)))?;
    let flag = |at: usize| if b.len() >= at + 4 { Ok(i32_at(b, at)) } else { Err(short_file()) };
    let block = |at: usize| -> Result<Vec<[f64; 3]>, String> {
        if b.len() < at + 12 * n {
            return Err(short_file());
        }
        Ok((0..n).map(|i| std::array::from_fn(|c| f32_at(b, at + 4 * (c * n + i)) as f64)).collect())
    };
    if flag(8)? != 1 {
        return Err("no joint data".into());
    }
    let lengths = block(12)?;
    let mut at = 12 + 12 * n;
    if flag(at)? != 1 {
        return Err("no Cartesian data".into());
    }
    let positions = block(at + 4)?;
    at += 4 + 12 * n;
    let tensions = if flag(at)? == 1 { Some(block(at + 4)?) } else { None };
    at += 4 + if tensions.is_some() { 12 * n } else { 0 };
    if b.len() != at {
        return Err(format!("{} bytes, {at} expected", b.len()));
    }
    Ok(Output { step, lengths, positions, tensions })
}

/// The CSPR3DOF limits of batotp's config.dat.
#[derive(Debug, Clone, PartialEq)]
pub struct Config {
    /// Cable speed limit (m/s), the same for the three.
    pub cable_speed: f64,
    /// Cable acceleration limit (m/s²).
    pub cable_acceleration: f64,
    /// Tension bounds per unit mass.
    pub tension: [f64; 2],
    /// Cartesian speed limit (m/s).
    pub speed: f64,
    /// Whether the Cartesian acceleration limit is on (cablenav has none).
    pub cart_acceleration_on: bool,
    /// The integration step (s).
    pub integ_res: f64,
    /// The output's time step (s).
    pub out_res: f64,
}

/// Reads a CSPR3DOF config.dat (input/README_for_config_file.txt: values in a fixed order,
/// `//` comments).
pub fn read_config(text: &str) -> Result<Config, String> {
    let mut words = text.lines().flat_map(|l| l.split("//").next().unwrap_or("").split_whitespace());
    let mut next = || words.next().ok_or_else(|| "config.dat ends early".to_string());
    let num = |w: &str| w.parse::<f64>().map_err(|e| format!("config.dat: {w}: {e}"));
    let robot = next()?;
    if robot != "CSPR3DOF" {
        return Err(format!("robot {robot}, not CSPR3DOF"));
    }
    let _parallel = next()?;
    let joints = num(next()?)? as usize;
    // nCart, trajFileName, isBINfile, pathType, areJntAnglesDegrees
    for _ in 0..5 {
        next()?;
    }
    let mut values = |count: usize| (0..count).map(|_| next().and_then(&num)).collect::<Result<Vec<f64>, String>>();
    let v = values(1 + joints)?; // isJntVelConOn, JntVelLims
    let (vel_on, vel) = (v[0] == 1.0, v[1..].to_vec());
    let v = values(1 + joints)?; // isJntAccConOn, JntAccLims
    let (acc_on, acc) = (v[0] == 1.0, v[1..].to_vec());
    let v = values(1 + 2 * joints)?; // isTrqConOn, JntTrqMax, JntTrqMin
    let (trq_on, trq_max, trq_min) = (v[0] == 1.0, v[1..1 + joints].to_vec(), v[1 + joints..].to_vec());
    // isCartVelConOn, CartVelMax, isCartAccConOn, CartAccMax, integRes, maxIntegTime,
    // inputDecimFact, smoothWindow, is_sdotOut, jntThresh, cartThresh, sWeights (3), scaleType,
    // thetaNormRes, thetaNormRes2, cartNormRes, cartNormRes2, outRes
    let v = values(20)?;
    let (cart_on, cart, cart_acc_on, integ_res, out_res) = (v[0] == 1.0, v[1], v[2] == 1.0, v[4], v[19]);
    let same = |v: &[f64], what: &str| -> Result<f64, String> {
        if v.iter().all(|x| *x == v[0]) {
            Ok(v[0])
        } else {
            Err(format!("{what} differ between cables ({v:?}): cablenav has one limit for all"))
        }
    };
    if !(vel_on && acc_on && trq_on && cart_on) {
        return Err("a constraint of the CSPR3DOF case is off in config.dat".into());
    }
    Ok(Config {
        cable_speed: same(&vel, "cable speed limits")?,
        cable_acceleration: same(&acc, "cable acceleration limits")?,
        tension: [same(&trq_min, "least tensions")?, same(&trq_max, "greatest tensions")?],
        speed: cart,
        cart_acceleration_on: cart_acc_on,
        integ_res,
        out_res,
    })
}

/// g of batotp/config.h (`static const double _g=9.81;`).
pub fn read_gravity(config_h: &str) -> Result<f64, String> {
    let at = config_h.find("_g=").ok_or("no _g= in config.h")?;
    let rest = &config_h[at + 3..];
    rest[..rest.find(';').ok_or("no ; after _g=")?].trim().parse().map_err(|e| format!("_g: {e}"))
}

/// The three base anchors of `findCSPR3DOFpmat` (batotp/robot.cpp), one per cable: the survey
/// points p1 = cible1 + delta1, p2 = cible3 + delta2 and p3, taken as (−y, −x, −z) and centred
/// on their centroid, with the same double operations in the same order.
pub fn anchors() -> [[f64; 3]; 3] {
    let add = |a: [f64; 3], b: [f64; 3]| [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
    let p1 = add([1.0941, -4.9074, 2.5542], [-0.765, 0.112, 3.74]);
    let p2 = add([0.2098, 5.3409, 2.6236], [0.43, 0.125, 3.615]);
    let p3 = [-5.9751, 0.1399, 6.1543];
    let order = [1, 0, 2];
    // pmat[coordinate][cable]
    let mut pmat = [[0.0; 3]; 3];
    for (i, &it) in order.iter().enumerate() {
        pmat[i] = [-p1[it], -p2[it], -p3[it]];
    }
    for row in &mut pmat {
        let centroid = 1.0 / 3.0 * (row[0] + row[1] + row[2]);
        for x in row.iter_mut() {
            *x -= centroid;
        }
    }
    std::array::from_fn(|cable| [pmat[0][cable], pmat[1][cable], pmat[2][cable]])
}

// ---------------------------------------------------------------------------------------------
// The fit: a least-squares uniform cubic B-spline, as Bézier pieces

type V3 = [f64; 3];

fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}

fn comb(terms: &[(f64, V3)]) -> V3 {
    std::array::from_fn(|d| terms.iter().map(|(w, p)| w * p[d]).sum())
}

/// The uniform cubic B-spline's four basis functions on a piece, at s ∈ [0, 1].
fn basis(s: f64) -> [f64; 4] {
    let r = 1.0 - s;
    [r * r * r / 6.0, (3.0 * s * s * s - 6.0 * s * s + 4.0) / 6.0, (-3.0 * s * s * s + 3.0 * s * s + 3.0 * s + 1.0) / 6.0, s * s * s / 6.0]
}

/// Point i of `count` at its own parameter u = pieces·i/(count − 1): (piece, s in it).
fn locate(pieces: usize, i: usize, count: usize) -> (usize, f64) {
    let u = pieces as f64 * i as f64 / (count - 1) as f64;
    let j = (u.floor() as usize).min(pieces - 1);
    (j, u - j as f64)
}

/// The least-squares control points (pieces + 3) of the uniform cubic B-spline with `pieces`
/// pieces through `points` at their own parameters (normal equations, banded Cholesky).
fn fit(points: &[V3], pieces: usize) -> Vec<V3> {
    let m = pieces + 3;
    let mut a = vec![[0.0f64; 4]; m]; // a[i][k] = M[i][i - k], the band below the diagonal
    let mut rhs = vec![[0.0; 3]; m];
    for (i, p) in points.iter().enumerate() {
        let (j, s) = locate(pieces, i, points.len());
        let b = basis(s);
        for r in 0..4 {
            for c in 0..=r {
                a[j + r][r - c] += b[r] * b[c];
            }
            for d in 0..3 {
                rhs[j + r][d] += b[r] * p[d];
            }
        }
    }
    // L·Lᵀ = M, L banded like M: l[i][k] = L[i][i - k]
    let mut l = vec![[0.0f64; 4]; m];
    for i in 0..m {
        let lo = i.saturating_sub(3);
        for j in lo..=i {
            let mut sum = a[i][i - j];
            for q in lo..j {
                sum -= l[i][i - q] * l[j][j - q];
            }
            if j == i {
                assert!(sum > 0.0, "the normal equations of {pieces} pieces are singular");
                l[i][0] = sum.sqrt();
            } else {
                l[i][i - j] = sum / l[j][0];
            }
        }
    }
    let mut y = rhs;
    for i in 0..m {
        for k in 1..4.min(i + 1) {
            let yk = y[i - k];
            for d in 0..3 {
                y[i][d] -= l[i][k] * yk[d];
            }
        }
        let pivot = l[i][0];
        y[i] = y[i].map(|x| x / pivot);
    }
    for i in (0..m).rev() {
        for k in 1..4 {
            if i + k < m {
                let yk = y[i + k];
                for d in 0..3 {
                    y[i][d] -= l[i + k][k] * yk[d];
                }
            }
        }
        let pivot = l[i][0];
        y[i] = y[i].map(|x| x / pivot);
    }
    y
}

/// The cubic Bézier pieces of a uniform cubic B-spline: piece j's four control points; piece j's
/// last point is piece j + 1's first, the same numbers.
fn bezier_pieces(ctrl: &[V3]) -> Vec<[V3; 4]> {
    let pieces = ctrl.len() - 3;
    let joins: Vec<V3> = (0..=pieces).map(|j| comb(&[(1.0 / 6.0, ctrl[j]), (4.0 / 6.0, ctrl[j + 1]), (1.0 / 6.0, ctrl[j + 2])])).collect();
    (0..pieces)
        .map(|j| [joins[j], comb(&[(2.0 / 3.0, ctrl[j + 1]), (1.0 / 3.0, ctrl[j + 2])]), comb(&[(1.0 / 3.0, ctrl[j + 1]), (2.0 / 3.0, ctrl[j + 2])]), joins[j + 1]])
        .collect()
}

/// A curve of cubic Bézier pieces, piece j over u ∈ [j, j + 1]: position and its first two
/// derivatives in u.
fn eval(pieces: &[[V3; 4]], u: f64) -> (V3, V3, V3) {
    let j = (u.max(0.0).floor() as usize).min(pieces.len() - 1);
    let s = u - j as f64;
    let r = 1.0 - s;
    let [p0, p1, p2, p3] = pieces[j];
    let pos = comb(&[(r * r * r, p0), (3.0 * r * r * s, p1), (3.0 * r * s * s, p2), (s * s * s, p3)]);
    let d1 = comb(&[(3.0 * r * r, sub(p1, p0)), (6.0 * r * s, sub(p2, p1)), (3.0 * s * s, sub(p3, p2))]);
    let d2 = comb(&[(6.0 * r, sub(sub(p2, p1), sub(p1, p0))), (6.0 * s, sub(sub(p3, p2), sub(p2, p1)))]);
    (pos, d1, d2)
}

/// Newton's method on |C(u) − p|² from u, kept in [0, pieces]: the distance at the end.
fn refine(pieces: &[[V3; 4]], p: V3, mut u: f64) -> f64 {
    let top = pieces.len() as f64;
    for _ in 0..50 {
        let (c, d1, d2) = eval(pieces, u);
        let e = sub(c, p);
        let g = dot(e, d1);
        let h = dot(d1, d1) + dot(e, d2);
        let step = if h > 0.0 { g / h } else { g / dot(d1, d1).max(1e-300) };
        let next = (u - step).clamp(0.0, top);
        if (next - u).abs() < 1e-15 * top.max(1.0) {
            u = next;
            break;
        }
        u = next;
    }
    norm(sub(eval(pieces, u).0, p))
}

/// The fit's deviation from the points.
#[derive(Debug, Clone, Copy)]
pub struct Deviation {
    /// Greatest distance from a point to the curve (m).
    pub max: f64,
    /// Mean distance (m).
    pub mean: f64,
    /// Greatest distance from a point to the curve at the point's own parameter (m).
    pub max_own: f64,
}

/// The distance from every point to the nearest point of the curve (see the module's doc).
fn deviation(pieces: &[[V3; 4]], points: &[V3]) -> Deviation {
    const SAMPLES: usize = 100;
    let n = pieces.len();
    let samples: Vec<(f64, V3)> = (0..=SAMPLES * n).map(|k| k as f64 / SAMPLES as f64).map(|u| (u, eval(pieces, u).0)).collect();
    let (mut max, mut sum, mut max_own) = (0.0f64, 0.0, 0.0f64);
    for (i, &p) in points.iter().enumerate() {
        let own = n as f64 * i as f64 / (points.len() - 1) as f64;
        let at_own = norm(sub(eval(pieces, own).0, p));
        let nearest = samples.iter().min_by(|a, b| norm(sub(a.1, p)).total_cmp(&norm(sub(b.1, p)))).expect("samples").0;
        let d = refine(pieces, p, own).min(refine(pieces, p, nearest)).min(at_own);
        max = max.max(d);
        sum += d;
        max_own = max_own.max(at_own);
    }
    Deviation { max, mean: sum / points.len() as f64, max_own }
}

/// The greatest distance of the points from the B-spline at their own parameters.
fn own_deviation(ctrl: &[V3], points: &[V3]) -> f64 {
    let pieces = ctrl.len() - 3;
    points
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let (j, s) = locate(pieces, i, points.len());
            let b = basis(s);
            norm(sub(comb(&[(b[0], ctrl[j]), (b[1], ctrl[j + 1]), (b[2], ctrl[j + 2]), (b[3], ctrl[j + 3])]), *p))
        })
        .fold(0.0, f64::max)
}

/// The fit of the path: the fewest uniform pieces within [`FIT_TOL`] at the points' own
/// parameters (else within 1 mm), as Bézier pieces.
pub struct Fit {
    /// The Bézier pieces.
    pub pieces: Vec<[V3; 4]>,
    /// Their deviation from the points.
    pub deviation: Deviation,
    /// The own-parameter deviation of one piece fewer (why not fewer).
    pub fewer: Option<f64>,
}

/// Fits the path's points.
pub fn fit_path(points: &[V3]) -> Result<Fit, String> {
    let mut within_mm = None;
    let mut previous = None;
    let mut chosen = None;
    for n in 1..=MAX_PIECES.min(points.len() - 3) {
        let ctrl = fit(points, n);
        let dev = own_deviation(&ctrl, points);
        if dev <= FIT_TOL {
            chosen = Some((ctrl, previous));
            break;
        }
        if within_mm.is_none() && dev <= 1e-3 {
            within_mm = Some((ctrl, previous));
        }
        previous = Some(dev);
    }
    let (ctrl, fewer) = chosen.or(within_mm).ok_or(format!("no uniform cubic spline of at most {MAX_PIECES} pieces is within 1 mm of the points"))?;
    let pieces = bezier_pieces(&ctrl);
    let deviation = deviation(&pieces, points);
    Ok(Fit { pieces, deviation, fewer })
}

// ---------------------------------------------------------------------------------------------
// The preset

/// A number in JSON, shortest round-trip form (Rust's `Display` of f64 never uses an exponent).
fn num(x: f64) -> String {
    assert!(x.is_finite());
    format!("{x}")
}

fn vec3(v: V3) -> String {
    format!("[{}, {}, {}]", num(v[0]), num(v[1]), num(v[2]))
}

/// The preset's text and the fit behind it.
pub struct Preset {
    /// The scenario file's text.
    pub json: String,
    /// The path's fit.
    pub fit: Fit,
    /// The path's points.
    pub points: usize,
    /// The parameter step between them in the file.
    pub step: f64,
    /// batotp's limits.
    pub config: Config,
    /// batotp's g.
    pub g: f64,
}

/// Builds the preset from the peer's files.
pub fn preset() -> Result<Preset, String> {
    let peer = peer_dir();
    let read = |p: &str| std::fs::read(peer.join(p)).map_err(|e| format!("{}: {e}", peer.join(p).display()));
    let path = read_path(&read("input/CSPR3DOF/CSPR3DOFspline.dat")?)?;
    let config = read_config(&String::from_utf8_lossy(&read("input/CSPR3DOF/config.dat")?))?;
    let g = read_gravity(&String::from_utf8_lossy(&read("batotp/config.h")?))?;
    let fit = fit_path(&path.points)?;
    let cables: Vec<String> = anchors().iter().map(|a| format!("      {{\"base\": {}}}", vec3(*a))).collect();
    let pieces: Vec<String> = fit
        .pieces
        .iter()
        .map(|p| format!("        {{\"translation\": {{\"bezier\": [{}]}}, \"orientation\": {{\"slerp\": [[1, 0, 0, 0], [1, 0, 0, 0]]}}}}", p.map(vec3).join(", ")))
        .collect();
    // the format has no description field: the name says where everything comes from, as the
    // thesis presets' names do
    let name = format!(
        "batotp's CSPR3DOF, Laval's 3-cable point mass: anchors of findCSPR3DOFpmat, limits of config.dat, the path CSPR3DOFspline.dat as {} C² cubic pieces within {:.1e} m of its {} points",
        fit.pieces.len(),
        fit.deviation.max,
        path.points.len()
    );
    let (first, last) = (fit.pieces[0][0], fit.pieces[fit.pieces.len() - 1][3]);
    let json = format!(
        "{{\n  \"format\": \"cablenav-scenario/5\",\n  \"name\": \"{name}\",\n  \"robot\": {{\n    \"mobility\": \"point\",\n    \"cables\": [\n{}\n    ],\n    \"tension\": {{\"min\": {}, \"max\": {}}},\n    \"dynamics\": {{\"mass\": 1, \"gravity\": [0, 0, {}]}},\n    \"winch\": {{\"speed\": {}, \"acceleration\": {}}},\n    \"speed\": {}\n  }},\n  \"poses\": {{\n    \"start\": {{\"position\": {}, \"quaternion\": [1, 0, 0, 0]}},\n    \"end\": {{\"position\": {}, \"quaternion\": [1, 0, 0, 0]}}\n  }},\n  \"trajectories\": [\n    {{\"name\": \"{PATH_NAME}\", \"pieces\": [\n{}\n    ]}}\n  ]\n}}\n",
        cables.join(",\n"),
        num(config.tension[0]),
        num(config.tension[1]),
        num(g),
        num(config.cable_speed),
        num(config.cable_acceleration),
        num(config.speed),
        vec3(first),
        vec3(last),
        pieces.join(",\n"),
    );
    check_written(&json, &fit.pieces)?;
    Ok(Preset { json, fit, points: path.points.len(), step: path.step, config, g })
}

/// The written pieces read back as the same doubles, joins included.
fn check_written(json: &str, pieces: &[[V3; 4]]) -> Result<(), String> {
    let v: serde_json::Value = serde_json::from_str(json).map_err(|e| format!("the preset is not JSON: {e}"))?;
    let written = v["trajectories"][0]["pieces"].as_array().ok_or("no pieces")?;
    for (j, (w, p)) in written.iter().zip(pieces).enumerate() {
        for (k, point) in p.iter().enumerate() {
            for d in 0..3 {
                if w["translation"]["bezier"][k][d].as_f64() != Some(point[d]) {
                    return Err(format!("piece {j} point {k} does not read back as written"));
                }
            }
        }
        if j > 0 && written[j - 1]["translation"]["bezier"][3] != w["translation"]["bezier"][0] {
            return Err(format!("pieces {} and {j} do not share their join", j - 1));
        }
    }
    Ok(())
}

/// `batotp-preset`: writes static/scenarios/laval-cspr3dof.json and prints the fit.
pub fn run_preset() {
    let p = preset().unwrap_or_else(|e| panic!("batotp preset: {e}"));
    std::fs::write(preset_path(), &p.json).unwrap_or_else(|e| panic!("{}: {e}", preset_path().display()));
    let d = p.fit.deviation;
    println!("wrote {} ({} bytes)", preset_path().display(), p.json.len());
    println!(
        "fit: {} uniform cubic pieces (C²); distance from the {} points to the curve: max {:.3e} m, mean {:.3e} m (at their own parameters: max {:.3e} m); {} pieces: {}",
        p.fit.pieces.len(),
        p.points,
        d.max,
        d.mean,
        d.max_own,
        p.fit.pieces.len() - 1,
        p.fit.fewer.map_or("—".into(), |f| format!("max {f:.3e} m at their own parameters"))
    );
    println!("path: {} points {} apart in its parameter", p.points, p.step);
    println!("anchors: {:?}", anchors());
    println!("limits (config.dat): {:?}; g = {}", p.config, p.g);
}

// ---------------------------------------------------------------------------------------------
// batotp's output as a timed spline

/// Each coordinate's natural cubic spline through `y` at spacing h: (velocity, acceleration) at
/// every point (the second derivative 0 at both ends).
fn natural_spline(y: &[f64], h: f64) -> Vec<(f64, f64)> {
    let n = y.len() - 1;
    let mut m = vec![0.0; n + 1];
    if n >= 2 {
        // M[k-1] + 4 M[k] + M[k+1] = 6 (y[k-1] - 2 y[k] + y[k+1]) / h², k = 1 … n-1 (Thomas)
        let mut c = vec![0.0; n + 1];
        let mut d = vec![0.0; n + 1];
        for k in 1..n {
            let r = 6.0 * (y[k - 1] - 2.0 * y[k] + y[k + 1]) / (h * h);
            let denom = 4.0 - c[k - 1];
            c[k] = 1.0 / denom;
            d[k] = (r - d[k - 1]) / denom;
        }
        for k in (1..n).rev() {
            m[k] = d[k] - c[k] * m[k + 1];
        }
    }
    (0..=n)
        .map(|k| {
            let v = if k < n { (y[k + 1] - y[k]) / h - h * (2.0 * m[k] + m[k + 1]) / 6.0 } else { (y[n] - y[n - 1]) / h + h * (m[n - 1] + 2.0 * m[n]) / 6.0 };
            (v, m[k])
        })
        .collect()
}

/// A knot of the timed spline.
#[derive(Debug, Clone, Copy)]
pub struct Knot {
    /// Seconds.
    pub time: f64,
    /// Position, velocity, acceleration.
    pub p: V3,
    /// Velocity.
    pub v: V3,
    /// Acceleration.
    pub a: V3,
}

/// batotp's output as knots: its positions at the time step the file states, with the natural
/// cubic spline's velocities and accelerations.
pub fn knots(out: &Output) -> Vec<Knot> {
    let per: Vec<Vec<(f64, f64)>> = (0..3).map(|c| natural_spline(&out.positions.iter().map(|p| p[c]).collect::<Vec<_>>(), out.step)).collect();
    out.positions
        .iter()
        .enumerate()
        .map(|(k, p)| Knot { time: k as f64 * out.step, p: *p, v: std::array::from_fn(|c| per[c][k].0), a: std::array::from_fn(|c| per[c][k].1) })
        .collect()
}

/// The knots as a format 4 trajectory (JSON).
fn knots_json(name: &str, knots: &[Knot]) -> serde_json::Value {
    let ks: Vec<serde_json::Value> = knots
        .iter()
        .map(|k| serde_json::json!({"time": k.time, "position": k.p, "quaternion": [1, 0, 0, 0], "velocity": k.v, "acceleration": k.a}))
        .collect();
    serde_json::json!({"name": name, "spline": "quintic", "knots": ks})
}

/// The preset with batotp's output added as the trajectory [`OUTPUT_NAME`].
pub fn with_output(preset_json: &str, knots: &[Knot]) -> Result<Scenario, String> {
    let mut v: serde_json::Value = serde_json::from_str(preset_json).map_err(|e| e.to_string())?;
    v["trajectories"].as_array_mut().ok_or("no trajectories")?.push(knots_json(OUTPUT_NAME, knots));
    Scenario::from_json(&v.to_string()).map_err(|e| e.to_string())
}

/// What the limits are at a knot, computed here: the tensions balancing A·τ = g − ẍ (unit mass),
/// the cable speeds and accelerations, the point's speed.
#[derive(Debug, Clone, Copy)]
pub struct AtKnot {
    /// Tensions.
    pub tensions: V3,
    /// Cable speeds l̇.
    pub speeds: V3,
    /// Cable accelerations l̈.
    pub accelerations: V3,
    /// |ẋ|.
    pub speed: f64,
}

/// The limits' quantities at a knot (independently of cablenav's conditions).
pub fn at_knot(k: &Knot, anchors: &[V3; 3], g: f64) -> AtKnot {
    let units: [V3; 3] = std::array::from_fn(|j| {
        let r = sub(k.p, anchors[j]);
        let l = norm(r);
        r.map(|x| x / l)
    });
    let lengths: [f64; 3] = std::array::from_fn(|j| norm(sub(k.p, anchors[j])));
    // Σ τ_j u_j = (0, 0, g) − a, u_j from anchor j to the point (batotp's A matrix)
    let rhs = [-k.a[0], -k.a[1], g - k.a[2]];
    let cols = units;
    let det = |a: V3, b: V3, c: V3| a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
    let d = det(cols[0], cols[1], cols[2]);
    let tensions = [det(rhs, cols[1], cols[2]) / d, det(cols[0], rhs, cols[2]) / d, det(cols[0], cols[1], rhs) / d];
    let speeds: V3 = std::array::from_fn(|j| dot(units[j], k.v));
    let accelerations: V3 = std::array::from_fn(|j| dot(units[j], k.a) + (dot(k.v, k.v) - speeds[j] * speeds[j]) / lengths[j]);
    AtKnot { tensions, speeds, accelerations, speed: norm(k.v) }
}

// ---------------------------------------------------------------------------------------------
// Running batotp

/// One run of batest: what it printed.
#[derive(Debug, Clone, Default)]
pub struct BatotpRun {
    /// "Output trajectory is … sec."
    pub duration: f64,
    /// The forward integration's "traj time." (its time law's duration).
    pub integrated: f64,
    /// "Input data interp." (s)
    pub interp: f64,
    /// "Accel. constraint integ." (s)
    pub integ: f64,
    /// "Total,  without file IO" (s)
    pub total: f64,
    /// "Total,     with file IO" (s)
    pub total_io: f64,
    /// The process's wall time (s).
    pub wall: f64,
    /// Its standard output.
    pub stdout: String,
}

/// The number after `label` on the first line that has it (up to the next space).
fn after(text: &str, label: &str) -> Result<f64, String> {
    let at = text.find(label).ok_or(format!("batest printed no \"{label}\""))?;
    let rest = text[at + label.len()..].trim_start();
    let word: String = rest.chars().take_while(|c| c.is_ascii_digit() || *c == '.' || *c == '-' || *c == 'e').collect();
    word.parse().map_err(|e| format!("\"{label}\" {word}: {e}"))
}

/// Parses batest's printout.
pub fn parse_batest(stdout: &str) -> Result<BatotpRun, String> {
    let fwd = stdout.lines().find(|l| l.starts_with("fwd. integ.:")).ok_or("batest printed no forward integration")?;
    Ok(BatotpRun {
        duration: after(stdout, "Output trajectory is")?,
        integrated: after(fwd, "traj time.")?,
        interp: after(stdout, "Input data interp.      :")?,
        integ: after(stdout, "Accel. constraint integ.:")?,
        total: after(stdout, "Total,  without file IO :")?,
        total_io: after(stdout, "Total,     with file IO :")?,
        wall: 0.0,
        stdout: stdout.to_string(),
    })
}

/// Copies a directory tree, the copies writable.
fn copy_tree(from: &Path, to: &Path) -> std::io::Result<()> {
    std::fs::create_dir_all(to)?;
    for entry in std::fs::read_dir(from)? {
        let entry = entry?;
        let target = to.join(entry.file_name());
        if entry.file_type()?.is_dir() {
            copy_tree(&entry.path(), &target)?;
        } else {
            std::fs::copy(entry.path(), &target)?;
            // the peer's files are read-only; the copies are overwritten (input/config.dat)
            let mut perms = std::fs::metadata(&target)?.permissions();
            #[allow(clippy::permissions_set_readonly_false)]
            perms.set_readonly(false);
            std::fs::set_permissions(&target, perms)?;
        }
    }
    Ok(())
}

/// A copy of the peer built in a temporary directory, removed when dropped.
pub struct Built {
    /// The copy.
    pub dir: PathBuf,
    /// The build's wall time (s).
    pub build_seconds: f64,
    /// g++'s version line.
    pub compiler: String,
}

impl Drop for Built {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.dir);
    }
}

/// Copies and builds the peer as PEER.md says, its CSPR3DOF input in place.
pub fn build() -> Result<Built, String> {
    let dir = std::env::temp_dir().join(format!("cablenav-batotp-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    copy_tree(&peer_dir(), &dir).map_err(|e| format!("copying the peer to {}: {e}", dir.display()))?;
    let built = Built { dir, build_seconds: 0.0, compiler: String::new() };
    let started = Instant::now();
    let out = Command::new("bash").arg("compile.sh").current_dir(&built.dir).output().map_err(|e| format!("compile.sh: {e}"))?;
    let build_seconds = started.elapsed().as_secs_f64();
    if !out.status.success() || !built.dir.join("Release/batest").is_file() {
        return Err(format!(
            "compile.sh failed ({}; g++ and libeigen3-dev: scripts/install.sh --batotp):\n{}{}",
            out.status,
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    for entry in std::fs::read_dir(built.dir.join("input/CSPR3DOF")).map_err(|e| e.to_string())? {
        let entry = entry.map_err(|e| e.to_string())?;
        std::fs::copy(entry.path(), built.dir.join("input").join(entry.file_name())).map_err(|e| e.to_string())?;
    }
    let compiler = Command::new("g++").arg("--version").output().map(|o| String::from_utf8_lossy(&o.stdout).lines().next().unwrap_or("").to_string()).unwrap_or_default();
    let mut built = built;
    built.build_seconds = build_seconds;
    built.compiler = compiler;
    Ok(built)
}

/// Runs `Release/batest` once in the built copy.
pub fn run_batest(built: &Built) -> Result<BatotpRun, String> {
    let started = Instant::now();
    let out = Command::new("./batest").current_dir(built.dir.join("Release")).output().map_err(|e| format!("batest: {e}"))?;
    let wall = started.elapsed().as_secs_f64();
    let stdout = String::from_utf8_lossy(&out.stdout).to_string();
    if !out.status.success() {
        return Err(format!("batest failed ({}):\n{stdout}{}", out.status, String::from_utf8_lossy(&out.stderr)));
    }
    Ok(BatotpRun { wall, ..parse_batest(&stdout)? })
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

// ---------------------------------------------------------------------------------------------
// The comparison

fn ms(s: f64) -> String {
    if s < 0.1 {
        format!("{:.1} ms", s * 1000.0)
    } else {
        format!("{:.0} ms", s * 1000.0)
    }
}

/// The grids cablenav's timing runs on: its default, and about as many cells as batotp's
/// integration takes steps (0.01 s over about 20 s), and twice that.
const CELLS: [usize; 3] = [400, 2000, 4000];

/// A timing's last report and the median time of its runs (s).
type Timed = Result<(TimingReport, f64), String>;

/// cablenav's fastest safe timing of the preset's path on `cells` cells: the last report and the
/// median time of [`RUNS`] runs.
fn cablenav_timing(json: &str, cells: usize) -> Timed {
    let s = Scenario::from_json(json).map_err(|e| format!("the preset: {e}"))?;
    let path = s.trajectories.iter().find(|t| t.name == PATH_NAME).ok_or("the preset has no batotp-path")?;
    let mut times = Vec::new();
    let mut last = None;
    for _ in 0..RUNS {
        let started = Instant::now();
        last = Some(fastest(&s, path, TimingOptions { cells, ..TimingOptions::default() }).map_err(|e| format!("cablenav time: {e}"))?.0);
        times.push(started.elapsed().as_secs_f64());
    }
    Ok((last.expect("runs"), median(times)))
}

/// An infeasible stretch of batotp's output: [start, end] in seconds and the conditions cablenav's
/// per-pose check finds violated just inside its start.
struct Stretch {
    start: f64,
    end: f64,
    violated: Vec<String>,
}

/// cablenav's verification of batotp's output.
struct Verified {
    /// The exact verification.
    report: VerifyReport,
    /// Its time (s).
    seconds: f64,
    /// The per-pose check at every knot.
    checks: Vec<PoseReport>,
    /// The infeasible stretches, named.
    stretches: Vec<Stretch>,
}

/// cablenav's verification of batotp's output: exact (and its time), the per-pose check at every
/// knot, and each infeasible stretch named by the conditions the check finds violated just inside
/// its start (a boundary the verifier could not certify has no label of its own: it is reported
/// as a few nanoseconds of `uncertain`).
fn cablenav_verify(json: &str, ks: &[Knot]) -> Result<Verified, String> {
    let s = with_output(json, ks).map_err(|e| format!("batotp's output as a trajectory: {e}"))?;
    let traj = s.trajectories.iter().find(|t| t.name == OUTPUT_NAME).ok_or("no output trajectory")?;
    let started = Instant::now();
    let report = verify_trajectory(&s, traj).map_err(|e| format!("verifying batotp's output: {e}"))?;
    let seconds = started.elapsed().as_secs_f64();
    let n = ks.len();
    let check = |t: f64| check_along(&s, traj, t).map_err(|e| format!("checking at t = {t}: {e}"));
    let checks = (0..n).map(|k| check(k as f64 / (n - 1) as f64)).collect::<Result<Vec<_>, _>>()?;
    let duration = ks[n - 1].time;
    let infeasible = report.seconds.as_deref().map_or(&[][..], |sec| &sec.infeasible[..]);
    let stretches = infeasible
        .iter()
        .map(|&[start, end]| {
            let inside = start + (1e-6f64).min(0.5 * (end - start));
            Ok(Stretch { start, end, violated: check(inside / duration)?.violated })
        })
        .collect::<Result<Vec<_>, String>>()?;
    Ok(Verified { report, seconds, checks, stretches })
}

/// Distinct strings, in order of first appearance.
fn distinct<'a>(items: impl Iterator<Item = &'a str>) -> Vec<&'a str> {
    let mut out: Vec<&str> = Vec::new();
    for x in items {
        if !out.contains(&x) {
            out.push(x);
        }
    }
    out
}

/// One limit of the case, measured along batotp's output.
struct Limit {
    /// Its name.
    name: &'static str,
    /// Its bound.
    bound: f64,
    /// How far past it a state is (positive: violated): from the quantities at a state.
    excess: fn(&AtKnot, &Config) -> f64,
    /// The bound's scale for "by more than 1 %".
    scale: fn(&Config) -> f64,
}

fn limits(c: &Config) -> Vec<Limit> {
    vec![
        Limit { name: "tension max", bound: c.tension[1], excess: |a, c| a.tensions.into_iter().fold(f64::NEG_INFINITY, f64::max) - c.tension[1], scale: |c| c.tension[1] - c.tension[0] },
        Limit { name: "tension min", bound: c.tension[0], excess: |a, c| c.tension[0] - a.tensions.into_iter().fold(f64::INFINITY, f64::min), scale: |c| c.tension[1] - c.tension[0] },
        Limit { name: "cable speed", bound: c.cable_speed, excess: |a, c| a.speeds.iter().fold(0.0f64, |m, x| m.max(x.abs())) - c.cable_speed, scale: |c| c.cable_speed },
        Limit { name: "cable acceleration", bound: c.cable_acceleration, excess: |a, c| a.accelerations.iter().fold(0.0f64, |m, x| m.max(x.abs())) - c.cable_acceleration, scale: |c| c.cable_acceleration },
        Limit { name: "platform speed", bound: c.speed, excess: |a, c| a.speed - c.speed, scale: |c| c.speed },
    ]
}

/// The state on the knots' cubic spline (each stretch the cubic with the knots' positions,
/// velocities and accelerations; its jerk constant) at `share` ∈ [0, 1] of stretch k.
fn between(ks: &[Knot], k: usize, share: f64) -> Knot {
    let (a, b) = (&ks[k], &ks[k + 1]);
    let h = b.time - a.time;
    let t = share * h;
    let jerk: V3 = std::array::from_fn(|d| (b.a[d] - a.a[d]) / h);
    Knot {
        time: a.time + t,
        p: std::array::from_fn(|d| a.p[d] + a.v[d] * t + a.a[d] * t * t / 2.0 + jerk[d] * t * t * t / 6.0),
        v: std::array::from_fn(|d| a.v[d] + a.a[d] * t + jerk[d] * t * t / 2.0),
        a: std::array::from_fn(|d| a.a[d] + jerk[d] * t),
    }
}

/// Samples per stretch between knots, for the magnitudes of the violations.
const DENSE: usize = 100;

/// `batotp`: the whole comparison, the section's body on stdout.
pub fn run_batotp() {
    let preset = preset().unwrap_or_else(|e| panic!("batotp preset: {e}"));
    let on_disk = std::fs::read_to_string(preset_path()).unwrap_or_default();
    if on_disk != preset.json {
        panic!("{} is not what `cargo run --release --example bench -- batotp-preset` writes from the peer's files: run it", preset_path().display());
    }
    eprintln!("[batotp] building the peer (compile.sh) in a temporary copy");
    let built = build().unwrap_or_else(|e| panic!("{e}"));
    eprintln!("[batotp] built in {:.1} s ({}); running batest {RUNS} times", built.build_seconds, built.compiler);
    let runs: Vec<BatotpRun> = (0..RUNS).map(|_| run_batest(&built).unwrap_or_else(|e| panic!("{e}"))).collect();
    let last = runs.last().expect("runs").clone();
    eprintln!("{}", last.stdout);
    let med = |f: &dyn Fn(&BatotpRun) -> f64| median(runs.iter().map(f).collect());
    let output = read_output(&std::fs::read(built.dir.join("output/traj_out.dat")).expect("batest writes output/traj_out.dat")).unwrap_or_else(|e| panic!("traj_out.dat: {e}"));
    let compiler = built.compiler.clone();
    drop(built);
    let c = &preset.config;
    assert_eq!(output.step, c.out_res, "traj_out.dat's step is config.dat's outRes");

    let timed: Vec<(usize, Timed)> = CELLS
        .iter()
        .map(|&cells| {
            eprintln!("[batotp] cablenav's fastest safe timing on {cells} cells, {RUNS} runs");
            let r = cablenav_timing(&preset.json, cells);
            match &r {
                Ok((r, t)) => eprintln!("[batotp]   {:?} s certified, {} s uncertified, {} cells, {} rounds, {}", r.duration, r.uncertified_duration, r.cells, r.rounds, ms(*t)),
                Err(e) => eprintln!("[batotp]   {e}"),
            }
            (cells, r)
        })
        .collect();

    // batotp's output as knots, and the limits at them and between them computed here
    let ks = knots(&output);
    let n = ks.len();
    let out_duration = ks.last().expect("knots").time;
    let anchors = anchors();
    let at = |k: &Knot| at_knot(k, &anchors, preset.g);
    let own: Vec<AtKnot> = ks.iter().map(at).collect();
    let dense: Vec<AtKnot> = (0..n - 1).flat_map(|k| (0..DENSE).map(move |i| (k, i as f64 / DENSE as f64))).map(|(k, x)| at(&between(&ks, k, x))).chain(std::iter::once(own[n - 1])).collect();
    let dt = output.step / DENSE as f64;
    // the anchors against batotp's own cable lengths (its inverse kinematics, float32)
    let length_diff = output
        .lengths
        .iter()
        .zip(&output.positions)
        .flat_map(|(l, p)| (0..3).map(move |j| (l[j] - norm(sub(*p, anchors[j]))).abs()))
        .fold(0.0f64, f64::max);
    eprintln!("[batotp] cable lengths from the preset's anchors against batotp's: at most {length_diff:.2e} m apart");
    eprintln!("[batotp] verifying batotp's output ({n} knots)");
    let verified = cablenav_verify(&preset.json, &ks);

    // --- the section's body
    let d = preset.fit.deviation;
    println!(
        "The case: batotp's `input/CSPR3DOF` — config.dat's limits (cable speed ≤ {} m/s, cable acceleration ≤ {} m/s², tension in [{}, {}] per unit mass, Cartesian speed ≤ {} m/s; no Cartesian acceleration limit, no length bounds), `dynCSPR3DOF`'s unit point mass under g = {} m/s² along +z (its frame has z down), the anchors `findCSPR3DOFpmat` computes (they give batotp's own cable lengths in traj_out.dat to {:.1e} m, float32), and the path's {} points as a C² uniform cubic spline of {} Bézier pieces: the fewest uniform pieces reproducing every point to 1 µm (batotp's generator made the path as a cubic spline through 20 points, 19 pieces); the points lie at most {:.1e} m from the curve (mean {:.1e} m), their float32 rounding. The preset is `static/scenarios/laval-cspr3dof.json`, written from the peer's files by `cargo run --release --example bench -- batotp-preset`.",
        num(c.cable_speed),
        num(c.cable_acceleration),
        num(c.tension[0]),
        num(c.tension[1]),
        num(c.speed),
        num(preset.g),
        length_diff,
        preset.points,
        preset.fit.pieces.len(),
        d.max,
        d.mean
    );
    println!();
    println!("| planner | duration, rest to rest | where the limits are enforced | compute time |");
    println!("|---|---:|---|---:|");
    println!(
        "| batotp (`Release/batest`; {compiler}, -O3) | {:.3} s printed; its time law (forward integration) {:.3} s | at its {} s integration steps (its output, below, leaves them) | {} without file I/O (input interpolation {}, integration {}), {} with it; the process {} wall (medians of {RUNS} runs) |",
        last.duration,
        last.integrated,
        num(c.integ_res),
        ms(med(&|r| r.total)),
        ms(med(&|r| r.interp)),
        ms(med(&|r| r.integ)),
        ms(med(&|r| r.total_io)),
        ms(med(&|r| r.wall)),
    );
    for (cells, r) in &timed {
        match r {
            Ok((r, t)) => {
                let certified = r.duration.map_or("not certified".to_string(), |x| format!("{x:.3} s certified"));
                println!(
                    "| cablenav (`plan::timing::fastest`, what `cablenav time` runs), {cells} cells{} | {certified} (the grid's optimum {:.3} s; {} cells, {} rounds) | everywhere along the path (certified) | {} (median of {RUNS} runs, both cores) |",
                    if *cells == TimingOptions::default().cells { " (the default)" } else { "" },
                    r.uncertified_duration,
                    r.cells,
                    r.rounds,
                    ms(*t)
                );
            }
            Err(e) => println!("| cablenav, {cells} cells | failed: {e} | — | — |"),
        }
    }
    println!();
    if let Some((_, Ok((r, t)))) = timed.first() {
        // the two targets on the default grid, from this run
        let verdict = |ok: bool| if ok { "**met**" } else { "**not met**" };
        if let Some(d) = r.duration {
            let over = d / last.duration - 1.0;
            println!("Targets, default grid, this run: the certified duration within 1 % of batotp's printed {:.3} s or shorter — {:+.2} %, {}; the compute time no slower than batotp's — {} against {} without file I/O, {}.", last.duration, 100.0 * over, verdict(over <= 0.01), ms(*t), ms(med(&|r| r.total)), verdict(*t <= med(&|r| r.total)));
            println!();
        }
        println!("cablenav's law (default grid) is bound by: {}.", distinct(r.binding.iter().map(|b| b.constraint.as_str())).join("; "));
        println!();
    }
    println!(
        "batotp prints {:.3} s = ({n} − 1) × {} s, the length of its output read at the step the file states; its time law takes {:.3} s: `interpOutputData` places the {n} output points {:.3}/{} = {:.5} s apart, the second and the second-to-last a third of a step from the ends, then writes them with the step {} s.",
        last.duration,
        num(output.step),
        last.integrated,
        last.integrated,
        n - 3,
        last.integrated / (n - 3) as f64,
        num(output.step)
    );
    println!();
    println!(
        "batotp's output, `output/traj_out.dat`, as the file states it ({n} positions {} s apart, {:.2} s): the timed quintic spline `{OUTPUT_NAME}` through them, each knot with the velocity and acceleration of the natural cubic spline through the positions (the interpolation batotp itself uses for the tensions it writes, so the quintic is that cubic spline; it starts at {:.4} m/s and ends at {:.4} m/s, batotp's law at rest). The limits at its {n} points and, sampled {DENSE} times per step, between them (computed here from the spline: A·τ = g − ẍ for the tensions):",
        num(output.step),
        out_duration,
        own[0].speed,
        own[n - 1].speed
    );
    println!();
    println!("| limit | bound | worst at the points | points past it | worst between them | time past it | time past it by over 1 % |");
    println!("|---|---:|---:|---:|---:|---:|---:|");
    let mut any_past = vec![false; dense.len()];
    for l in limits(c) {
        let worst = |v: &[AtKnot]| v.iter().map(|a| (l.excess)(a, c)).fold(f64::NEG_INFINITY, f64::max);
        let value = |e: f64| if l.name == "tension min" { l.bound - e } else { l.bound + e };
        let past = |v: &[AtKnot], by: f64| v.iter().filter(|a| (l.excess)(a, c) > by).count();
        for (flag, a) in any_past.iter_mut().zip(&dense) {
            *flag |= (l.excess)(a, c) > 0.0;
        }
        println!(
            "| {} | {} | {:.3} | {} of {n} | {:.3} | {:.2} s | {:.2} s |",
            l.name,
            num(l.bound),
            value(worst(&own)),
            past(&own, 0.0),
            value(worst(&dense)),
            past(&dense, 0.0) as f64 * dt,
            past(&dense, 0.01 * (l.scale)(c)) as f64 * dt
        );
    }
    let sampled_past = any_past.iter().filter(|x| **x).count() as f64 * dt;
    let clearly: Vec<bool> = dense.iter().map(|a| limits(c).iter().any(|l| (l.excess)(a, c) > 0.01 * (l.scale)(c))).collect();
    let clearly_past = clearly.iter().filter(|x| **x).count() as f64 * dt;
    // the bursts past a limit by over 1 %: (start, end) in seconds
    let mut bursts: Vec<(f64, f64)> = Vec::new();
    for (i, &x) in clearly.iter().enumerate() {
        let t = i as f64 * dt;
        match bursts.last_mut() {
            Some(b) if x && (t - b.1) <= 1.5 * dt => b.1 = t,
            _ if x => bursts.push((t, t)),
            _ => {}
        }
    }
    println!();
    if let Some(tr) = &output.tensions {
        let diffs: Vec<f64> = tr.iter().zip(&own).map(|(b, o)| (0..3).map(|j| (b[j] - o.tensions[j]).abs()).fold(0.0f64, f64::max)).collect();
        // batotp's last few differ more: its own spline's end
        let inner = diffs[..n - 3].iter().fold(0.0f64, |m, x| m.max(*x));
        let ends = diffs[n - 3..].iter().fold(0.0f64, |m, x| m.max(*x));
        let lo = tr.iter().flatten().fold(f64::INFINITY, |m, x| m.min(*x));
        let hi = tr.iter().flatten().fold(f64::NEG_INFINITY, |m, x| m.max(*x));
        let bad = tr.iter().filter(|t| t.iter().any(|x| *x < c.tension[0] || *x > c.tension[1])).count();
        println!(
            "* The tensions batotp writes in traj_out.dat itself lie in [{lo:.3}, {hi:.3}], {bad} of its {n} points outside [{}, {}] (the ones computed here agree to {inner:.1e}, float32 positions, except at the last three points: {ends:.2}).",
            num(c.tension[0]),
            num(c.tension[1])
        );
    }
    match &verified {
        Ok(Verified { report: v, seconds: secs, checks, stretches }) => {
            let bad = checks.iter().filter(|r| !r.feasible).count();
            let own_bad = own.iter().filter(|a| limits(c).iter().any(|l| (l.excess)(a, c) > 0.0)).count();
            let labels = distinct(checks.iter().flat_map(|r| r.violated.iter().map(String::as_str)));
            println!(
                "* cablenav's per-pose check at the {n} points (`verify::check_along`, moving): {bad} violate something (computed here: {own_bad}){}.",
                if labels.is_empty() { String::new() } else { format!(": {}", labels.join(", ")) }
            );
            let sec = v.seconds.as_deref();
            let total: f64 = stretches.iter().map(|x| x.end - x.start).sum();
            let uncertain: f64 = sec.map_or(0.0, |s| s.uncertain.iter().map(|[a, b]| b - a).sum());
            let widest = sec.map_or(0.0, |s| s.uncertain.iter().map(|[a, b]| b - a).fold(0.0, f64::max));
            println!(
                "* Exact verification (`verify::verify_trajectory`, {}): {} infeasible stretches, {:.3} s of the {:.2} s (sampled here: {:.2} s){}{}.",
                ms(*secs),
                stretches.len(),
                total,
                out_duration,
                sampled_past,
                if v.uncertain.is_empty() { String::new() } else { format!("; {} uncertain, each at most {widest:.0e} s wide ({uncertain:.0e} s in all): boundaries between feasible and infeasible that it could not certify", v.uncertain.len()) },
                sec.and_then(|s| s.min_duration).map_or(String::new(), |m| format!("; the least uniform time scale that holds everywhere makes it {m:.3} s"))
            );
            // the check's labels against the computation here, just inside each stretch's start
            let named = stretches
                .iter()
                .filter(|x| {
                    let t = x.start + (1e-6f64).min(0.5 * (x.end - x.start));
                    let k = ((t / output.step) as usize).min(n - 2);
                    let q = at(&between(&ks, k, (t - ks[k].time) / output.step));
                    x.violated.iter().all(|what| {
                        let cable = |j: usize| what.starts_with(&format!("cable {} ", j + 1));
                        (0..3).any(|j| {
                            cable(j)
                                && ((what.ends_with("tension upper bound") && q.tensions[j] > c.tension[1])
                                    || (what.ends_with("tension lower bound") && q.tensions[j] < c.tension[0])
                                    || (what.ends_with("acceleration") && q.accelerations[j].abs() > c.cable_acceleration)
                                    || (what.ends_with("speed") && q.speeds[j].abs() > c.cable_speed))
                        }) || (what == "platform speed" && q.speed > c.speed)
                    }) && !x.violated.is_empty()
                })
                .count();
            println!("* Each stretch named by what cablenav's check finds violated 1 µs inside its start (the computation here agrees at {named} of {}):", stretches.len());
            println!();
            let mut kinds: Vec<(&str, usize, f64)> = Vec::new();
            for x in stretches {
                for what in &x.violated {
                    match kinds.iter_mut().find(|k| k.0 == what) {
                        Some(k) => {
                            k.1 += 1;
                            k.2 += x.end - x.start;
                        }
                        None => kinds.push((what, 1, x.end - x.start)),
                    }
                }
            }
            if !stretches.is_empty() {
                println!("| violated at the stretch's start | stretches | their seconds in all | longest (s) |");
                println!("|---|---:|---:|---|");
                for (what, k, total) in &kinds {
                    let mut mine: Vec<&Stretch> = stretches.iter().filter(|x| x.violated.iter().any(|w| w == what)).collect();
                    mine.sort_by(|x, y| (y.end - y.start).total_cmp(&(x.end - x.start)));
                    let first: Vec<String> = mine.iter().take(3).map(|x| format!("[{:.3}, {:.3}]", x.start, x.end)).collect();
                    println!("| {what} | {k} | {total:.3} | {} |", first.join(", "));
                }
                println!();
            }
        }
        Err(e) => {
            println!("* cablenav could not verify it: {e}.");
            println!();
        }
    }
    // reading it
    let worst_min = dense.iter().enumerate().min_by(|a, b| a.1.tensions.into_iter().fold(f64::INFINITY, f64::min).total_cmp(&b.1.tensions.into_iter().fold(f64::INFINITY, f64::min))).map(|(i, a)| (i as f64 * dt, a.tensions.into_iter().fold(f64::INFINITY, f64::min))).expect("samples");
    println!(
        "Reading it: batotp's law rides its limits, so its output, interpolated between its points as batotp itself interpolates it, is past one of them over {:.1} s of its {:.2} s, mostly by a hair, and by more than 1 % of a bound (of the tension range for the tensions) over {:.2} s, in {} bursts of at most {:.0} ms; the worst is a tension of {:.2} at {:.2} s. The tensions batotp writes show the same.",
        sampled_past,
        out_duration,
        clearly_past,
        bursts.len(),
        1000.0 * bursts.iter().map(|b| b.1 - b.0 + dt).fold(0.0, f64::max),
        worst_min.1,
        worst_min.0
    );
    println!();
    let relative = |r: &TimingReport| r.duration.map(|x| 100.0 * (x / last.integrated - 1.0));
    let said: Vec<String> = timed
        .iter()
        .filter_map(|(cells, r)| r.as_ref().ok().and_then(|(r, _)| relative(r)).map(|p| format!("{:.2} % {} on {cells} cells", p.abs(), if p >= 0.0 { "slower" } else { "faster" })))
        .collect();
    if !said.is_empty() {
        println!(
            "cablenav's law, certified along the whole path, is {} than batotp's time law ({:.3} s): its λ̈ is constant on each cell (about {:.3} s long on the default grid) and its limits are tightened by the relative margin {} at the grid points.",
            said.join(", "),
            last.integrated,
            last.integrated / TimingOptions::default().cells as f64,
            TimingOptions::default().margin
        );
    }
    println!();
}
