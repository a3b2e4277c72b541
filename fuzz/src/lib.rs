//! The fuzz targets of cablenav, as plain functions of the input bytes, so that the same bodies
//! run under libFuzzer (`fuzz_targets/*.rs`, nightly + cargo-fuzz) and under the seeded stable
//! driver (`src/bin/stable.rs`, any toolchain). A target may return early on input it does not
//! accept (it returns whether the input got past parsing, for the driver's statistics); what it
//! must never do is panic.

use cablenav::scenario::{caspr, share_url};
use cablenav::verify::{ray, verify_all};
use cablenav::Scenario;

/// The targets, by name: (name, function).
pub const TARGETS: [(&str, fn(&[u8]) -> bool); 4] = [("scenario_parse", scenario_parse), ("verify", verify), ("caspr", caspr_import), ("url_fragment", url_fragment)];

/// Arbitrary bytes → `Scenario::from_json` (when they are UTF-8). Parsing and validation must
/// return `Ok` or an `Err` naming the field, never panic.
pub fn scenario_parse(data: &[u8]) -> bool {
    std::str::from_utf8(data).is_ok_and(|text| Scenario::from_json(text).is_ok())
}

/// Arbitrary bytes → `Scenario::from_json`; when it parses, exact verification of every
/// trajectory (a multi-link robot's paths), and a ray through the first pose (configuration) in
/// a coordinate and over a small range chosen from the input's bytes. Errors are fine; panics
/// are bugs.
pub fn verify(data: &[u8]) -> bool {
    let Ok(text) = std::str::from_utf8(data) else { return false };
    let Ok(s) = Scenario::from_json(text) else { return false };
    let _ = verify_all(&s, None);
    // the first pose, or a multi-link robot's first configuration
    let first = s.poses.first().map(|(n, p)| (n.clone(), p.coords().to_vec())).or_else(|| s.configs.first().cloned());
    if let Some((name, q)) = first {
        // The JSON must stay valid, so the choice comes from a hash of the whole input: the
        // coordinate, and a range of width 0.05 to 0.8 (m or rad) around the pose's value.
        let h = data.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, &b| (h ^ b as u64).wrapping_mul(0x0100_0000_01b3));
        let coord = s.coord_at((h % q.len() as u64) as usize);
        let width = 0.05 + 0.75 * ((h >> 8) % 1024) as f64 / 1023.0;
        let shift = ((h >> 18) % 1024) as f64 / 1023.0; // where the pose's value sits in the range
        let c = q[coord.index()];
        let lo = c - shift * width;
        let _ = ray(&s, &name, coord, lo, lo + width);
    }
    true
}

/// Separates the bodies file from the cables file in a CASPR input.
pub const CASPR_SEPARATOR: &[u8] = b"\n<!--cables-->\n";

/// Arbitrary bytes as a CASPR bodies file and cables file (split at the first
/// [`CASPR_SEPARATOR`]; without one, the same text for both) → the import and its validation,
/// and the file-kind sniffing the page uses.
pub fn caspr_import(data: &[u8]) -> bool {
    let Ok(text) = std::str::from_utf8(data) else { return false };
    let (bodies, cables) = match text.find(std::str::from_utf8(CASPR_SEPARATOR).expect("ASCII")) {
        Some(at) => (&text[..at], &text[at + CASPR_SEPARATOR.len()..]),
        None => (text, text),
    };
    let _ = caspr::kind(bodies);
    let _ = caspr::kind(cables);
    caspr::import("fuzz", bodies, cables).is_ok()
}

/// Arbitrary bytes as the page's URL hash (`#preset=…` or `#s=<deflated base64url JSON>`) →
/// the decoding the page does on load, then the scenario parse of what it yields.
pub fn url_fragment(data: &[u8]) -> bool {
    let Ok(hash) = std::str::from_utf8(data) else { return false };
    let h = hash.strip_prefix('#').unwrap_or(hash);
    let Some(encoded) = h.strip_prefix("s=") else { return false };
    share_url::decode_scenario(encoded).is_ok_and(|json| Scenario::from_json(&json).is_ok())
}
