//! CASPR model import: the real model files of ../shared/models/caspr (embedded by path at
//! compile time, so this also runs under `wasm-pack test --node`; not copied into the repo) and
//! of tests/data/caspr (CASPR's planar and point-mass examples, copied with their source and
//! license: tests/data/caspr/README.md) against the numbers written in them and against the thesis
//! preset, plus every refusal.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use cablenav::scenario::caspr::{import, kind, model_files, to_json};
use cablenav::verify::check_pose;
use cablenav::Scenario;
use nalgebra::Vector3;

macro_rules! model {
    ($path:literal) => {
        include_str!(concat!("../../shared/models/caspr/", $path))
    };
}

const CDPR7_BODIES: &str = model!("CDPR_7c_6Dof/CDPR_7c_6Dof_bodies.xml");
const CDPR7_CABLES: &str = model!("CDPR_7c_6Dof/CDPR_7c_6Dof_cables.xml");
const NIST_BODIES: &str = model!("NIST_ROBOCRANE/NIST_RoboCrane_bodies.xml");
const NIST_CABLES: &str = model!("NIST_ROBOCRANE/NIST_RoboCrane_cables.xml");
const ARM_BODIES: &str = model!("BMArm/BMArm_bodies.xml");
const ARM_CABLES: &str = model!("BMArm/BMArm_cables.xml");
const EXAMPLE_BODIES: &str = model!("Example_spatial/Example_spatial_bodies.xml");
const EXAMPLE_CABLES: &str = model!("Example_spatial/Example_spatial_cables.xml");
const COGIRO_BODIES: &str = model!("CoGiRo/CoGiRo_bodies.xml");
const COGIRO_CABLES: &str = model!("CoGiRo/CoGiRo_cables.xml");
const COGIRO_TRAJECTORIES: &str = model!("CoGiRo/CoGiRo_trajectories.xml");
const CDPR7_PRESET: &str = include_str!("../static/scenarios/cdpr7.json");

/// A model file of tests/data/caspr (copies of CASPR's, see its README.md).
macro_rules! data {
    ($path:literal) => {
        include_str!(concat!("data/caspr/", $path))
    };
}

const PLANAR_BODIES: &str = data!("Example_planar_XY/Example_planar_XY_bodies.xml");
const PLANAR_CABLES: &str = data!("Example_planar_XY/Example_planar_XY_cables.xml");
const PLANAR_TRAJECTORIES: &str = data!("Example_planar_XY/Example_planar_XY_trajectories.xml");
const POINT_BODIES: &str = data!("Example_point_XZ/Example_point_XZ_bodies.xml");
const POINT_CABLES: &str = data!("Example_point_XZ/Example_point_XZ_cables.xml");
const POINT_TRAJECTORIES: &str = data!("Example_point_XZ/Example_point_XZ_trajectories.xml");
const KNTU_BODIES: &str = data!("KNTU_planar/KNTU_planar_bodies.xml");
const KNTU_CABLES: &str = data!("KNTU_planar/KNTU_planar_cables.xml");
const KNTU_TRAJECTORIES: &str = data!("KNTU_planar/KNTU_planar_trajectories.xml");

fn v(x: f64, y: f64, z: f64) -> Vector3<f64> {
    Vector3::new(x, y, z)
}

#[test]
fn the_thesis_robot_matches_the_preset() {
    let s = import("CDPR_7c_6Dof", CDPR7_BODIES, CDPR7_CABLES).unwrap();
    let preset = Scenario::from_json(CDPR7_PRESET).unwrap();
    assert_eq!(s.robot.cables.len(), 7);
    for (i, (a, b)) in s.robot.cables.iter().zip(&preset.robot.cables).enumerate() {
        assert_eq!((a.base, a.platform), (b.base, b.platform), "cable {}", i + 1);
        assert_eq!((a.tension.min, a.tension.max), (0.0, 1000.0));
        assert_eq!((a.length.min, a.length.max), (0.0, f64::INFINITY));
    }
    assert_eq!(s.robot.diameter, 0.1);
    assert_eq!(s.name, "CDPR_7c_6Dof");
    // q_initial = "2 2 2 0 0 0"
    let p = s.pose("initial").unwrap();
    assert_eq!(p.position, v(2.0, 2.0, 2.0));
    assert!(p.rotation.angle().abs() < 1e-15);
    assert_eq!(s.trajectories.len(), 1);
    assert_eq!(s.trajectories[0].pose_at(0.5).position, v(2.0, 2.0, 2.0));
}

