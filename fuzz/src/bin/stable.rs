//! The fuzz targets on the stable toolchain: a seeded generator that mutates the seed corpus and
//! feeds each target a fixed number of inputs, in parallel, and reports the count. No coverage
//! feedback (that needs libFuzzer and nightly): instead the mutations know the input formats —
//! JSON values are mutated as trees (numbers swapped for extremes, NaN-like text, members
//! dropped, arrays truncated or doubled, subtrees copied between seeds), besides byte edits and
//! dictionary tokens; CASPR inputs are mutated as XML text, URL fragments as link data of
//! mutated scenarios plus damaged base64. The same seed gives the same inputs.
//!
//!     cargo run --release --manifest-path fuzz/Cargo.toml --bin stable -- [--runs N] [--seed S] [--target NAME]...
//!
//! A panic prints the target, the input's index and seed and saves the input to
//! `fuzz/artifacts/<target>/stable-<seed>-<index>`, then the run fails (exit 1).

use cablenav_fuzz::{CASPR_SEPARATOR, TARGETS};
use base64::Engine;
use rayon::prelude::*;
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

/// SplitMix64: a small, well-mixed PRNG; one per input, seeded from (run seed, index).
struct Rng(u64);

impl Rng {
    fn new(seed: u64, index: u64) -> Rng {
        let mut r = Rng(seed ^ index.wrapping_mul(0x9e37_79b9_7f4a_7c15));
        r.next();
        r
    }
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    /// Uniform in 0..n (n > 0).
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
    fn chance(&mut self, one_in: usize) -> bool {
        self.below(one_in) == 0
    }
    fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }
}

/// Numbers that break naive geometry and parsing.
const EXTREMES: [f64; 16] = [0.0, -0.0, 1.0, -1.0, 1e-300, -1e-300, 1e300, -1e300, f64::MAX, f64::MIN, f64::MIN_POSITIVE, 5e-324, 1e-9, 0.5, 3.141592653589793, 1e6];

/// Text that is not a finite number but may be typed where one is expected.
const ODD_NUMBERS: [&str; 8] = ["NaN", "Infinity", "-Infinity", "1e999", "-1e999", "1e-999", "00", "1."];

/// A mutated copy of a JSON value: one to four edits at random nodes.
fn mutate_value(v: &Value, donors: &[Value], rng: &mut Rng) -> Value {
    let mut out = v.clone();
    for _ in 0..1 + rng.below(4) {
        edit_random_node(&mut out, donors, rng, 0);
    }
    out
}

/// A copy of a JSON value with one to three of its numbers nudged (relative changes up to 10%,
/// or small absolute ones): inputs that mostly stay valid, so they reach verification.
fn nudge_numbers(v: &Value, rng: &mut Rng) -> Value {
    let mut out = v.clone();
    for _ in 0..1 + rng.below(3) {
        nudge_one(&mut out, rng);
    }
    out
}

/// Walks down to a random leaf and nudges it if it is a number.
fn nudge_one(node: &mut Value, rng: &mut Rng) {
    match node {
        Value::Object(map) if !map.is_empty() => {
            let k = rng.below(map.len());
            nudge_one(map.values_mut().nth(k).expect("non-empty"), rng);
        }
        Value::Array(items) if !items.is_empty() => {
            let k = rng.below(items.len());
            nudge_one(&mut items[k], rng);
        }
        Value::Number(n) => {
            let x = n.as_f64().unwrap_or(0.0);
            let y = if rng.chance(2) { x * (1.0 + (rng.below(2001) as f64 - 1000.0) * 1e-4) } else { x + (rng.below(2001) as f64 - 1000.0) * 1e-3 };
            *node = serde_json::Number::from_f64(y).map(Value::Number).unwrap_or(Value::Null);
        }
        _ => {}
    }
}

/// Walks down to a random node and edits it.
fn edit_random_node(v: &mut Value, donors: &[Value], rng: &mut Rng, depth: usize) {
    let descend = depth < 12 && rng.below(3) != 0;
    match v {
        Value::Object(map) if descend && !map.is_empty() => {
            let key = map.keys().nth(rng.below(map.len())).cloned().expect("non-empty");
            if rng.chance(8) {
                map.remove(&key);
            } else if let Some(child) = map.get_mut(&key) {
                edit_random_node(child, donors, rng, depth + 1);
            }
        }
        Value::Array(items) if descend && !items.is_empty() => {
            let k = rng.below(items.len());
            match rng.below(10) {
                0 => {
                    items.truncate(k);
                }
                1 => {
                    let copy = items[k].clone();
                    items.insert(k, copy);
                }
                2 => {
                    let copies: Vec<Value> = items.clone();
                    items.extend(copies);
                }
                _ => edit_random_node(&mut items[k], donors, rng, depth + 1),
            }
        }
        _ => *v = replacement(v, donors, rng),
    }
}

