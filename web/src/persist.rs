//! Sharing and persistence: the scenario in the URL hash (deflated, base64url), autosave to
//! localStorage, embed mode, and JSON/CASPR files in and out. The encoding and the start-up
//! decision are plain functions (unit-tested natively); the rest is thin browser glue.
//!
//! Hash forms: `#preset=<id>` for an unedited preset, `#s=<data>` for anything else, where
//! `<data>` is the scenario JSON, deflated (raw DEFLATE, level 9) and base64url-encoded
//! without padding; then the page's [`Settings`] that differ from their defaults, as
//! `&tab=<id>&planner=<id>&steps=<n>` (links without them, written before they existed, open
//! with the defaults).

use leptos::prelude::*;
use serde_json::{json, Value};
use wasm_bindgen::JsCast;

use crate::presets::{self, PRESETS};
use crate::state::{Settings, Tab};
pub use cablenav::scenario::share_url::{decode_scenario, encode_scenario, MAX_SHARED_BYTES};

/// The localStorage key of the autosaved scenario.
pub const STORAGE_KEY: &str = "cablenav.autosave";

/// What a URL hash asks for.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Shared {
    /// A preset, by id.
    Preset(&'static str),
    /// A scenario's JSON.
    Scenario(String),
}

/// Reads a URL hash (with or without its `#`): `None` for an empty hash or one of another
/// form, else what it shares or why it cannot be read.
pub fn parse_hash(hash: &str) -> Option<Result<Shared, String>> {
    let h = hash.strip_prefix('#').unwrap_or(hash);
    let h = h.split('&').next().unwrap_or_default();
    if let Some(id) = h.strip_prefix("preset=") {
        return Some(
            presets::find(id)
                .map(|i| Shared::Preset(PRESETS[i].id))
                .ok_or_else(|| format!("the shared link names an unknown preset “{id}”")),
        );
    }
    h.strip_prefix("s=").map(|data| decode_scenario(data).map(Shared::Scenario))
}

/// The hash that shares `source`: `#preset=<id>` while it is that preset's text, else `#s=…`.
pub fn hash_for(source: &str, origin: &str) -> String {
    match presets::find(origin) {
        Some(i) if PRESETS[i].json == source => format!("#preset={origin}"),
        _ => format!("#s={}", encode_scenario(source)),
    }
}

/// The settings part of a hash: `&key=value` for each setting that differs from its default
/// (empty when none does). Steps typed as anything but a whole number are not kept.
pub fn settings_query(s: &Settings) -> String {
    let d = Settings::default();
    let mut out = String::new();
    if s.tab != d.tab {
        out += &format!("&tab={}", s.tab.id());
    }
    if s.planner != d.planner {
        out += &format!("&planner={}", s.planner);
    }
    if s.steps != d.steps && is_whole(&s.steps) {
        out += &format!("&steps={}", s.steps);
    }
    out
}

/// Whether `text` is a whole number as the address keeps it (1 to 12 digits).
fn is_whole(text: &str) -> bool {
    (1..=12).contains(&text.len()) && text.bytes().all(|b| b.is_ascii_digit())
}

/// The settings of a hash (the `&key=value` pairs after its first part, or a bare settings
/// string): unknown keys and values are left at their defaults, so a link from a newer page
/// still opens.
pub fn parse_settings(hash: &str) -> Settings {
    let h = hash.strip_prefix('#').unwrap_or(hash);
    let mut s = Settings::default();
    for pair in h.split('&') {
        let Some((key, value)) = pair.split_once('=') else { continue };
        match key {
            "tab" => s.tab = Tab::from_id(value).unwrap_or(s.tab),
            "planner" => {
                if let Some((id, _, true)) = crate::state::PLANNERS.iter().find(|p| p.0 == value) {
                    s.planner = *id;
                }
            }
            "steps" if is_whole(value) => s.steps = value.to_string(),
            _ => {}
        }
    }
    s
}