#[test]
fn robocrane_reads_anchors_tensions_and_the_initial_pose() {
    let out = to_json("robocrane", NIST_BODIES, NIST_CABLES).unwrap();
    assert!(out.notes.is_empty(), "{:?}", out.notes);
    let s = Scenario::from_json(&out.json).unwrap();
    let expect_base = [
        v(-3.0, -1.7321, 3.0),
        v(-3.0, -1.7321, 3.0),
        v(3.0, -1.7321, 3.0),
        v(3.0, -1.7321, 3.0),
        v(0.0, 3.4642, 3.0),
        v(0.0, 3.4642, 3.0),
    ];
    let expect_platform =
        [v(0.0, -0.866, 0.0), v(-0.75, 0.433, 0.0), v(0.0, -0.866, 0.0), v(0.75, 0.433, 0.0), v(-0.75, 0.433, 0.0), v(0.75, 0.433, 0.0)];
    let expect_max = [1000.0, 5000.0, 1000.0, 5000.0, 5000.0, 5000.0];
    for (i, c) in s.robot.cables.iter().enumerate() {
        assert_eq!(c.base, expect_base[i], "base {}", i + 1);
        assert_eq!(c.platform, expect_platform[i], "platform {}", i + 1);
        assert_eq!((c.tension.min, c.tension.max), (0.0, expect_max[i]), "tension {}", i + 1);
    }
    // No diameter in the file: the format's default.
    assert_eq!(s.robot.diameter, 0.0);
    assert!(!out.json.contains("diameter"));
    // Lengths at q_initial = (0, 0, 1.5), identity, by hand.
    let p = s.pose("initial").unwrap();
    assert_eq!(p.position, v(0.0, 0.0, 1.5));
    let report = check_pose(&s, "initial", p);
    for (i, l) in report.lengths.iter().enumerate() {
        let by_hand = (expect_base[i] - (expect_platform[i] + v(0.0, 0.0, 1.5))).norm();
        assert!((l - by_hand).abs() < 1e-12, "cable {}: {l} vs {by_hand}", i + 1);
    }
}

#[test]
fn com_attachments_add_the_centre_of_mass_and_angles_are_converted() {
    let bodies = EXAMPLE_BODIES
        .replace("<com_location>0.0 0.0 0.0</com_location>", "<com_location>0.1 0.2 0.3</com_location>")
        .replace("q_initial=\"0.5 0.5 0.5 0 0 0\"", "q_initial=\"0.5 0.5 0.5 0 0 1.5707963267948966\"");
    assert_ne!(bodies, EXAMPLE_BODIES, "the test edits must apply");
    let s = import("example", &bodies, EXAMPLE_CABLES).unwrap();
    // cable 1: attachment_reference="com", platform location (-0.15, -0.1, 0.05)
    assert!((s.robot.cables[0].platform - v(-0.05, 0.1, 0.35)).norm() < 1e-15);
    assert_eq!(s.robot.cables[0].base, v(0.0, 0.0, 1.0));
    assert_eq!((s.robot.cables[0].tension.min, s.robot.cables[0].tension.max), (5.0, 300.0));
    // γ = π/2 about z: the platform x axis points along world y.
    let r = s.pose("initial").unwrap().matrix();
    assert!((r * v(1.0, 0.0, 0.0) - v(0.0, 1.0, 0.0)).norm() < 1e-12);
}

#[test]
fn per_cable_tensions_when_only_some_cables_give_them() {
    let cables = NIST_CABLES.replacen("<force_min>0.0</force_min>", "", 1);
    let out = to_json("n", NIST_BODIES, &cables).unwrap();
    let s = Scenario::from_json(&out.json).unwrap();
    assert_eq!(s.robot.cables[0].tension.min, 0.0); // the format's default
    assert_eq!(s.robot.cables[0].tension.max, 1000.0);
    assert_eq!(s.robot.cables[1].tension.max, 5000.0);
}

#[test]
fn files_are_recognised_by_their_root() {
    assert_eq!(kind(NIST_BODIES), Some("bodies"));
    assert_eq!(kind(NIST_CABLES), Some("cables"));
    assert_eq!(kind("<trajectories/>"), Some("trajectories"));
    assert_eq!(kind("<operational_spaces/>"), None);
    assert_eq!(kind("not xml"), None);
}

fn err(bodies: &str, cables: &str) -> cablenav::Error {
    to_json("x", bodies, cables).expect_err("an error")
}

#[test]
fn refusals_name_the_file_and_say_why() {
    // a multi-link robot is imported (tests/chain.rs); one with a joint type it cannot move by is not
    let e = err(&ARM_BODIES.replace("R_X", "UNIVERSAL_XY"), NIST_CABLES);
    assert_eq!(e.field, "bodies");
    assert!(e.reason.contains("UNIVERSAL_XY") && e.reason.contains("multi-link"), "{e}");

    let e = err(NIST_CABLES, NIST_CABLES);
    assert_eq!(e.field, "bodies");
    assert!(e.reason.contains("<cables>"), "{e}");

    let e = err(NIST_BODIES, "<cables><cable_set id=\"a\">");
    assert_eq!(e.field, "cables");
    assert!(e.reason.contains("not well-formed"), "{e}");

    let e = err(&NIST_BODIES.replace("SPATIAL_EULER_XYZ", "R_X"), NIST_CABLES);
    assert!(e.reason.contains("R_X") && e.reason.contains("line 6"), "{e}");

    let e = err(&NIST_BODIES.replace("q_initial=\"0 0 1.5 0 0 0\"", "q_initial=\"0 0 x 0 0 0\""), NIST_CABLES);
    assert!(e.reason.contains("\"x\" is not a finite number"), "{e}");

    let e = err(NIST_BODIES, &NIST_CABLES.replace("default_cable_set=\"original\"", "default_cable_set=\"other\""));
    assert_eq!(e.field, "cables");
    assert!(e.reason.contains("\"other\""), "{e}");

    let e = err(NIST_BODIES, &NIST_CABLES.replacen("<link>1</link>", "<link>2</link>", 1));
    assert!(e.reason.contains("cable \"cable 1\"") && e.reason.contains("link 2"), "{e}");

    let e = err(NIST_BODIES, &NIST_CABLES.replacen("<location>0 -0.8660 0</location>", "<location>0 -0.8660</location>", 1));
    assert!(e.reason.contains("needs 3 numbers"), "{e}");

    let three = NIST_CABLES.replacen(
        "</attachments>",
        "<attachment><link>1</link><location>0 0 0</location></attachment></attachments>",
        1,
    );
    let e = err(NIST_BODIES, &three);
    assert!(e.reason.contains("3 attachments"), "{e}");

    // Fewer than 6 cables is the scenario's own error, at its field.
    let mut five = NIST_CABLES.to_string();
    let last = five.rfind("<cable_ideal").unwrap();
    let end = five.rfind("</cable_ideal>").unwrap() + "</cable_ideal>".len();
    five.replace_range(last..end, "");
    let e = import("x", NIST_BODIES, &five).expect_err("5 cables");
    assert_eq!(e.field, "robot.cables");
}

