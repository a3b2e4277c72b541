//! No import circles in `src/` (the core) nor in `web/src/` (the page).
//!
//! How the check reads a crate: every `.rs` file is a module (`a/b.rs` and `a/b/mod.rs` are
//! `a::b`; `lib.rs` and `main.rs` the root). Every path a file names through `crate::` or
//! `super::` — in `use` trees with braces as well as inline in code — is resolved to the deepest
//! module it reaches. A reference between two modules where neither contains the other is an
//! edge between the two children of their closest common folder that hold them: a folder's
//! files and subfolders are the rooms, and a room may use what its folder (`mod.rs`) defines or
//! what its own files hold without forming a circle. Each folder's graph of rooms must have no
//! cycle. Names re-exported by a folder's `mod.rs` count as the folder's own, and a child module
//! named without a prefix by its parent is the parent's business, so neither is an edge.
//!
//! Native only: it reads the source tree.
#![cfg(not(target_arch = "wasm32"))]

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// A module path: `["conditions", "tension"]`; the crate root is empty.
type Module = Vec<String>;

/// One reference found in a file: the module it lands in and the text that named it.
struct Reference {
    target: Module,
    path: String,
}

/// The module a file under the crate's source root defines.
fn module_of(relative: &str) -> Module {
    let mut parts: Vec<String> = relative.trim_end_matches(".rs").split('/').map(str::to_string).collect();
    if matches!(parts.last().map(String::as_str), Some("mod" | "lib" | "main")) {
        parts.pop();
    }
    parts
}

/// The source without comments, string and character literals (replaced by spaces), so that a
/// `crate::` in a doc comment or a message is not read as a reference.
fn code_only(source: &str) -> String {
    let bytes = source.as_bytes();
    let mut out = String::with_capacity(source.len());
    let mut i = 0;
    while i < bytes.len() {
        let rest = &source[i..];
        if rest.starts_with("//") {
            let end = rest.find('\n').unwrap_or(rest.len());
            i += end;
        } else if rest.starts_with("/*") {
            let rest = rest.as_bytes();
            let mut depth = 0;
            let mut j = 0;
            while j < rest.len() {
                if rest[j..].starts_with(b"/*") {
                    depth += 1;
                    j += 2;
                } else if rest[j..].starts_with(b"*/") {
                    depth -= 1;
                    j += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    j += 1;
                }
            }
            i += j;
            out.push(' ');
        } else if let Some(len) = raw_string_len(rest) {
            i += len;
            out.push(' ');
        } else if rest.starts_with('"') {
            let rest = rest.as_bytes();
            let mut j = 1;
            while j < rest.len() && rest[j] != b'"' {
                j += if rest[j] == b'\\' { 2 } else { 1 };
            }
            i += (j + 1).min(rest.len());
            out.push(' ');
        } else if let Some(len) = char_literal_len(rest) {
            i += len;
            out.push(' ');
        } else {
            let c = rest.chars().next().expect("not at the end");
            out.push(c);
            i += c.len_utf8();
        }
    }
    out
}

/// The length of a raw string literal (`r"…"`, `r#"…"#`) starting `text`, if one does.
fn raw_string_len(text: &str) -> Option<usize> {
    let after_r = text.strip_prefix('r')?;
    let hashes = after_r.len() - after_r.trim_start_matches('#').len();
    let body = after_r[hashes..].strip_prefix('"')?;
    let close = format!("\"{}", "#".repeat(hashes));
    let end = body.find(&close)?;
    Some(1 + hashes + 1 + end + close.len())
}

/// The length of a character literal starting `text` (`'a'`, `'\n'`, `'\''`), if one does (a
/// lifetime `'a` is not one).
fn char_literal_len(text: &str) -> Option<usize> {
    let rest = text.strip_prefix('\'')?;
    let mut chars = rest.char_indices();
    let (_, c) = chars.next()?;
    let after = if c == '\\' {
        let (_, escaped) = chars.next()?;
        if escaped == 'u' {
            return rest.find('}').map(|k| 1 + k + 2);
        }
        chars.next()?
    } else {
        chars.next()?
    };
    (after.1 == '\'').then_some(1 + after.0 + 1)
}