/// A new value for a leaf (or a whole subtree).
fn replacement(v: &Value, donors: &[Value], rng: &mut Rng) -> Value {
    match rng.below(8) {
        0 | 1 if v.is_number() => {
            let x = v.as_f64().unwrap_or(0.0);
            let y = match rng.below(4) {
                0 => *rng.pick(&EXTREMES),
                1 => x * (1.0 + (rng.below(2001) as f64 - 1000.0) * 1e-3),
                2 => -x,
                _ => x + (rng.below(2001) as f64 - 1000.0) * 1e-2,
            };
            serde_json::Number::from_f64(y).map(Value::Number).unwrap_or(Value::Null)
        }
        2 => Value::String(rng.pick(&ODD_NUMBERS).to_string()),
        3 => Value::Null,
        4 => Value::Array(vec![]),
        5 => {
            // a subtree of another seed, anywhere: the right type at the wrong place, or a
            // whole robot where a number was
            let mut donor = rng.pick(donors).clone();
            for _ in 0..rng.below(4) {
                donor = match donor {
                    Value::Object(m) if !m.is_empty() => m.values().nth(rng.below(m.len())).cloned().expect("non-empty"),
                    Value::Array(a) if !a.is_empty() => a[rng.below(a.len())].clone(),
                    other => other,
                };
            }
            donor
        }
        6 => Value::String(match v {
            Value::String(s) if !s.is_empty() => s[..s.char_indices().nth(rng.below(s.chars().count())).map_or(0, |(i, _)| i)].to_string(),
            _ => "q1".to_string(),
        }),
        _ => serde_json::json!(rng.below(100) as i64 - 10),
    }
}

/// Byte-level edits: flips, overwrites, deletions, duplications, dictionary tokens, splices.
fn mutate_bytes(data: &[u8], dict: &[Vec<u8>], donors: &[Vec<u8>], rng: &mut Rng) -> Vec<u8> {
    let mut out = data.to_vec();
    for _ in 0..1 + rng.below(6) {
        let len = out.len();
        let at = if len == 0 { 0 } else { rng.below(len + 1) };
        match rng.below(7) {
            0 if len > 0 => {
                let k = at.min(len - 1);
                out[k] ^= 1 << rng.below(8);
            }
            1 if len > 0 => {
                let k = at.min(len - 1);
                out[k] = *rng.pick(b"{}[]\":,0123456789.-eE \\n<>/=");
            }
            2 if len > 0 => {
                let n = 1 + rng.below(16.min(len - at.min(len - 1)));
                out.drain(at.min(len - 1)..(at.min(len - 1) + n).min(len));
            }
            3 if len > 0 => {
                let k = at.min(len - 1);
                let n = 1 + rng.below(64.min(len - k));
                let chunk = out[k..k + n].to_vec();
                out.splice(at..at, chunk);
            }
            4 if !dict.is_empty() => {
                let token = rng.pick(dict).clone();
                out.splice(at..at, token);
            }
            5 if !donors.is_empty() => {
                let d = rng.pick(donors);
                if !d.is_empty() {
                    let k = rng.below(d.len());
                    let n = 1 + rng.below(256.min(d.len() - k));
                    out.splice(at..at, d[k..k + n].iter().copied());
                }
            }
            _ => out.truncate(at),
        }
    }
    out
}

/// The seeds of one target and how its inputs are made from them.
struct Corpus {
    /// Seed inputs as bytes.
    seeds: Vec<Vec<u8>>,
    /// The seeds parsed as JSON (empty when the format is not JSON).
    values: Vec<Value>,
    dict: Vec<Vec<u8>>,
    kind: Kind,
}

#[derive(Clone, Copy)]
enum Kind {
    Json,
    Caspr,
    Fragment,
}