/// Every model of CASPR's multi-link library imports, with every joint type it uses and its
/// cables routed as written (format 6: cables from the base or from a link, over any links, to a
/// link): links, cables, segments, cables starting on a link and cables routed through anchors
/// counted from the files; its links' masses with closure left out (`robot.closure` false);
/// Spatial_Tree (a spatial end effector and a fixed tree) imports whole; R_AXIS keeps its axis,
/// normalised.
#[test]
fn every_joint_type_of_the_library_is_read() {
    for (name, bodies, cables, joint, [links, cables_n, segments, from_link, via]) in [
        ("4U_modular_units_arm", model!("4U_modular_units_arm/4U_modular_units_arm_bodies.xml"), model!("4U_modular_units_arm/4U_modular_units_arm_cables.xml"), "U_YZ", [4, 12, 12, 9, 0]),
        ("SJTUSnake", model!("SJTUSnake/SJTUSnake_bodies.xml"), model!("SJTUSnake/SJTUSnake_cables.xml"), "U_XZ", [12, 36, 432, 0, 33]),
        ("BioBiped_one_leg", model!("BioBiped_one_leg/BioBiped_one_leg_bodies.xml"), model!("BioBiped_one_leg/BioBiped_one_leg_cables.xml"), "PLANAR_YZ", [4, 9, 9, 9, 0]),
        ("RoboyLeftArm", model!("RoboyLeftArm/RoboyLeftArm_bodies.xml"), model!("RoboyLeftArm/RoboyLeftArm_cables.xml"), "R_AXIS", [4, 11, 11, 2, 0]),
        ("8S_neck", model!("8S_neck/8S_neck_bodies.xml"), model!("8S_neck/8S_neck_cables.xml"), "S_EULER_XYZ", [8, 76, 102, 30, 8]),
        ("CAREX", model!("CAREX/CAREX_bodies.xml"), model!("CAREX/CAREX_cables.xml"), "R_Y", [2, 6, 8, 0, 2]),
    ] {
        assert!(bodies.contains(joint));
        let imported = to_json(name, bodies, cables).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(imported.json.contains("cablenav-scenario/6"), "{name}");
        let s = Scenario::from_json(&imported.json).unwrap_or_else(|e| panic!("{name}: {e}"));
        let chain = s.robot.chain.as_ref().unwrap();
        let counted = [
            chain.links.len(),
            s.robot.cables.len(),
            s.robot.segments().len(),
            s.robot.cables.iter().filter(|c| c.from.is_some()).count(),
            s.robot.cables.iter().filter(|c| !c.via.is_empty()).count(),
        ];
        assert_eq!(counted, [links, cables_n, segments, from_link, via], "{name}: links, cables, segments, from a link, routed");
        assert!(chain.is_loaded() && !chain.closure, "{name}: weighed, closure left out");
        assert!(imported.notes.iter().any(|n| n.contains("robot.closure")), "{name}: {:?}", imported.notes);
    }
    // CAREX's elbow range as written, −3.416 to 3.1416, is wider than a turn: one turn, with a note
    let carex = to_json("CAREX", model!("CAREX/CAREX_bodies.xml"), model!("CAREX/CAREX_cables.xml")).unwrap();
    assert!(carex.notes.iter().any(|n| n.contains("-3.416") && n.contains("wider than one turn")), "{:?}", carex.notes);
    let tree = to_json("Spatial_Tree", model!("Spatial_Tree/Spatial_Tree_bodies.xml"), model!("Spatial_Tree/Spatial_Tree_cables.xml")).expect("Spatial_Tree imports");
    let s = Scenario::from_json(&tree.json).expect("and validates");
    let chain = s.robot.chain.as_ref().unwrap();
    assert_eq!(chain.links[0].joint, cablenav::model::Joint::Spatial);
    assert_eq!(chain.links[0].coords.iter().map(|c| c.name.as_str()).collect::<Vec<_>>(), ["x", "y", "z", "alpha", "beta", "gamma"]);
    assert_eq!(chain.links[1].joint, cablenav::model::Joint::Revolute(Vector3::x()));
    // the end effector sits where its q_initial puts it: (1, 2, 1), unrotated
    let (o, r) = chain.frames(&s.config("initial").unwrap())[0];
    assert!((o - v(1.0, 2.0, 1.0)).norm() < 1e-12 && (r - nalgebra::Matrix3::identity()).norm() < 1e-12, "{o} {r}");
    // R_AXIS about a written axis, normalised
    let axis = ARM_BODIES.replacen("type=\"R_X\"", "type=\"R_AXIS\" axis=\"0 3 4\"", 1);
    let arm = Scenario::from_json(&to_json("arm", &axis, ARM_CABLES).expect("imports").json).unwrap();
    assert!(arm.robot.chain.as_ref().unwrap().links.iter().any(|l| l.joint == cablenav::model::Joint::Revolute(Vector3::new(0.0, 0.6, 0.8))));
    let e = err(&ARM_BODIES.replacen("type=\"R_X\"", "type=\"R_AXIS\"", 1), ARM_CABLES);
    assert!(e.reason.contains("R_AXIS") && e.reason.contains("no axis"), "{e}");
}