/// Every path written after `crate::` or `super::` in `code`, expanded through `{…}` groups,
/// as segments relative to the file's module (`super` kept as a segment). A `#[cfg(test)] mod`
/// is skipped: tests may reach anywhere to check one module against another.
fn paths_in(code: &str) -> Vec<Vec<String>> {
    let tokens = without_test_modules(tokenize(code));
    let mut out = Vec::new();
    let mut i = 0;
    while i < tokens.len() {
        let starts_path = (tokens[i] == "crate" || tokens[i] == "super")
            && tokens.get(i + 1).map(String::as_str) == Some("::")
            && (i == 0 || tokens[i - 1] != "::");
        if starts_path {
            let (paths, next) = path_tree(&tokens, i, Vec::new());
            out.extend(paths);
            i = next;
        } else {
            i += 1;
        }
    }
    out
}

/// `tokens` without the items of `#[cfg(test)] mod name { … }` (other attributes may stand
/// between the two).
fn without_test_modules(tokens: Vec<String>) -> Vec<String> {
    const CFG_TEST: [&str; 7] = ["#", "[", "cfg", "(", "test", ")", "]"];
    let mut out = Vec::with_capacity(tokens.len());
    let mut i = 0;
    while i < tokens.len() {
        let body = tokens[i..].iter().take(CFG_TEST.len()).map(String::as_str).eq(CFG_TEST).then(|| {
            let mut k = i + CFG_TEST.len();
            // further attributes: `# [ … ]`
            while tokens.get(k).map(String::as_str) == Some("#") && tokens.get(k + 1).map(String::as_str) == Some("[") {
                k += 2;
                let mut depth = 1;
                while k < tokens.len() && depth > 0 {
                    match tokens[k].as_str() {
                        "[" => depth += 1,
                        "]" => depth -= 1,
                        _ => {}
                    }
                    k += 1;
                }
            }
            let is_mod = tokens.get(k).map(String::as_str) == Some("mod") && tokens.get(k + 2).map(String::as_str) == Some("{");
            is_mod.then_some(k + 3)
        });
        let Some(Some(start)) = body else {
            out.push(tokens[i].clone());
            i += 1;
            continue;
        };
        i = start;
        let mut depth = 1;
        while i < tokens.len() && depth > 0 {
            match tokens[i].as_str() {
                "{" => depth += 1,
                "}" => depth -= 1,
                _ => {}
            }
            i += 1;
        }
    }
    out
}

/// Identifiers, `::`, `{`, `}`, `,` and single other characters.
fn tokenize(code: &str) -> Vec<String> {
    let mut tokens = Vec::new();
    let chars: Vec<char> = code.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if c.is_alphanumeric() || c == '_' {
            let start = i;
            while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            tokens.push(chars[start..i].iter().collect());
        } else if c == ':' && chars.get(i + 1) == Some(&':') {
            tokens.push("::".to_string());
            i += 2;
        } else if c.is_whitespace() {
            i += 1;
        } else {
            tokens.push(c.to_string());
            i += 1;
        }
    }
    tokens
}

/// Reads a path (and the `{…}` groups it opens) from `tokens[i]`, each finished path prefixed
/// by `prefix`; returns the paths and the index after them.
fn path_tree(tokens: &[String], mut i: usize, prefix: Vec<String>) -> (Vec<Vec<String>>, usize) {
    let mut path = prefix;
    loop {
        let Some(token) = tokens.get(i) else { return (vec![path], i) };
        if token == "{" {
            let mut out = Vec::new();
            i += 1;
            while i < tokens.len() && tokens[i] != "}" {
                if tokens[i] == "," {
                    i += 1;
                    continue;
                }
                let (paths, next) = path_tree(tokens, i, path.clone());
                out.extend(paths);
                i = next;
            }
            return (out, i + 1);
        }
        let is_name = token.chars().next().is_some_and(|c| c.is_alphanumeric() || c == '_');
        if !is_name {
            return (vec![path], i);
        }
        path.push(token.clone());
        i += 1;
        if tokens.get(i).map(String::as_str) == Some("::") {
            i += 1;
        } else {
            // `as alias` ends this path
            if tokens.get(i).map(String::as_str) == Some("as") {
                i += 2;
            }
            return (vec![path], i);
        }
    }
}

