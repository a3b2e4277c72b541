//! CASPR model import: the real model files of ../shared/models/caspr (embedded by path at
//! compile time, so this also runs under `wasm-pack test --node`; never copied into the repo)
//! against the numbers written in them and against the thesis preset, plus every refusal.

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

/// Every joint type of CASPR's multi-link library is read: the bodies of the four models that
/// use them pass, and the import stops at their cables (routed, or between two links: not yet
/// supported, each named); Spatial_Tree (a spatial end effector and a fixed tree) imports whole;
/// R_AXIS keeps its axis, normalised.
#[test]
fn every_joint_type_of_the_library_is_read() {
    for (name, bodies, cables, joint) in [
        ("4U_modular_units_arm", model!("4U_modular_units_arm/4U_modular_units_arm_bodies.xml"), model!("4U_modular_units_arm/4U_modular_units_arm_cables.xml"), "U_YZ"),
        ("SJTUSnake", model!("SJTUSnake/SJTUSnake_bodies.xml"), model!("SJTUSnake/SJTUSnake_cables.xml"), "U_XZ"),
        ("BioBiped_one_leg", model!("BioBiped_one_leg/BioBiped_one_leg_bodies.xml"), model!("BioBiped_one_leg/BioBiped_one_leg_cables.xml"), "PLANAR_YZ"),
        ("RoboyLeftArm", model!("RoboyLeftArm/RoboyLeftArm_bodies.xml"), model!("RoboyLeftArm/RoboyLeftArm_cables.xml"), "R_AXIS"),
    ] {
        assert!(bodies.contains(joint));
        let e = to_json(name, bodies, cables).expect_err("routed or link-to-link cables");
        assert_eq!(e.field, "cables", "{name}: {e}");
        assert!(e.reason.contains("routed") || e.reason.contains("between two links"), "{name}: {e}");
    }
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
    // a multi-link model's trajectories are not read, with a note
    let out = model_to_json("arm", ARM_BODIES, ARM_CABLES, Some(COGIRO_TRAJECTORIES), None).unwrap();
    assert!(out.notes.iter().any(|n| n.contains("multi-link")), "{:?}", out.notes);
}