impl Corpus {
    /// Input `index` of the run with `seed`.
    fn input(&self, seed: u64, index: u64) -> Vec<u8> {
        let mut rng = Rng::new(seed, index);
        // a few inputs are the seeds themselves, unchanged
        if index < self.seeds.len() as u64 {
            return self.seeds[index as usize].clone();
        }
        match self.kind {
            Kind::Json => {
                if rng.chance(3) && !self.values.is_empty() {
                    nudge_numbers(rng.pick(&self.values), &mut rng).to_string().into_bytes()
                } else if rng.chance(2) && !self.values.is_empty() {
                    let v = mutate_value(rng.pick(&self.values), &self.values, &mut rng);
                    let text = if rng.chance(2) { v.to_string() } else { serde_json::to_string_pretty(&v).expect("a Value serialises") };
                    // sometimes damage the valid JSON too
                    if rng.chance(6) {
                        mutate_bytes(text.as_bytes(), &self.dict, &self.seeds, &mut rng)
                    } else {
                        text.into_bytes()
                    }
                } else {
                    mutate_bytes(rng.pick(self.seeds.as_slice()).as_slice(), &self.dict, &self.seeds, &mut rng)
                }
            }
            Kind::Caspr => mutate_bytes(rng.pick(self.seeds.as_slice()).as_slice(), &self.dict, &self.seeds, &mut rng),
            Kind::Fragment => {
                let json = if self.values.is_empty() || rng.chance(4) {
                    String::from_utf8_lossy(&mutate_bytes(rng.pick(self.seeds.as_slice()).as_slice(), &self.dict, &self.seeds, &mut rng)).into_owned()
                } else if rng.chance(2) {
                    nudge_numbers(rng.pick(&self.values), &mut rng).to_string()
                } else {
                    mutate_value(rng.pick(&self.values), &self.values, &mut rng).to_string()
                };
                // the page deflates at level 9 (scenario::share_url::encode_scenario); any level decodes
                // alike, and level 1 keeps the generator cheap
                let deflated = miniz_oxide::deflate::compress_to_vec(json.as_bytes(), 1);
                let link = format!("#s={}", base64::engine::general_purpose::URL_SAFE_NO_PAD.encode(deflated));
                if rng.chance(3) {
                    mutate_bytes(link.as_bytes(), &[b"#s=".to_vec(), b"#preset=".to_vec(), b"=".to_vec(), b"%".to_vec()], &[], &mut rng)
                } else {
                    link.into_bytes()
                }
            }
        }
    }
}

/// Reads every file of `dir` with one of the extensions, sorted by name (missing dir: none).
fn read_dir(dir: &Path, ext: &[&str]) -> Vec<(PathBuf, Vec<u8>)> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .map(|it| it.filter_map(|e| e.ok().map(|e| e.path())).filter(|p| p.extension().is_some_and(|x| ext.iter().any(|e| x == *e))).collect())
        .unwrap_or_default();
    files.sort();
    files.into_iter().filter_map(|p| std::fs::read(&p).ok().map(|d| (p, d))).collect()
}

/// libFuzzer dictionary entries: the quoted strings of `fuzz/scenario.dict`, unescaped.
fn dictionary(path: &Path) -> Vec<Vec<u8>> {
    let text = std::fs::read_to_string(path).unwrap_or_default();
    text.lines()
        .filter(|l| l.starts_with('"') && l.ends_with('"') && l.len() >= 2)
        .map(|l| l[1..l.len() - 1].replace("\\\"", "\"").replace("\\\\", "\\").into_bytes())
        .collect()
}

