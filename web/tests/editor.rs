//! Component tests of the scenario editor in a real browser (wasm-bindgen-test in headless
//! Chromium through chromedriver: `wasm-pack test --chrome --headless web`, run by
//! scripts/test.sh). Each test mounts the editor (or the whole page) over a scenario, acts as a
//! user does (sets an input's text and fires `input`, clicks) and checks what the editor shows
//! and what it wrote to the scenario JSON.
#![cfg(target_arch = "wasm32")]

use cablenav_web::editor::ScenarioEditor;
use cablenav_web::presets::{find, PRESETS};
use leptos::prelude::*;
use serde_json::Value;
use wasm_bindgen::JsCast;
use wasm_bindgen_test::{wasm_bindgen_test, wasm_bindgen_test_configure};
use web_sys::{Element, HtmlElement, HtmlInputElement, HtmlSelectElement};

wasm_bindgen_test_configure!(run_in_browser);

fn document() -> web_sys::Document {
    web_sys::window().unwrap().document().unwrap()
}

/// A fresh container in the page's body.
fn container() -> HtmlElement {
    let div = document().create_element("div").unwrap();
    document().body().unwrap().append_child(&div).unwrap();
    div.dyn_into().unwrap()
}

/// Lets the reactive system run its effects (they are scheduled, not synchronous).
async fn settle() {
    for _ in 0..3 {
        let promise = js_sys::Promise::new(&mut |resolve, _| {
            web_sys::window().unwrap().set_timeout_with_callback_and_timeout_and_arguments_0(&resolve, 0).unwrap();
        });
        wasm_bindgen_futures::JsFuture::from(promise).await.unwrap();
    }
}

/// Fires a bubbling event `name` at `target`, as the browser does for user input.
fn fire(target: &web_sys::EventTarget, name: &str) {
    let init = web_sys::EventInit::new();
    init.set_bubbles(true);
    target.dispatch_event(&web_sys::Event::new_with_event_init_dict(name, &init).unwrap()).unwrap();
}

fn preset(id: &str) -> &'static str {
    PRESETS[find(id).unwrap()].json
}

struct Mounted {
    root: HtmlElement,
    source: RwSignal<String>,
    origin: RwSignal<&'static str>,
    _handle: leptos::mount::UnmountHandle<leptos::tachys::view::any_view::AnyViewState>,
}

impl Mounted {
    fn q(&self, selector: &str) -> Element {
        self.root.query_selector(selector).unwrap().unwrap_or_else(|| panic!("nothing matches {selector}"))
    }
    fn all(&self, selector: &str) -> u32 {
        self.root.query_selector_all(selector).unwrap().length()
    }
    fn input(&self, field: &str) -> HtmlInputElement {
        self.q(&format!("[data-field=\"{field}\"]")).dyn_into().unwrap()
    }
    /// Types `text` into the input of `field` (sets it, fires `input`).
    async fn type_into(&self, field: &str, text: &str) {
        let input = self.input(field);
        input.set_value(text);
        fire(&input, "input");
        settle().await;
    }
    async fn click(&self, selector: &str) {
        self.q(selector).dyn_into::<HtmlElement>().unwrap().click();
        settle().await;
    }
    async fn choose(&self, selector: &str, value: &str) {
        let select: HtmlSelectElement = self.q(selector).dyn_into().unwrap();
        select.set_value(value);
        fire(&select, "change");
        settle().await;
    }
    /// The message shown next to the input of `field`, in the nearest `container`.
    fn message_near(&self, field: &str, container: &str) -> Option<String> {
        let input = self.input(field);
        let around = input.closest(container).unwrap()?;
        around.query_selector("[data-testid=\"field-error\"]").unwrap().map(|m| m.text_content().unwrap_or_default())
    }
    fn json(&self) -> Value {
        serde_json::from_str(&self.source.get_untracked()).unwrap()
    }
}

async fn mount_editor(id: &str) -> Mounted {
    let root = container();
    let source = RwSignal::new(preset(id).to_string());
    let origin = RwSignal::new(PRESETS[find(id).unwrap()].id);
    let handle = leptos::mount::mount_to(root.clone(), move || view! { <ScenarioEditor source origin /> }.into_any());
    settle().await;
    Mounted { root, source, origin, _handle: handle }
}

#[wasm_bindgen_test]
async fn a_number_typed_is_written_and_marks_the_scenario_edited() {
    let m = mount_editor("cdpr7").await;
    assert_eq!(m.input("robot.cables[2].base[1]").value(), "2");
    m.type_into("robot.cables[2].base[1]", "2.25").await;
    assert_eq!(m.json()["robot"]["cables"][2]["base"][1], 2.25);
    assert_eq!(m.origin.get_untracked(), "edited");
    assert_eq!(m.q("[data-testid=\"editor-status\"]").class_name(), "status ok");
}