/// The platform's physical data comes along (format 4): CoGiRo's mass, centre of mass and
/// inertia about it as written, CASPR's gravity; the model holds itself at its initial pose.
#[test]
fn physical_data_becomes_the_platforms_dynamics() {
    let imported = to_json("CoGiRo", COGIRO_BODIES, COGIRO_CABLES).unwrap();
    assert!(imported.json.contains("cablenav-scenario/4"));
    let s = import("CoGiRo", COGIRO_BODIES, COGIRO_CABLES).unwrap();
    let d = s.robot.dynamics.as_ref().expect("CoGiRo has a mass");
    assert_eq!(d.mass, 91.058);
    assert_eq!(d.com, v(-0.034, -0.013, 0.264));
    assert_eq!((d.inertia[(0, 0)], d.inertia[(1, 1)], d.inertia[(2, 2)]), (36.598, 35.982, 25.439));
    assert_eq!((d.inertia[(0, 1)], d.inertia[(0, 2)], d.inertia[(1, 2)]), (-0.453, 3.012, -1.539));
    assert_eq!(d.inertia, d.inertia.transpose());
    assert_eq!(d.gravity, v(0.0, 0.0, -9.81));
    assert_eq!(s.robot.cables.len(), 8);
    let report = check_pose(&s, "initial", s.pose("initial").unwrap());
    let w = report.wrench.expect("a mass brings the tension conditions");
    assert!(w.feasible && w.margin.unwrap() > 100.0, "{w:?}");
    // an inertia about the joint is moved to the centre of mass: I_com = I_joint − m(|c|²E − ccᵀ)
    let about_joint = COGIRO_BODIES.replace(r#"<inertia ref="com">"#, r#"<inertia ref="joint">"#);
    let moved = import("CoGiRo", &about_joint, COGIRO_CABLES).unwrap().robot.dynamics.unwrap();
    let c = d.com;
    let shift = (nalgebra::Matrix3::identity() * c.norm_squared() - c * c.transpose()) * d.mass;
    assert!((moved.inertia - (d.inertia - shift)).amax() < 1e-12);
    // no rigid body: imported massless, with a note
    let flat = COGIRO_BODIES.replace("<Ixx>36.598</Ixx>", "<Ixx>-1</Ixx>");
    let massless = to_json("CoGiRo", &flat, COGIRO_CABLES).unwrap();
    assert!(massless.json.contains("cablenav-scenario/1") && massless.notes.iter().any(|n| n.contains("massless")), "{:?}", massless.notes);
}

#[test]
fn a_model_directory_names_its_files() {
    let names = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    let files = model_files(&names(&["NIST_RoboCrane_cables.xml", "NIST_RoboCrane_bodies.xml", "NIST_RoboCrane_operational_spaces.xml"])).unwrap();
    assert_eq!((files.name.as_str(), files.bodies.as_str(), files.cables.as_str()), ("NIST_RoboCrane", "NIST_RoboCrane_bodies.xml", "NIST_RoboCrane_cables.xml"));
    assert_eq!(model_files(&names(&["a_cables.xml"])).unwrap_err().field, "model");
    assert!(model_files(&names(&["a_bodies.xml", "b_bodies.xml"])).unwrap_err().reason.contains("exactly one"));
    assert!(model_files(&names(&["a_bodies.xml", "b_cables.xml"])).unwrap_err().reason.contains("a_cables.xml"));
}

/// CASPR's trajectories file: its splines become timed trajectories through knots (relative or
/// absolute times, the parent location added), other kinds are skipped with a note, and an
/// angular rate at a knot or an unknown time definition is refused naming the file and line.
#[test]
fn trajectories_import_as_timed_splines() {
    use cablenav::scenario::caspr::model_to_json;
    let out = model_to_json("CoGiRo", COGIRO_BODIES, COGIRO_CABLES, Some(COGIRO_TRAJECTORIES), None).unwrap();
    assert!(out.notes.is_empty(), "{:?}", out.notes);
    let s = Scenario::from_json(&out.json).unwrap();
    let names: Vec<&str> = s.trajectories.iter().map(|t| t.name.as_str()).collect();
    assert_eq!(names, ["hold initial", "general_1", "general_2", "general_3", "long_stable"]);
    let long = s.trajectory(Some("long_stable")).unwrap();
    assert_eq!((long.duration, long.piece_count()), (Some(18.0), 9));
    let knots = long.knots.as_ref().unwrap();
    assert_eq!(knots.points[3].pose.position, Vector3::new(0.0, 2.0, 0.0));
    let first = s.trajectory(Some("general_1")).unwrap().knots.clone().unwrap();
    let got = first.points[0].pose.rotation.to_rotation_matrix();
    let rx = nalgebra::Rotation3::from_axis_angle(&Vector3::x_axis(), -0.5);
    let ry = nalgebra::Rotation3::from_axis_angle(&Vector3::y_axis(), 0.2);
    let rz = nalgebra::Rotation3::from_axis_angle(&Vector3::z_axis(), 0.3);
    assert!((got.matrix() - (rx * ry * rz).matrix()).norm() < 1e-12, "R = Rx(a)·Ry(b)·Rz(g)");
    // absolute times, a skipped kind, an operational trajectory
    let xml = COGIRO_TRAJECTORIES
        .replacen("time_definition=\"relative\"", "time_definition=\"absolute\"", 1)
        .replacen("<point time=\"2.0\">", "<point time=\"1.5\">", 1)
        .replacen("<quintic_spline_trajectory id=\"general_2\"", "<linear_spline_trajectory id=\"general_2\"", 1)
        .replacen("</quintic_spline_trajectory>\n        <quintic_spline_trajectory id=\"general_3\"", "</linear_spline_trajectory>\n        <quintic_spline_trajectory id=\"general_3\"", 1)
        .replace("</trajectories>", "<operational_trajectories/></trajectories>");
    let out = model_to_json("c", COGIRO_BODIES, COGIRO_CABLES, Some(&xml), None).unwrap();
    assert!(out.notes.iter().any(|n| n.contains("linear_spline_trajectory id=\"general_2\"") && n.contains("skipped")), "{:?}", out.notes);
    assert!(out.notes.iter().any(|n| n.contains("operational_trajectories")), "{:?}", out.notes);
    let s = Scenario::from_json(&out.json).unwrap();
    let g1 = s.trajectory(Some("general_1")).unwrap();
    // absolute: knots at 0, 1.5 and 2.0 s
    assert_eq!(g1.knots.as_ref().unwrap().points.iter().map(|k| k.time).collect::<Vec<_>>(), [0.0, 1.5, 2.0]);
    // refusals
    let spin = COGIRO_TRAJECTORIES.replacen("<q_dot>0.0 0.0 0.0 0.0 0.0 0.0</q_dot>", "<q_dot>0.0 0.0 0.0 0.1 0.0 0.0</q_dot>", 1);
    let e = model_to_json("c", COGIRO_BODIES, COGIRO_CABLES, Some(&spin), None).unwrap_err();
    assert!(e.field == "trajectories" && e.reason.contains("line 7") && e.reason.contains("angular rate"), "{e}");
    let odd = COGIRO_TRAJECTORIES.replacen("time_definition=\"relative\"", "time_definition=\"soon\"", 1);
    let e = model_to_json("c", COGIRO_BODIES, COGIRO_CABLES, Some(&odd), None).unwrap_err();
    assert!(e.field == "trajectories" && e.reason.contains("soon"), "{e}");
    let e = model_to_json("c", COGIRO_BODIES, COGIRO_CABLES, Some("<bodies_system/>"), None).unwrap_err();
    assert!(e.field == "trajectories" && e.reason.contains("<trajectories>"), "{e}");
    let bad_time = COGIRO_TRAJECTORIES.replacen("<point time=\"2.0\">", "<point time=\"later\">", 1);
    let e = model_to_json("c", COGIRO_BODIES, COGIRO_CABLES, Some(&bad_time), None).unwrap_err();
    assert!(e.reason.contains("finite time"), "{e}");
    // a multi-link model's trajectories are its joints' (tests/joint_splines.rs): another
    // model's file, of six coordinates for the arm's four, is refused naming the point
    let e = model_to_json("arm", ARM_BODIES, ARM_CABLES, Some(COGIRO_TRAJECTORIES), None).unwrap_err();
    assert!(e.field == "trajectories" && e.reason.contains("point 0 of \"general_1\" needs 4 numbers"), "{e}");
}

/// CASPR's Example_planar_XY (a `PLANAR_XY` joint: q = x y θ, θ about z) imports as a planar
/// robot (format 5): its anchors, tension bounds, mass and inertia as written, the pose `initial`
/// at q_initial, and its quintic and cubic splines as knots in the plane z = 0 turning about z only
/// (the other kinds skipped with a note); `verify` runs on it and agrees with CASPR's names: the
/// trajectory "example_quintic" is feasible, "example_infeasible" is not where it stops at x = 1.
#[test]
fn the_planar_example_imports_as_a_planar_robot() {
    use cablenav::model::Mobility;
    use cablenav::scenario::caspr::model_to_json;
    let out = model_to_json("Example_planar_XY", PLANAR_BODIES, PLANAR_CABLES, Some(PLANAR_TRAJECTORIES), None).unwrap();
    for skipped in ["example_linear", "example_cubic_average_velocity", "example_parabolic_blend", "example_file"] {
        assert!(out.notes.iter().any(|n| n.contains(&format!("id=\"{skipped}\"")) && n.contains("skipped")), "{skipped}: {:?}", out.notes);
    }
    assert!(out.notes.iter().any(|n| n.contains("cable set \"basic\" of 3")), "{:?}", out.notes);
    assert_eq!(out.notes.len(), 5, "{:?}", out.notes);

    // the JSON as written: format 5, every position in z = 0, every rotation about z
    let json: serde_json::Value = serde_json::from_str(&out.json).unwrap();
    assert_eq!(json["format"], "cablenav-scenario/5");
    assert_eq!(json["robot"]["mobility"], "planar");
    assert_eq!(json["poses"]["initial"]["position"], serde_json::json!([0.5, 0.5, 0.0]));
    assert_eq!(json["poses"]["initial"]["euler_xyz_deg"], serde_json::json!([0.0, 0.0, 0.0]));
    let mut knots = 0;
    for t in json["trajectories"].as_array().unwrap() {
        for k in t["knots"].as_array().into_iter().flatten() {
            knots += 1;
            assert_eq!(k["position"][2], 0.0, "{k}");
            assert_eq!((&k["euler_xyz_deg"][0], &k["euler_xyz_deg"][1]), (&0.0.into(), &0.0.into()), "{k}");
            assert_eq!(k["velocity"][2], 0.0, "{k}");
        }
    }
    assert_eq!(knots, 2 + 2 + 3 + 3 + 3 + 3 + 2 + 3 + 3);

    // the scenario
    let s = Scenario::from_json(&out.json).unwrap();
    assert_eq!(s.robot.mobility, Mobility::Planar);
    let bases = [v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), v(1.0, 1.0, 0.0), v(0.0, 1.0, 0.0)];
    let platforms = [v(-0.125, 0.0, 0.0), v(0.125, 0.0, 0.0), v(0.125, 0.0, 0.0), v(-0.125, 0.0, 0.0)];
    assert_eq!(s.robot.cables.len(), 4);
    for (i, c) in s.robot.cables.iter().enumerate() {
        assert_eq!((c.base, c.platform), (bases[i], platforms[i]), "cable {}", i + 1);
        assert_eq!((c.tension.min, c.tension.max), (0.01, 1000.0), "cable {}", i + 1);
    }
    let d = s.robot.dynamics.as_ref().expect("mass 10");
    assert_eq!((d.mass, d.com, d.gravity), (10.0, v(0.0, 0.0, 0.0), v(0.0, 0.0, -9.81)));
    assert_eq!(d.inertia, nalgebra::Matrix3::identity() * 10.0);
    let initial = s.pose("initial").unwrap();
    assert_eq!(initial.position, v(0.5, 0.5, 0.0));
    assert_eq!(initial.rotation.angle(), 0.0);
    let names: Vec<&str> = s.trajectories.iter().map(|t| t.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "hold initial",
            "example_cubic",
            "example_quintic",
            "example_infeasible",
            "example_inside",
            "setpoint_eMPC_infeasible",
            "example_outside1",
            "example_outside1_alt",
            "example_outside2",
            "example_outside3"
        ]
    );
    for t in &s.trajectories {
        for k in t.knots.iter().flat_map(|k| &k.points) {
            assert_eq!(k.pose.position.z, 0.0, "{}", t.name);
            assert_eq!((k.pose.rotation.i, k.pose.rotation.j), (0.0, 0.0), "{}: a rotation about z", t.name);
        }
    }
    // relative times; θ = 0.3 about z at the end of example_outside3
    let inside = s.trajectory(Some("example_inside")).unwrap().knots.as_ref().unwrap();
    assert_eq!(inside.points.iter().map(|k| k.time).collect::<Vec<_>>(), [0.0, 5.0, 10.0]);
    let turned = s.trajectory(Some("example_outside3")).unwrap().knots.as_ref().unwrap().points[2].pose;
    assert_eq!(turned.position, v(0.3, 0.5, 0.0));
    let about_z = nalgebra::UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 0.3);
    assert!(turned.rotation.angle_to(&about_z) < 1e-12, "{:?}", turned.rotation);
    assert_eq!(s.trajectory(Some("example_cubic")).unwrap().duration, Some(5.0));

    // verify: the wrench conditions in fx, fy, mz
    let report = check_pose(&s, "initial", initial);
    assert!(report.wrench.as_ref().is_some_and(|w| w.feasible), "{:?}", report.wrench);
    let quintic = cablenav::verify::verify_trajectory(&s, s.trajectory(Some("example_quintic")).unwrap()).unwrap();
    assert_eq!((quintic.feasible.as_slice(), quintic.uncertain.len()), (&[[0.0, 1.0]][..], 0), "{quintic:?}");
    // it stops at x = 1 (t = 0.5), where all four cables pull towards −x: no tension balances that
    let stop = cablenav::verify::verify_trajectory(&s, s.trajectory(Some("example_infeasible")).unwrap()).unwrap();
    assert!(stop.infeasible.iter().any(|[a, b]| *a < 0.5 && 0.5 < *b), "{stop:?}");
    assert!(stop.feasible.iter().any(|[a, _]| *a == 0.0), "{stop:?}");

    // another cable set of the file
    let cross = Scenario::from_json(&model_to_json("x", PLANAR_BODIES, PLANAR_CABLES, None, Some("basic_cross")).unwrap().json).unwrap();
    assert_eq!(cross.robot.cables[0].platform, v(-0.1, 0.05, 0.0));
    assert_eq!(cross.robot.mobility, Mobility::Planar);
}