/// Resolves a path written in `from` to the deepest known module it reaches.
fn resolve(from: &Module, from_is_folder: bool, path: &[String], modules: &BTreeSet<Module>) -> Option<Module> {
    let mut base: Module;
    let mut rest = path;
    if rest.first().map(String::as_str) == Some("crate") {
        base = Vec::new();
        rest = &rest[1..];
    } else {
        // `super` in a folder's mod.rs is the folder's parent; in a file, the file's folder
        base = from.clone();
        if !from_is_folder {
            base.pop();
        }
        let mut first = true;
        while rest.first().map(String::as_str) == Some("super") {
            if !first || from_is_folder {
                base.pop()?;
            }
            first = false;
            rest = &rest[1..];
        }
    }
    for segment in rest {
        let mut next = base.clone();
        next.push(segment.clone());
        if modules.contains(&next) {
            base = next;
        } else {
            break;
        }
    }
    Some(base)
}

/// The circles of a crate whose files are `files` (path relative to the source root, contents):
/// per folder, each cycle among its rooms, with a reference behind each step.
fn circles(files: &[(String, String)]) -> Vec<String> {
    let modules: BTreeSet<Module> = files.iter().map(|(p, _)| module_of(p)).collect();
    // folder -> room -> room -> an example reference
    let mut graphs: BTreeMap<Module, BTreeMap<String, BTreeMap<String, String>>> = BTreeMap::new();
    for (relative, source) in files {
        let from = module_of(relative);
        let is_folder = relative.ends_with("mod.rs") || relative == "lib.rs" || relative == "main.rs";
        for path in paths_in(&code_only(source)) {
            let Some(target) = resolve(&from, is_folder, &path, &modules) else { continue };
            let reference = Reference { target, path: path.join("::") };
            let common = from.iter().zip(&reference.target).take_while(|(a, b)| a == b).count();
            if common == from.len() || common == reference.target.len() {
                continue; // one contains the other
            }
            let folder = from[..common].to_vec();
            let (a, b) = (from[common].clone(), reference.target[common].clone());
            graphs
                .entry(folder)
                .or_default()
                .entry(a)
                .or_default()
                .entry(b)
                .or_insert_with(|| format!("{relative} names {}", reference.path));
        }
    }
    let mut found = Vec::new();
    for (folder, graph) in &graphs {
        for cycle in cycles(graph) {
            let steps: Vec<String> = cycle
                .windows(2)
                .map(|w| format!("{} → {} ({})", w[0], w[1], graph[&w[0]][&w[1]]))
                .collect();
            let name = if folder.is_empty() { "the crate root".to_string() } else { folder.join("::") };
            found.push(format!("in {name}: {}", steps.join("; ")));
        }
    }
    found
}

/// One cycle through each strongly connected part of `graph` that has one (as a closed list of
/// nodes), found by depth-first search.
fn cycles(graph: &BTreeMap<String, BTreeMap<String, String>>) -> Vec<Vec<String>> {
    let mut out = Vec::new();
    let mut reported: BTreeSet<String> = BTreeSet::new();
    for start in graph.keys() {
        if reported.contains(start) {
            continue;
        }
        // a path from `start` back to itself, if any
        let mut stack = vec![(start.clone(), vec![start.clone()])];
        let mut seen = BTreeSet::new();
        while let Some((node, path)) = stack.pop() {
            let Some(next) = graph.get(&node) else { continue };
            if next.contains_key(start) {
                let mut cycle = path.clone();
                cycle.push(start.clone());
                reported.extend(path);
                out.push(cycle);
                break;
            }
            for n in next.keys() {
                if seen.insert(n.clone()) {
                    let mut p = path.clone();
                    p.push(n.clone());
                    stack.push((n.clone(), p));
                }
            }
        }
    }
    out
}

/// Every `.rs` file under `root`, as (path relative to root with `/`, contents).
fn read_tree(root: &Path) -> Vec<(String, String)> {
    let mut files = Vec::new();
    let mut dirs = vec![root.to_path_buf()];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).expect("readable source folder") {
            let path = entry.expect("a folder entry").path();
            if path.is_dir() {
                dirs.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let relative = path.strip_prefix(root).expect("under the root").to_string_lossy().replace('\\', "/");
                files.push((relative, std::fs::read_to_string(&path).expect("readable source file")));
            }
        }
    }
    files.sort();
    files
}

