//! The JSON path a scenario's parse error names, found from the error's position in the text
//! (`src/scenario/json_path.rs`), against serde_path_to_error, which tracks the path while it
//! reads: on every preset and fuzzing seed, broken in many ways (characters deleted, tokens
//! inserted, values replaced, keys misspelt, the text cut short), both name the same place.
//! Natively only: it reads the files from the repository.
#![cfg(not(target_arch = "wasm32"))]

use cablenav::scenario::json::{parse, RawScenario};

/// What serde_path_to_error says of `text`: the path (the missing field added, as the core's
/// errors add it) and the message; `None` when the text reads.
fn tracked(text: &str) -> Option<(String, String)> {
    let mut de = serde_json::Deserializer::from_str(text);
    let err = serde_path_to_error::deserialize::<_, RawScenario>(&mut de).err()?;
    let path = err.path().to_string();
    let mut path = if path == "." { String::new() } else { path };
    let message = err.into_inner().to_string();
    if let Some(rest) = message.strip_prefix("missing field `") {
        if let Some(end) = rest.find('`') {
            let field = &rest[..end];
            path = if path.is_empty() { field.to_owned() } else { format!("{path}.{field}") };
        }
    }
    Some((path, message))
}

#[test]
fn parse_errors_name_the_paths_serde_path_to_error_tracks() {
    let dirs = ["static/scenarios", "static/multilink", "fuzz/corpus/scenario_parse"];
    let texts: Vec<String> = dirs.iter().flat_map(|d| std::fs::read_dir(d).unwrap()).map(|e| std::fs::read_to_string(e.unwrap().path()).unwrap()).collect();
    let mut seed = 5u64;
    let mut rnd = move |n: usize| {
        seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        ((seed >> 33) as usize) % n.max(1)
    };
    let tokens = ["\"x\"", "1", "-2.5", "01", "1.", "[]", "{}", "[1,2]", "[1,2,3,4]", "true", "tru", "null", "{\"bogus\": 1}", "\"", "]", "}", ",", ":", "\n"];
    let (mut compared, mut bad) = (0, Vec::new());
    for round in 0..120_000 {
        let mut t = texts[rnd(texts.len())].clone();
        for _ in 0..1 + rnd(4) {
            let i = rnd(t.len());
            if !t.is_char_boundary(i) {
                continue;
            }
            match rnd(5) {
                0 => {
                    let j = (i + 1..=t.len()).find(|&j| t.is_char_boundary(j)).unwrap_or(t.len());
                    t.replace_range(i..j, "");
                }
                1 => t.insert_str(i, tokens[rnd(tokens.len())]),
                2 => t.truncate(i),
                3 => {
                    // the value after the next colon replaced
                    if let Some(c) = t[i..].find(':') {
                        let at = i + c + 1;
                        let end = t[at..].find([',', '}']).map_or(t.len(), |e| at + e);
                        t.replace_range(at..end, tokens[rnd(tokens.len())]);
                    }
                }
                _ => {
                    // a key or string misspelt
                    if let Some(c) = t[i..].find('"') {
                        t.insert_str(i + c + 1, "zz");
                    }
                }
            }
        }
        let Some((path, message)) = tracked(&t) else { continue };
        // the format is read first: texts whose format fails say so instead; and the tracking
        // deserializer itself reads a few texts differently (a struct written as a longer array)
        let Err(got) = parse(&t) else { continue };
        if got.field == "format" || !got.reason.ends_with(&message) {
            continue;
        }
        compared += 1;
        if got.field != path {
            bad.push(format!("round {round}: serde_path_to_error {path:?}, cablenav {:?} ({message})\n{t}", got.field));
        }
    }
    assert!(bad.is_empty(), "{} of {compared} differ; first: {}", bad.len(), bad[0]);
    assert!(compared > 20_000, "only {compared} errors compared");
}