/// The whole hash that shares the page: the scenario ([`hash_for`]) and the settings
/// ([`settings_query`]).
pub fn share_hash(source: &str, origin: &str, settings: &Settings) -> String {
    hash_for(source, origin) + &settings_query(settings)
}

/// The autosave record: the scenario, where it came from and the settings.
pub fn saved_record(source: &str, origin: &str, settings: &Settings) -> String {
    json!({"source": source, "origin": origin, "settings": settings_query(settings)}).to_string()
}

/// Where the page starts.
#[derive(Debug, Clone, PartialEq)]
pub struct Boot {
    /// The scenario JSON.
    pub source: String,
    /// A preset id, or `"edited"`.
    pub origin: &'static str,
    /// The preset the picker shows.
    pub preset: usize,
    /// Something to tell the user (a damaged link), if any.
    pub note: Option<String>,
    /// `?embed=1`: view and results only.
    pub embed: bool,
    /// The open tab and the planning choices.
    pub settings: Settings,
}

/// `origin` as a static name: a preset id, else `"edited"`.
fn static_origin(origin: &str, source: &str) -> (&'static str, usize) {
    match presets::find(origin) {
        Some(i) if PRESETS[i].json == source => (PRESETS[i].id, i),
        Some(i) => ("edited", i),
        None => ("edited", 0),
    }
}

/// Decides the start: a shared hash first, then (when `restore`, i.e. a top-level page that is
/// not embedded) the autosave, then the first preset.
pub fn boot_state(hash: &str, saved: Option<&str>, restore: bool, embed: bool) -> Boot {
    let first = |note| Boot { source: PRESETS[0].json.to_string(), origin: PRESETS[0].id, preset: 0, note, embed, settings: Settings::default() };
    let mut note = None;
    match parse_hash(hash) {
        Some(Ok(Shared::Preset(id))) => {
            let i = presets::find(id).unwrap_or(0);
            return Boot { source: PRESETS[i].json.to_string(), origin: PRESETS[i].id, preset: i, note: None, embed, settings: parse_settings(hash) };
        }
        Some(Ok(Shared::Scenario(source))) => {
            let (origin, preset) = PRESETS
                .iter()
                .position(|p| p.json == source)
                .map_or(("edited", 0), |i| (PRESETS[i].id, i));
            return Boot { source, origin, preset, note: None, embed, settings: parse_settings(hash) };
        }
        Some(Err(e)) => note = Some(e),
        None => {}
    }
    if restore {
        let record: Option<Value> = saved.and_then(|s| serde_json::from_str(s).ok());
        if let Some(source) = record.as_ref().and_then(|r| r.get("source")?.as_str()) {
            let origin = record.as_ref().and_then(|r| r.get("origin")?.as_str()).unwrap_or("edited");
            let (origin, preset) = static_origin(origin, source);
            let settings = parse_settings(record.as_ref().and_then(|r| r.get("settings")?.as_str()).unwrap_or_default());
            return Boot { source: source.to_string(), origin, preset, note, embed, settings };
        }
    }
    first(note)
}

/// Whether a query string (`?embed=1&…`) asks for embed mode.
pub fn is_embed(search: &str) -> bool {
    search.trim_start_matches('?').split('&').any(|kv| kv == "embed=1" || kv == "embed=true")
}

/// The iframe snippet that embeds the page at `page` (scheme, host and path, no query or
/// hash) showing the scenario of `hash`.
pub fn embed_snippet(page: &str, hash: &str) -> String {
    format!(
        "<iframe src=\"{page}?embed=1{hash}\" width=\"900\" height=\"640\" style=\"border:1px solid #ccc\" \
         title=\"cablenav\" loading=\"lazy\"></iframe>"
    )
}

/// A file name for exporting the scenario called `name`.
pub fn export_name(name: &str) -> String {
    let stem: String = name
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() || c == '-' || c == '_' { c } else { '-' })
        .collect();
    let stem = stem.trim_matches('-');
    format!("{}.json", if stem.is_empty() { "scenario" } else { stem })
}