/// KNTU_planar (also `PLANAR_XY`) imports too; its inertia (Izz alone) is not positive definite,
/// which a planar platform would not need but `robot.dynamics` does: imported massless, and the
/// note says why.
#[test]
fn kntu_planar_imports_massless_with_a_note() {
    use cablenav::scenario::caspr::model_to_json;
    let out = model_to_json("KNTU_planar", KNTU_BODIES, KNTU_CABLES, Some(KNTU_TRAJECTORIES), None).unwrap();
    assert!(out.notes.iter().any(|n| n.contains("massless") && n.contains("turns about z only")), "{:?}", out.notes);
    assert!(out.notes.iter().any(|n| n.contains("no quintic or cubic spline")), "{:?}", out.notes);
    let s = Scenario::from_json(&out.json).unwrap();
    assert_eq!(s.robot.mobility, cablenav::model::Mobility::Planar);
    assert!(s.robot.dynamics.is_none());
    assert_eq!(s.robot.cables[1].base, v(-1.12, 1.05, 0.0));
    assert_eq!(s.robot.cables[2].platform, v(0.15, 0.0, 0.0));
    assert_eq!(s.robot.cables[3].tension.max, 60.0);
    assert!(check_pose(&s, "initial", s.pose("initial").unwrap()).feasible);
}