fn assert_no_circles(folder: &str) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join(folder);
    let files = read_tree(&root);
    assert!(files.len() > 10, "{folder}: only {} files found", files.len());
    let found = circles(&files);
    assert!(found.is_empty(), "import circles in {folder}:\n{}", found.join("\n"));
}

#[test]
fn the_core_has_no_import_circle() {
    assert_no_circles("src");
}

#[test]
fn the_page_has_no_import_circle() {
    assert_no_circles("web/src");
}

fn tree(files: &[(&str, &str)]) -> Vec<(String, String)> {
    files.iter().map(|(p, s)| (p.to_string(), s.to_string())).collect()
}

#[test]
fn a_circle_between_folders_and_between_siblings_is_found() {
    // scenario/validate.rs uses conditions, and conditions use the scenario: a circle at the root
    let files = tree(&[
        ("lib.rs", "pub mod scenario; pub mod conditions;"),
        ("scenario/mod.rs", "mod validate; pub struct Scenario;"),
        ("scenario/validate.rs", "use crate::{conditions::{cables_at, Other}, model};"),
        ("conditions/mod.rs", "use crate::scenario::Scenario; pub fn cables_at() {}"),
    ]);
    let found = circles(&files);
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].starts_with("in the crate root: "), "{found:?}");
    assert!(found[0].contains("scenario/validate.rs names crate::conditions::cables_at"), "{found:?}");

    // two files of one folder naming each other through `super::`
    let files = tree(&[
        ("lib.rs", "pub mod plots;"),
        ("plots/mod.rs", "mod section; mod slice;"),
        ("plots/section.rs", "pub fn frame() { super::slice::ticks(); }"),
        ("plots/slice.rs", "use super::section::frame; pub fn ticks() {}"),
    ]);
    let found = circles(&files);
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].starts_with("in plots: "), "{found:?}");
}

#[test]
fn parents_children_comments_and_strings_are_no_circle() {
    let files = tree(&[
        ("lib.rs", "pub mod conditions; pub mod scenario;"),
        // a folder and its files use each other; a layer uses a lower one
        ("conditions/mod.rs", "mod tension; pub use tension::Tension; pub trait Condition {} use crate::scenario::Scenario;"),
        ("conditions/tension.rs", "use super::Condition; use crate::scenario::{Scenario, self};"),
        // the lower layer mentions the upper one only in comments, strings and its tests
        (
            "scenario/mod.rs",
            "//! see crate::conditions::Condition\n/* crate::conditions */ const S: &str = \"crate::conditions::x\"; \
             const R: &str = r#\"crate::conditions\"#; const C: char = '\"'; fn f<'a>(x: &'a str) {} pub struct Scenario; \
             #[cfg(test)]\n#[allow(dead_code)]\nmod tests { use crate::conditions::Condition; fn g() { if true { crate::conditions::f(); } } }",
        ),
    ]);
    assert!(circles(&files).is_empty(), "{:?}", circles(&files));
}

#[test]
fn paths_resolve_through_super_and_brace_groups() {
    let modules: BTreeSet<Module> =
        [vec![], vec!["a".to_string()], vec!["a".to_string(), "b".to_string()], vec!["c".to_string()]].into_iter().collect();
    let s = |x: &str| x.split("::").map(str::to_string).collect::<Vec<_>>();
    let ab = vec!["a".to_string(), "b".to_string()];
    // from the file a/b.rs, `super` is a; from the folder a/mod.rs, `super` is the root
    assert_eq!(resolve(&ab, false, &s("super::Thing"), &modules), Some(vec!["a".to_string()]));
    assert_eq!(resolve(&vec!["a".to_string()], true, &s("super::c::X"), &modules), Some(vec!["c".to_string()]));
    assert_eq!(resolve(&ab, false, &s("crate::c::X"), &modules), Some(vec!["c".to_string()]));
    let paths = paths_in("use crate::{a::{b::X, Y}, c as d}; let v = super::super::c::f();");
    assert_eq!(
        paths,
        vec![s("crate::a::b::X"), s("crate::a::Y"), s("crate::c"), s("super::super::c::f")],
    );
}