#[wasm_bindgen_test]
async fn a_typo_stays_in_the_field_with_a_message_and_is_not_written() {
    let m = mount_editor("cdpr7").await;
    let before = m.source.get_untracked();
    m.type_into("robot.cables[0].platform[2]", "0.3.1").await;
    assert_eq!(m.input("robot.cables[0].platform[2]").value(), "0.3.1");
    assert_eq!(m.input("robot.cables[0].platform[2]").get_attribute("aria-invalid").as_deref(), Some("true"));
    let msg = m.message_near("robot.cables[0].platform[2]", "label").expect("a message at the field");
    assert!(msg.contains("not a number"), "{msg}");
    assert_eq!(m.source.get_untracked(), before, "nothing was written");
    // an empty required number is refused the same way
    m.type_into("robot.cables[0].platform[2]", "").await;
    assert!(m.message_near("robot.cables[0].platform[2]", "label").unwrap().contains("enter a number"));
    assert_eq!(m.source.get_untracked(), before);
}

#[wasm_bindgen_test]
async fn the_cores_errors_show_at_the_field_they_name() {
    let m = mount_editor("cdpr7").await;
    m.type_into("robot.length.min", "12").await;
    let msg = m.message_near("robot.length.min", "fieldset").expect("a message at the bounds");
    assert!(msg.contains("min 12 is greater than max 10"), "{msg}");
    let status = m.q("[data-testid=\"editor-status\"]").text_content().unwrap();
    assert!(status.contains("robot.length"), "{status}");
    // a duplicate obstacle name: the core names obstacles[1].name
    let m = mount_editor("cdpr7-tree").await;
    m.type_into("obstacles[1].name", "crown").await;
    let msg = m.message_near("obstacles[1].name", "label").expect("a message at the name");
    assert!(msg.contains("duplicate obstacle name"), "{msg}");
    assert!(m.message_near("obstacles[0].name", "label").is_none(), "only at the field named");
}

#[wasm_bindgen_test]
async fn cables_are_added_and_removed() {
    let m = mount_editor("cdpr7").await;
    assert_eq!(m.all("[data-testid=\"cable-row\"]"), 7);
    m.click("[data-testid=\"add-cable\"]").await;
    assert_eq!(m.all("[data-testid=\"cable-row\"]"), 8);
    assert_eq!(m.json()["robot"]["cables"].as_array().unwrap().len(), 8);
    assert_eq!(m.input("robot.cables[7].base[0]").value(), "4.1");
    for _ in 0..3 {
        m.click("[data-testid=\"cable-row\"] button.remove").await;
    }
    assert_eq!(m.all("[data-testid=\"cable-row\"]"), 5);
    // five cables: the core's error, at the table
    let status = m.q("[data-testid=\"editor-status\"]").text_content().unwrap();
    assert!(status.contains("robot.cables") && status.contains("at least 6"), "{status}");
    assert!(m.q("[data-testid=\"cable-table-scroll\"] + [data-testid=\"field-error\"]").text_content().unwrap().contains("at least 6"));
}

#[wasm_bindgen_test]
async fn the_wrench_ellipsoid_is_edited_in_three_ways_and_checked_spd() {
    let m = mount_editor("robocrane").await;
    assert_eq!(m.input("wrench.radius").value(), "0.01");
    m.choose("select[data-testid=\"ellipsoid-mode\"]", "radii").await;
    m.type_into("wrench.ellipsoid.radii[2]", "0.5").await;
    let e = &m.json()["wrench"]["ellipsoid"];
    assert_eq!(e[2][2], 4.0);
    assert_eq!(e[0][0], 10000);
    m.type_into("wrench.ellipsoid.radii[0]", "-1").await;
    assert!(m.message_near("wrench.ellipsoid.radii[0]", "label").unwrap().contains("must be positive"));
    m.choose("select[data-testid=\"ellipsoid-mode\"]", "matrix").await;
    m.type_into("wrench.ellipsoid[0][1]", "300").await;
    let msg = m.message_near("wrench.ellipsoid[0][1]", "fieldset").expect("a message at E");
    assert!(msg.contains("not symmetric"), "{msg}");
    m.type_into("wrench.ellipsoid[1][0]", "300").await;
    m.type_into("wrench.ellipsoid[0][0]", "1").await;
    let msg = m.message_near("wrench.ellipsoid[0][0]", "fieldset").expect("a message at E");
    assert!(msg.contains("positive definite"), "{msg}");
    m.choose("select[data-testid=\"point-frame\"]", "platform").await;
    assert_eq!(m.json()["wrench"]["point_frame"], "platform");
}

