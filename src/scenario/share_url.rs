//! The scenario in a shareable link: the page puts it in the URL hash as `#s=<data>`, where
//! `<data>` is the scenario JSON deflated (raw DEFLATE, level 9) and base64url-encoded without
//! padding. Pure functions, so the page, the CLI and the fuzzer all use the same decoding.

use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use base64::Engine;

/// Largest scenario a shared link may inflate to (bytes), so a crafted link cannot exhaust memory.
pub const MAX_SHARED_BYTES: usize = 8 << 20;

/// The scenario JSON as link data: deflated, base64url.
pub fn encode_scenario(json: &str) -> String {
    URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(json.as_bytes(), 9))
}

/// The scenario JSON from link data; the error says what is wrong with the link.
pub fn decode_scenario(data: &str) -> Result<String, String> {
    let bytes = URL_SAFE_NO_PAD
        .decode(data.trim())
        .map_err(|e| format!("the shared link is damaged (not base64url: {e})"))?;
    let raw = miniz_oxide::inflate::decompress_to_vec_with_limit(&bytes, MAX_SHARED_BYTES)
        .map_err(|e| format!("the shared link is damaged or too large (inflate: {:?})", e.status))?;
    String::from_utf8(raw).map_err(|_| "the shared link is damaged (not UTF-8 text)".to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_and_damage() {
        let json = include_str!("../../static/scenarios/cdpr7-tree.json");
        let data = encode_scenario(json);
        assert!(data.len() < json.len() / 2, "deflate compresses a scenario");
        assert_eq!(decode_scenario(&data).unwrap(), json);
        assert!(decode_scenario("not base64!").unwrap_err().contains("base64url"));
        assert!(decode_scenario(&data[..data.len() / 2]).is_err());
        // a deflate bomb: 9 MB of zeros in a few kB stops at the limit
        let bomb = URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(&vec![b'0'; MAX_SHARED_BYTES + 1], 9));
        assert!(decode_scenario(&bomb).unwrap_err().contains("too large"));
    }
}
