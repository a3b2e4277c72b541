//! The thesis' 4-DoF arm (`static/multilink/bmarm-x4-2.json`) with the configurations and queries
//! of `tests/data/bmarm-queries.json` merged in: one fixture for the core's planning tests
//! (`tests/joint_plan.rs`) and the command line's (`cli/tests/joint_plan.rs`), which include this
//! file by path (two test crates share no module otherwise).

use serde_json::Value;

/// The preset `arm` (its JSON text) with the fixture's configurations added and its queries as
/// the scenario's queries.
pub fn with_queries(arm: &str) -> Value {
    let mut v: Value = serde_json::from_str(arm).unwrap();
    let extra: Value = serde_json::from_str(include_str!("../data/bmarm-queries.json")).unwrap();
    for (name, config) in extra["configurations"].as_object().unwrap() {
        v["configurations"][name] = config.clone();
    }
    v["queries"] = extra["queries"].clone();
    v
}