#[wasm_bindgen_test]
async fn obstacles_of_every_type_are_added_edited_and_deleted() {
    let m = mount_editor("cdpr7").await;
    for kind in ["box", "sphere", "cylinder", "cone", "ellipsoid", "mesh"] {
        m.choose("select[data-testid=\"new-obstacle-type\"]", kind).await;
        m.click("[data-testid=\"add-obstacle\"]").await;
    }
    assert_eq!(m.all("[data-testid=\"obstacle\"]"), 6);
    let j = m.json();
    let kinds: Vec<&str> = j["obstacles"].as_array().unwrap().iter().map(|o| o["type"].as_str().unwrap()).collect();
    assert_eq!(kinds, ["box", "sphere", "cylinder", "cone", "ellipsoid", "mesh"]);
    assert_eq!(m.q("[data-testid=\"editor-status\"]").class_name(), "status ok");
    // the mesh's triangles as text, one per line; a bad index is the core's error there
    let tri = m.q("[data-field=\"obstacles[5].triangles\"]").dyn_into::<web_sys::HtmlTextAreaElement>().unwrap();
    tri.set_value("0 2 1\n0 1 9");
    fire(&tri, "input");
    settle().await;
    let status = m.q("[data-testid=\"editor-status\"]").text_content().unwrap();
    assert!(status.contains("obstacles[5].triangles[1][2]"), "{status}");
    let msg = m.q("[data-field=\"obstacles[5].triangles\"]").closest("label").unwrap().unwrap().text_content().unwrap();
    assert!(msg.contains("out of range"), "{msg}");
    // a colour, then back to the default
    m.type_into("obstacles[0].color", "#aa5500").await;
    assert_eq!(m.json()["obstacles"][0]["color"], "#aa5500");
    m.click("[data-testid=\"obstacle\"] button.small").await;
    assert!(m.json()["obstacles"][0].get("color").is_none());
    // delete the sphere; the others move up
    m.click("[data-testid=\"obstacle\"]:nth-of-type(2) [data-testid=\"remove-obstacle\"]").await;
    assert_eq!(m.json()["obstacles"].as_array().unwrap().len(), 5);
    assert_eq!(m.json()["obstacles"][1]["type"], "cylinder");
}

#[wasm_bindgen_test]
async fn the_pose_being_edited_is_checked_live() {
    let m = mount_editor("cdpr7").await;
    let check = |m: &Mounted| m.q("[data-testid=\"pose\"] [data-testid=\"pose-check\"]").get_attribute("data-feasible").unwrap();
    assert_eq!(check(&m), "true");
    m.type_into("poses.start.position[2]", "30").await;
    assert_eq!(check(&m), "false");
    assert!(m.q("[data-testid=\"pose-check\"]").text_content().unwrap().contains("length"));
    m.type_into("poses.start.position[2]", "1").await;
    assert_eq!(check(&m), "true");
    // converting the convention keeps the rotation
    m.choose("[data-testid=\"pose\"] select[data-testid=\"orientation-kind\"]", "tilt_torsion").await;
    let tt = m.json()["poses"]["start"]["tilt_torsion"].clone();
    assert!((tt[2].as_f64().unwrap() - 30f64.to_radians()).abs() < 1e-11, "{tt}");
    assert_eq!(check(&m), "true");
}

#[wasm_bindgen_test]
async fn via_points_and_trajectory_forms() {
    let m = mount_editor("cdpr7").await;
    let p1 = "trajectories[1].translation.polynomial.via[1][2]";
    assert_eq!(m.input(p1).value(), "1.8");
    m.type_into(p1, "2").await;
    assert_eq!(m.json()["trajectories"][1]["translation"]["polynomial"][2], serde_json::json!([1, 2]));
    m.choose("[data-testid=\"trajectory-item\"]:nth-of-type(2) select[data-testid=\"translation-kind\"]", "bezier").await;
    assert_eq!(m.json()["trajectories"][1]["translation"]["bezier"], serde_json::json!([[2, 1.5, 1], [1.5, 2.3, 3]]));
    m.click("[data-testid=\"add-trajectory\"]").await;
    assert_eq!(m.all("[data-testid=\"trajectory-item\"]"), 3);
    assert_eq!(m.q("[data-testid=\"editor-status\"]").class_name(), "status ok");
}