/// The corpus of a target, from the repository root `root`.
fn corpus(root: &Path, target: &str) -> Corpus {
    let fuzz = root.join("fuzz");
    let dict = dictionary(&fuzz.join("scenario.dict"));
    let json_seeds = || -> Vec<Vec<u8>> {
        let mut seeds: Vec<Vec<u8>> = read_dir(&fuzz.join("corpus").join(target), &["json"]).into_iter().map(|(_, d)| d).collect();
        if seeds.is_empty() {
            seeds = read_dir(&fuzz.join("corpus/scenario_parse"), &["json"]).into_iter().map(|(_, d)| d).collect();
        }
        seeds
    };
    match target {
        "caspr" => {
            // the CASPR models the tests use (../shared/models/caspr, not copied into the
            // repository), bodies + separator + cables, and the small seeds of fuzz/corpus/caspr
            let mut seeds: Vec<Vec<u8>> = read_dir(&fuzz.join("corpus/caspr"), &["xml"]).into_iter().map(|(_, d)| d).collect();
            let models = root.join("../shared/models/caspr");
            let mut dirs: Vec<PathBuf> = std::fs::read_dir(&models).map(|it| it.filter_map(|e| e.ok().map(|e| e.path())).filter(|p| p.is_dir()).collect()).unwrap_or_default();
            dirs.sort();
            for dir in dirs {
                let files = read_dir(&dir, &["xml"]);
                let find = |suffix: &str| files.iter().find(|(p, _)| p.to_string_lossy().ends_with(suffix)).map(|(_, d)| d.clone());
                if let (Some(mut bodies), Some(cables)) = (find("_bodies.xml"), find("_cables.xml")) {
                    bodies.extend_from_slice(CASPR_SEPARATOR);
                    bodies.extend_from_slice(&cables);
                    seeds.push(bodies);
                }
            }
            let dict = ["<", ">", "</", "/>", "=\"", "\"", "<!--cables-->", "<cable_set", "<link_rigid", "<frame_attachment", "<location", "<com_location", "num_links", "num_dofs", "marker", "1e308", "NaN", "-"]
                .iter()
                .map(|s| s.as_bytes().to_vec())
                .collect();
            Corpus { seeds, values: vec![], dict, kind: Kind::Caspr }
        }
        "url_fragment" => {
            let seeds = json_seeds();
            let values = seeds.iter().filter_map(|s| serde_json::from_slice(s).ok()).collect();
            Corpus { seeds, values, dict, kind: Kind::Fragment }
        }
        _ => {
            let seeds = json_seeds();
            let values = seeds.iter().filter_map(|s| serde_json::from_slice(s).ok()).collect();
            Corpus { seeds, values, dict, kind: Kind::Json }
        }
    }
}

fn main() {
    let mut runs: u64 = 100_000;
    let mut seed: u64 = 1;
    let mut only: Vec<String> = vec![];
    let mut max_len: usize = 64 * 1024;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        let mut value = |name: &str| args.next().unwrap_or_else(|| panic!("{name} needs a value"));
        match a.as_str() {
            "--runs" => runs = value("--runs").parse().expect("--runs N"),
            "--seed" => seed = value("--seed").parse().expect("--seed S"),
            "--target" => only.push(value("--target")),
            "--max-len" => max_len = value("--max-len").parse().expect("--max-len BYTES"),
            "-h" | "--help" => {
                println!("usage: stable [--runs N (100000)] [--seed S (1)] [--target NAME]... [--max-len BYTES (65536)]");
                println!("targets: {}", TARGETS.iter().map(|t| t.0).collect::<Vec<_>>().join(", "));
                return;
            }
            other => panic!("unknown argument {other} (see --help)"),
        }
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    // a panic in a target is caught and reported below; keep the default message short
    std::panic::set_hook(Box::new(|info| eprintln!("panic: {info}")));
    let mut failed = false;
    for (name, target) in TARGETS {
        if !only.is_empty() && !only.iter().any(|o| o == name) {
            continue;
        }
        let corpus = corpus(&root, name);
        assert!(!corpus.seeds.is_empty(), "no seeds for {name}");
        let started = std::time::Instant::now();
        let skipped = AtomicUsize::new(0);
        let accepted = AtomicUsize::new(0);
        let crashes: Vec<u64> = (0..runs)
            .into_par_iter()
            .filter_map(|i| {
                let input = corpus.input(seed, i);
                if input.len() > max_len {
                    skipped.fetch_add(1, Ordering::Relaxed);
                    return None;
                }
                let outcome = std::panic::catch_unwind(|| target(&input));
                if matches!(outcome, Ok(true)) {
                    accepted.fetch_add(1, Ordering::Relaxed);
                }
                outcome.is_err().then(|| {
                    let dir = root.join("fuzz/artifacts").join(name);
                    let _ = std::fs::create_dir_all(&dir);
                    let path = dir.join(format!("stable-{seed}-{i}"));
                    let _ = std::fs::write(&path, &input);
                    eprintln!("{name}: input {i} (seed {seed}) panicked; saved to {}", path.display());
                    i
                })
            })
            .collect();
        let skipped = skipped.into_inner();
        println!(
            "fuzz {name}: {} inputs run ({} got past parsing; seed {seed}, {} seeds, {} longer than {max_len} B skipped), {} panics, {:.1} s",
            runs as usize - skipped,
            accepted.into_inner(),
            corpus.seeds.len(),
            skipped,
            crashes.len(),
            started.elapsed().as_secs_f64()
        );
        failed |= !crashes.is_empty();
    }
    if failed {
        std::process::exit(1);
    }
}