/// What a planar import refuses, naming the element: anything out of the plane z = 0, a turn of
/// half a turn or more between two points of a spline, an angular rate at a point, a `q` of the
/// wrong length, and planar joints in other planes.
#[test]
fn planar_refusals_name_the_element() {
    use cablenav::scenario::caspr::model_to_json;
    let e = err(PLANAR_BODIES, &PLANAR_CABLES.replacen("<location>1.0 1.0 0.0</location>", "<location>1.0 1.0 0.2</location>", 1));
    assert!(e.field == "cables" && e.reason.contains("cable \"cable 3\" (line 38)") && e.reason.contains("base anchor") && e.reason.contains("z = 0"), "{e}");
    let e = err(PLANAR_BODIES, &PLANAR_CABLES.replacen("<location>0.125 0 0</location>", "<location>0.125 0 0.01</location>", 1));
    assert!(e.field == "cables" && e.reason.contains("cable \"cable 2\"") && e.reason.contains("platform anchor"), "{e}");
    let high = PLANAR_BODIES.replace("<location>0.0 0.0 0.0</location>", "<location>0.0 0.0 1.0</location>");
    let e = err(&high, PLANAR_CABLES);
    assert!(e.field == "bodies" && e.reason.contains("line 21") && e.reason.contains("z = 1"), "{e}");
    let e = err(&PLANAR_BODIES.replace("<com_location>0.0 0.0 0.0</com_location>", "<com_location>0.0 0.0 0.1</com_location>"), PLANAR_CABLES);
    assert!(e.field == "bodies" && e.reason.contains("centre of mass"), "{e}");
    let e = err(&PLANAR_BODIES.replace("q_initial=\"0.5 0.5 0\"", "q_initial=\"0.5 0.5 0 0 0 0\""), PLANAR_CABLES);
    assert!(e.reason.contains("line 7") && e.reason.contains("needs 3 numbers"), "{e}");
    for other in ["PLANAR_XZ", "PLANAR_YZ"] {
        let e = err(&PLANAR_BODIES.replace("PLANAR_XY", other), PLANAR_CABLES);
        assert!(e.field == "bodies" && e.reason.contains(&format!("line 7: <joint type=\"{other}\">")) && e.reason.contains("plane z = 0"), "{e}");
    }
    let traj = |xml: &str| model_to_json("x", PLANAR_BODIES, PLANAR_CABLES, Some(xml), None).unwrap_err();
    let e = traj(&PLANAR_TRAJECTORIES.replace("<q>0.3 0.5 0.3</q>", "<q>0.3 0.5 3.3</q>"));
    assert!(e.field == "trajectories" && e.reason.contains("example_outside3") && e.reason.contains("half a turn"), "{e}");
    let e = traj(&PLANAR_TRAJECTORIES.replacen("<q_dot>0.0 0.0 0.0</q_dot>", "<q_dot>0.1 0.0 0.2</q_dot>", 1));
    assert!(e.reason.contains("line 17") && e.reason.contains("angular rate"), "{e}");
    let e = traj(&PLANAR_TRAJECTORIES.replacen("<q>0.3 0.5 0.0</q>\n                    <q_dot>", "<q>0.3 0.5 0.0 0</q>\n                    <q_dot>", 1));
    assert!(e.reason.contains("needs 3 numbers"), "{e}");
}