#[wasm_bindgen_test]
async fn the_editor_follows_the_source_when_it_changes_elsewhere() {
    let m = mount_editor("cdpr7").await;
    m.type_into("robot.cables[0].base[0]", "x").await; // a pending typo
    m.source.set(preset("robocrane").to_string());
    settle().await;
    assert_eq!(m.all("[data-testid=\"cable-row\"]"), 6);
    assert_eq!(m.input("robot.cables[0].base[0]").value(), "-2");
    m.source.set("{ not json".to_string());
    settle().await;
    assert!(m.root.text_content().unwrap().contains("not JSON"));
}

#[wasm_bindgen_test]
async fn the_page_autosaves_and_puts_the_scenario_in_the_hash() {
    let root = container();
    let handle = leptos::mount::mount_to(root.clone(), || view! { <cablenav_web::app::App /> }.into_any());
    settle().await;
    let field: HtmlInputElement = root.query_selector("[data-field=\"robot.cables[0].base[2]\"]").unwrap().unwrap().dyn_into().unwrap();
    field.set_value("0.5");
    fire(&field, "input");
    settle().await;
    let storage = web_sys::window().unwrap().local_storage().unwrap().unwrap();
    let saved: Value = serde_json::from_str(&storage.get_item(cablenav_web::persist::STORAGE_KEY).unwrap().unwrap()).unwrap();
    assert_eq!(saved["origin"], "edited");
    let scenario: Value = serde_json::from_str(saved["source"].as_str().unwrap()).unwrap();
    assert_eq!(scenario["robot"]["cables"][0]["base"][2], 0.5);
    let hash = web_sys::window().unwrap().location().hash().unwrap();
    let shared = cablenav_web::persist::decode_scenario(hash.strip_prefix("#s=").expect("#s= hash")).unwrap();
    assert_eq!(shared, saved["source"].as_str().unwrap());
    drop(handle);
    storage.remove_item(cablenav_web::persist::STORAGE_KEY).unwrap();
}

#[wasm_bindgen_test]
async fn a_multi_link_robot_is_edited_link_by_link() {
    let m = mount_editor("bmarm-x4-2").await;
    // links with their joints; no wrench set or poses, but configurations and paths
    assert_eq!(m.all("[data-testid=\"link\"]"), 2);
    assert_eq!(m.all("[data-testid=\"link-coordinate\"]"), 4, "alpha, beta, gamma and theta");
    assert_eq!(m.all("[data-testid=\"configuration\"]"), 4);
    assert_eq!(m.all("[data-testid=\"path\"]"), 1);
    assert!(m.root.query_selector("[data-testid=\"multilink-note\"]").unwrap().is_some());
    assert_eq!(m.input("robot.links[1].name").value(), "Lower Arm");
    // a joint range and a configuration value are written where the core reads them
    m.type_into("robot.links[0].joint.range[1][1]", "0.9").await;
    assert_eq!(m.json()["robot"]["links"][0]["joint"]["range"][1][1], 0.9);
    m.type_into("configurations.fig312.beta", "0.3").await;
    assert_eq!(m.json()["configurations"]["fig312"]["beta"], 0.3);
    assert_eq!(m.q("[data-testid=\"editor-status\"]").class_name(), "status ok");
    // renaming a link renames the cables that pull it
    let pulled = |v: &Value, name: &str| v["robot"]["cables"].as_array().unwrap().iter().filter(|c| c["link"] == name).count();
    let before = pulled(&m.json(), "Lower Arm");
    assert!(before > 0);
    m.type_into("robot.links[1].name", "Forearm").await;
    assert_eq!((pulled(&m.json(), "Forearm"), pulled(&m.json(), "Lower Arm")), (before, 0));
    assert!(cablenav::Scenario::from_json(&m.source.get_untracked()).is_ok());
    // a joint type changed: the coordinates follow, in every configuration too
    m.choose("[data-testid=\"link-1-joint\"]", "prismatic").await;
    assert_eq!(m.json()["robot"]["links"][1]["joint"]["coordinates"], serde_json::json!(["d"]));
    assert_eq!(m.json()["configurations"]["above"]["d"], 0);
    assert_eq!(m.q("[data-testid=\"editor-status\"]").class_name(), "status ok");
    // a path grows by a step picked from the configurations
    m.choose("[data-testid=\"path-0-add-step\"]", "initial").await;
    assert_eq!(m.json()["trajectories"][0]["through"], serde_json::json!(["below", "above", "initial"]));
    assert_eq!(m.all("[data-testid=\"path-step\"]"), 3);
    // the cable table says which link each cable pulls
    let link: HtmlSelectElement = m.q("[data-field=\"robot.cables[4].link\"]").dyn_into().unwrap();
    assert_eq!(link.value(), "Forearm");
}