// ---------------------------------------------------------------------------------------------
// Browser glue

fn window() -> Option<web_sys::Window> {
    web_sys::window()
}

fn storage() -> Option<web_sys::Storage> {
    window()?.local_storage().ok().flatten()
}

/// Whether the page runs inside a frame (then it neither restores nor writes the autosave: a
/// course page shows its author's scenario, not the visitor's edits).
pub fn in_frame() -> bool {
    window().is_some_and(|w| match w.top() {
        Ok(Some(top)) => top != w,
        _ => true,
    })
}

/// Reads the URL, the autosave and the frame state, and decides the start.
pub fn boot() -> Boot {
    let location = window().map(|w| w.location());
    let hash = location.as_ref().and_then(|l| l.hash().ok()).unwrap_or_default();
    let search = location.as_ref().and_then(|l| l.search().ok()).unwrap_or_default();
    let embed = is_embed(&search);
    let restore = !embed && !in_frame();
    let saved = if restore { storage().and_then(|s| s.get_item(STORAGE_KEY).ok().flatten()) } else { None };
    boot_state(&hash, saved.as_deref(), restore, embed)
}

/// The page's address without query and hash.
pub fn page_address() -> String {
    window()
        .map(|w| w.location())
        .map(|l| format!("{}{}", l.origin().unwrap_or_default(), l.pathname().unwrap_or_default()))
        .unwrap_or_default()
}

/// Keeps the URL hash and (outside frames and embed mode) the autosave in step with the
/// scenario and the settings, and loads a shared link pasted into the address bar of the open
/// page.
pub fn keep(source: RwSignal<String>, origin: RwSignal<&'static str>, preset: RwSignal<usize>, settings: RwSignal<Settings>, embed: bool) {
    if embed {
        return;
    }
    let autosave = !in_frame();
    let quiet = crate::state::Quiet::watch();
    Effect::new(move |_| {
        if quiet() {
            return; // written when the drag ends
        }
        let (text, from) = (source.get(), origin.get());
        let hash = settings.with(|s| share_hash(&text, from, s));
        if let Some(w) = window() {
            if w.location().hash().ok().as_deref() != Some(hash.as_str()) {
                let _ = w.history().and_then(|h| h.replace_state_with_url(&wasm_bindgen::JsValue::NULL, "", Some(&hash)));
            }
        }
        if autosave {
            if let Some(s) = storage() {
                let _ = s.set_item(STORAGE_KEY, &settings.with(|x| saved_record(&text, from, x)));
            }
        }
    });
    let handle = window_event_listener(leptos::ev::hashchange, move |_| {
        let hash = window().and_then(|w| w.location().hash().ok()).unwrap_or_default();
        let now = settings.with_untracked(|s| share_hash(&source.get_untracked(), origin.get_untracked(), s));
        if hash != now && matches!(parse_hash(&hash), Some(Ok(_))) {
            let b = boot_state(&hash, None, false, false);
            if b.source != source.get_untracked() {
                preset.set(b.preset);
                source.set(b.source);
                origin.set(b.origin);
            }
            if settings.with_untracked(|s| *s != b.settings) {
                settings.set(b.settings);
            }
        }
    });
    on_cleanup(move || handle.remove());
}

/// Offers `text` as a file download called `name`.
pub fn download(name: &str, text: &str, mime: &str) -> Result<(), String> {
    let fail = |what: &str| format!("could not export: {what}");
    let document = window().and_then(|w| w.document()).ok_or_else(|| fail("no document"))?;
    let parts = js_sys::Array::of1(&wasm_bindgen::JsValue::from_str(text));
    let options = web_sys::BlobPropertyBag::new();
    options.set_type(mime);
    let blob = web_sys::Blob::new_with_str_sequence_and_options(&parts, &options).map_err(|_| fail("Blob"))?;
    let url = web_sys::Url::create_object_url_with_blob(&blob).map_err(|_| fail("object URL"))?;
    let a: web_sys::HtmlAnchorElement =
        document.create_element("a").map_err(|_| fail("link"))?.dyn_into().map_err(|_| fail("link"))?;
    a.set_href(&url);
    a.set_download(name);
    a.click();
    let _ = web_sys::Url::revoke_object_url(&url);
    Ok(())
}