/// CASPR's Example_point_XZ (`P_XZ`: a point moving in the XZ plane, 2 DoF) is refused naming the
/// joint: cablenav's point masses move in 3-D, and its cables, all in the plane y = 0, could not
/// hold one across it; `P_XY` (2_DoF_VSD) likewise.
#[test]
fn the_point_example_is_refused_naming_its_joint() {
    use cablenav::scenario::caspr::model_to_json;
    let e = model_to_json("Example_point_XZ", POINT_BODIES, POINT_CABLES, Some(POINT_TRAJECTORIES), None).unwrap_err();
    assert_eq!(e.field, "bodies");
    assert!(e.reason.starts_with("line 6: <joint type=\"P_XZ\">: a point moving in the XZ plane (2 DoF) is not supported"), "{e}");
    assert!(e.reason.contains("T_XYZ") && e.reason.contains("PLANAR_XY"), "{e}");
    let e = err(&POINT_BODIES.replace("P_XZ", "P_XY"), POINT_CABLES);
    assert!(e.reason.contains("<joint type=\"P_XY\">") && e.reason.contains("XY plane"), "{e}");
}

/// CASPR's 3-D translational joint `T_XYZ` (q = x y z; no model of CASPR's uses it, so
/// Example_point_XZ is edited into one) imports as a point mass (format 5 mobility "point"): the
/// cables omit their platform anchor, the dynamics the inertia and centre of mass, poses and knots
/// their orientation. Cables must all end at one point of the link (the cable that does not is
/// named); a common point off the joint moves the positions by it, with a note.
#[test]
fn a_t_xyz_link_imports_as_a_point_mass() {
    use cablenav::scenario::caspr::model_to_json;
    let bodies = POINT_BODIES
        .replace("type=\"P_XZ\" q_initial=\"1.0 1.0\" q_min=\"0.0 -2.0\" q_max=\"2.0 2.0\"", "type=\"T_XYZ\" q_initial=\"0.0 0.1 0.2\" q_min=\"-1 -1 -1\" q_max=\"1 1 1\"")
        .replace("<mass>5</mass>", "<mass>1</mass>");
    // the 4-cable set, its base anchors moved off the plane y = 0 (a regular tetrahedron)
    let cables = POINT_CABLES
        .replace("default_cable_set=\"3_cables\"", "default_cable_set=\"4_cables\"")
        .replace("<location>0.5 0.0 0.5</location>", "<location>0.5 0.5 0.5</location>")
        .replace("<location>-0.5 0.0 0.5</location>", "<location>-0.5 -0.5 0.5</location>")
        .replace("<location>-0.5 0.0 -0.5</location>", "<location>-0.5 0.5 -0.5</location>")
        .replace("<location>0.5 0.0 -0.5</location>", "<location>0.5 -0.5 -0.5</location>");
    assert!(bodies.contains("T_XYZ") && cables.contains("-0.5 0.5 -0.5"), "the test edits must apply");
    let trajectories = POINT_TRAJECTORIES.replace("<q>0.0 -0.1</q>", "<q>0.0 0.0 -0.1</q>").replace("<q>0.0 0.1</q>", "<q>0.0 0.0 0.1</q>").replace("<q>0.0 0.0</q>", "<q>0.0 0.0 0.0</q>").replace("0.0 0.0</q_dot>", "0.0 0.0 0.0</q_dot>").replace("0.0 0.0</q_ddot>", "0.0 0.0 0.0</q_ddot>");
    let out = model_to_json("point", &bodies, &cables, Some(&trajectories), None).unwrap();
    assert_eq!(out.notes.len(), 1, "{:?}", out.notes); // the cable set
    let json: serde_json::Value = serde_json::from_str(&out.json).unwrap();
    assert_eq!(json["format"], "cablenav-scenario/5");
    assert_eq!(json["robot"]["mobility"], "point");
    assert!(json["robot"]["cables"].as_array().unwrap().iter().all(|c| c.get("platform").is_none()));
    assert_eq!(json["robot"]["dynamics"], serde_json::json!({"mass": 1.0, "gravity": [0.0, 0.0, -9.81]}));
    assert_eq!(json["poses"]["initial"], serde_json::json!({"position": [0.0, 0.1, 0.2]}));
    assert!(!out.json.contains("euler_xyz_deg") && !out.json.contains("slerp"), "{}", out.json);

    let s = Scenario::from_json(&out.json).unwrap();
    assert_eq!(s.robot.mobility, cablenav::model::Mobility::Point);
    assert_eq!(s.robot.cables[2].base, v(-0.5, 0.5, -0.5));
    assert!(s.robot.cables.iter().all(|c| c.platform == v(0.0, 0.0, 0.0)));
    assert_eq!((c_tension(&s), s.robot.dynamics.as_ref().unwrap().mass), ((5.0, 50.0), 1.0));
    assert_eq!(s.pose("initial").unwrap().position, v(0.0, 0.1, 0.2));
    let up = s.trajectory(Some("traj_bottom_to_top")).unwrap().knots.as_ref().unwrap();
    assert_eq!((up.points[1].time, up.points[1].pose.position), (4.0, v(0.0, 0.0, 0.1)));
    let report = check_pose(&s, "initial", s.pose("initial").unwrap());
    assert!(report.wrench.as_ref().is_some_and(|w| w.feasible), "{:?}", report.wrench);

    // a cable ending elsewhere on the link is named
    let mut apart = cables.clone();
    let last = apart.rfind("<location>0 0 0</location>").unwrap();
    apart.replace_range(last..last + "<location>0 0 0</location>".len(), "<location>0 0 0.1</location>");
    let e = err(&bodies, &apart);
    assert!(e.field == "cables" && e.reason.contains("cable \"cable 4\"") && e.reason.contains("point mass"), "{e}");
    // all ending at the centre of mass, off the joint: the positions move by it
    let off = bodies.replace("<com_location>0.0 0.0 0.0</com_location>", "<com_location>0.1 0.0 0.0</com_location>");
    let out = model_to_json("point", &off, &cables, Some(&trajectories), None).unwrap();
    assert!(out.notes.iter().any(|n| n.contains("[0.1, 0.0, 0.0]")), "{:?}", out.notes);
    let s = Scenario::from_json(&out.json).unwrap();
    assert_eq!(s.pose("initial").unwrap().position, v(0.1, 0.1, 0.2));
    assert_eq!(s.trajectory(Some("traj_bottom_to_top")).unwrap().knots.as_ref().unwrap().points[0].pose.position, v(0.1, 0.0, -0.1));
    // an inertia is left out, with a note
    let spinning = bodies.replace("<Izz>0.0</Izz>", "<Izz>0.5</Izz>");
    let out = model_to_json("point", &spinning, &cables, None, None).unwrap();
    assert!(out.notes.iter().any(|n| n.contains("inertia") && n.contains("left out")), "{:?}", out.notes);
    // Example_point_XZ's own trajectories give two coordinates
    let e = model_to_json("point", &bodies, &cables, Some(POINT_TRAJECTORIES), None).unwrap_err();
    assert!(e.field == "trajectories" && e.reason.contains("needs 3 numbers"), "{e}");
}

/// The robot-level tension bounds of the first cable.
fn c_tension(s: &Scenario) -> (f64, f64) {
    (s.robot.cables[0].tension.min, s.robot.cables[0].tension.max)
}