/// The name and text of every file chosen in a file input.
pub async fn read_files(files: Option<web_sys::FileList>) -> Vec<(String, Result<String, String>)> {
    let mut out = Vec::new();
    let Some(files) = files else { return out };
    for i in 0..files.length() {
        let Some(file) = files.get(i) else { continue };
        let text = wasm_bindgen_futures::JsFuture::from(file.text())
            .await
            .ok()
            .and_then(|v| v.as_string())
            .ok_or_else(|| format!("could not read {}", file.name()));
        out.push((file.name(), text));
    }
    out
}

/// Copies `text` to the clipboard (where the browser allows it).
pub fn copy_text(text: &str) {
    if let Some(w) = window() {
        let _ = w.navigator().clipboard().write_text(text);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scenarios_round_trip_through_the_hash() {
        for p in PRESETS {
            let data = encode_scenario(p.json);
            assert!(data.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'-' || b == b'_'), "base64url: {data}");
            assert!(data.len() < p.json.len(), "{}: compressed {} vs {}", p.id, data.len(), p.json.len());
            assert_eq!(decode_scenario(&data).unwrap(), p.json);
        }
        let odd = "{\"name\": \"ünïcödé ✓\"}";
        assert_eq!(decode_scenario(&encode_scenario(odd)).unwrap(), odd);
    }

    #[test]
    fn damaged_links_are_errors_not_panics() {
        assert!(decode_scenario("***").unwrap_err().contains("base64url"));
        assert!(decode_scenario("AAAA").is_err());
        let data = encode_scenario("abc");
        assert!(decode_scenario(&data[..data.len() - 2]).is_err());
        // a zip bomb: far more than the limit once inflated
        let bomb = encode_scenario(&" ".repeat(MAX_SHARED_BYTES + 1));
        assert!(decode_scenario(&bomb).unwrap_err().contains("too large"));
    }

    #[test]
    fn hashes_name_presets_or_carry_the_scenario() {
        let p = &PRESETS[1];
        assert_eq!(hash_for(p.json, p.id), format!("#preset={}", p.id));
        assert_eq!(parse_hash(&hash_for(p.json, p.id)), Some(Ok(Shared::Preset(p.id))));
        let edited = p.json.replace("\"box\"", "\"crate\"");
        let h = hash_for(&edited, p.id);
        assert!(h.starts_with("#s="));
        assert_eq!(parse_hash(&h), Some(Ok(Shared::Scenario(edited.clone()))));
        assert_eq!(parse_hash(""), None);
        assert_eq!(parse_hash("#section-2"), None);
        assert!(parse_hash("#preset=nope").unwrap().is_err());
    }

    #[test]
    fn start_prefers_the_link_then_the_autosave_then_the_first_preset() {
        let edited = PRESETS[2].json.replace("crown", "crown2");
        let saved = saved_record(&edited, "edited", &Settings::default());
        // nothing: the first preset
        let b = boot_state("", None, true, false);
        assert_eq!((b.origin, b.preset, b.source.as_str()), (PRESETS[0].id, 0, PRESETS[0].json));
        // the autosave
        let b = boot_state("", Some(&saved), true, false);
        assert_eq!((b.origin, b.source.as_str()), ("edited", edited.as_str()));
        // not in a frame / embed
        let b = boot_state("", Some(&saved), false, true);
        assert_eq!(b.origin, PRESETS[0].id);
        assert!(b.embed);
        // an autosaved preset keeps its id
        let b = boot_state("", Some(&saved_record(PRESETS[3].json, PRESETS[3].id, &Settings::default())), true, false);
        assert_eq!((b.origin, b.preset), (PRESETS[3].id, 3));
        // the link wins over the autosave
        let h = hash_for(PRESETS[1].json, PRESETS[1].id);
        let b = boot_state(&h, Some(&saved), true, false);
        assert_eq!((b.origin, b.preset), (PRESETS[1].id, 1));
        let h = hash_for("{\"x\": 1}", "edited");
        let b = boot_state(&h, Some(&saved), true, false);
        assert_eq!((b.origin, b.source.as_str()), ("edited", "{\"x\": 1}"));
        // a damaged link: say so, fall back to the autosave
        let b = boot_state("#s=***", Some(&saved), true, false);
        assert_eq!(b.source, edited);
        assert!(b.note.unwrap().contains("damaged"));
        // a damaged autosave: the first preset
        let b = boot_state("", Some("{not json"), true, false);
        assert_eq!(b.origin, PRESETS[0].id);
    }

    #[test]
    fn settings_ride_after_the_scenario_and_old_links_still_open() {
        let p = &PRESETS[1];
        let d = Settings::default();
        assert_eq!(share_hash(p.json, p.id, &d), format!("#preset={}", p.id), "the defaults add nothing: links stay as they were");
        let s = Settings { tab: Tab::Lattice, planner: "ray-lattice", steps: "9".into() };
        let h = share_hash(p.json, p.id, &s);
        assert_eq!(h, format!("#preset={}&tab=lattice&planner=ray-lattice&steps=9", p.id));
        assert_eq!(parse_hash(&h), Some(Ok(Shared::Preset(p.id))));
        assert_eq!(parse_settings(&h), s);
        let b = boot_state(&h, None, true, false);
        assert_eq!((b.preset, b.settings), (1, s.clone()));
        // an edited scenario: base64url has no '&', so the settings follow its data
        let edited = p.json.replace("\"box\"", "\"crate\"");
        let h = share_hash(&edited, "edited", &s);
        assert_eq!(parse_hash(&h), Some(Ok(Shared::Scenario(edited.clone()))));
        assert_eq!(boot_state(&h, None, true, false).settings, s);
        // an old link: the defaults
        assert_eq!(boot_state(&hash_for(&edited, "edited"), None, true, false).settings, d);
        // unknown keys, tabs, planners and steps that are not whole numbers are ignored
        let odd = parse_settings(&format!("#preset={}&tab=nope&planner=magic&steps=1e3&zoom=2&steps", p.id));
        assert_eq!(odd, d);
        assert_eq!(parse_settings("#preset=x&steps=1").steps, "1", "a bad count is kept: the core says why at Plan");
        assert_eq!(settings_query(&Settings { steps: "seven".into(), ..d.clone() }), "", "text is not put in the address");
        // the autosave keeps them too
        let saved = saved_record(p.json, p.id, &s);
        assert_eq!(boot_state("", Some(&saved), true, false).settings, s);
        assert_eq!(boot_state("", Some(&json!({"source": p.json, "origin": p.id}).to_string()), true, false).settings, d, "an older autosave");
    }

    #[test]
    fn embed_flag_snippet_and_file_names() {
        assert!(is_embed("?embed=1"));
        assert!(is_embed("?a=b&embed=1"));
        assert!(!is_embed("?embed=0"));
        assert!(!is_embed(""));
        let s = embed_snippet("https://x.org/cablenav/", "#preset=cdpr7");
        assert!(s.starts_with("<iframe src=\"https://x.org/cablenav/?embed=1#preset=cdpr7\""), "{s}");
        assert_eq!(export_name("cdpr7-box"), "cdpr7-box.json");
        assert_eq!(export_name("My robot / v2"), "My-robot---v2.json");
        assert_eq!(export_name("///"), "scenario.json");
    }
}
