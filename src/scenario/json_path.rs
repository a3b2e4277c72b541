//! The JSON path of the value a serde_json error is about (`robot.cables[2].base`), found from
//! the error's position in the text. Reading the file through a path-tracking deserializer would
//! do the same at the cost of a second copy of every type's deserializing code — about 20 kB of
//! the page's compressed wasm (docs/benchmarks.md, "Page weight") — so the file is read plainly
//! and, only when it fails, scanned once more to name the place.
//!
//! Where serde_json puts an error depends on what failed, so the caller says what to look for
//! ([`Anchor`]): a scalar whose reading failed ends at the position (it was read whole), a
//! container whose type is wrong starts there (it was only looked at), and what a container's own
//! visitor reports — a missing field, a wrong length — lies inside it (at its closing bracket).

/// Where the value an error is about lies relative to the error's position.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Anchor {
    /// A scalar, or an object's key, ends there (a key is named under its object).
    Ends,
    /// A container starts there.
    Starts,
    /// The innermost container that holds the position.
    Inside,
    /// The text stops being JSON there: the value being read (`?` for a key not yet read).
    Broken,
}

/// One step of a path.
#[derive(Debug, Clone)]
enum Step {
    Key(String),
    Index(usize),
    /// A key not read (yet).
    Unknown,
}

/// The byte offset of serde_json's (line, column) in `text`: lines count from 1, columns are the
/// bytes before the position on its line.
pub(super) fn offset(text: &str, line: usize, column: usize) -> usize {
    let start: usize = text.split_inclusive('\n').take(line.saturating_sub(1)).map(str::len).sum();
    (start + column).min(text.len())
}

/// The path (as serde_path_to_error writes it: keys joined by `.`, indices as `[i]`, the root
/// empty) of the value `anchor` says lies at byte `at` of `text`; an [`Anchor::Ends`] or
/// [`Anchor::Starts`] with no such value falls back to the innermost container holding `at`.
/// Text past a syntax error is not read; what is open there counts as holding `at`.
pub(super) fn path_at(text: &str, at: usize, anchor: Anchor) -> String {
    let mut scan = Scan { b: text.as_bytes(), pos: 0, at, anchor, path: Vec::new(), found: None, inside: None, broken: None };
    scan.value(0);
    let broken = if anchor == Anchor::Broken { scan.broken.take() } else { None };
    broken.or(scan.found).or(scan.inside).map(|p| written(&p)).unwrap_or_default()
}

/// The text of a path.
fn written(path: &[Step]) -> String {
    let mut out = String::new();
    for step in path {
        match step {
            Step::Key(k) if out.is_empty() => out.push_str(k),
            Step::Key(k) => {
                out.push('.');
                out.push_str(k);
            }
            Step::Index(i) => out.push_str(&format!("[{i}]")),
            Step::Unknown if out.is_empty() => out.push('?'),
            Step::Unknown => out.push_str(".?"),
        }
    }
    out
}

/// A scan of the text for the value at `at`.
struct Scan<'a> {
    b: &'a [u8],
    pos: usize,
    at: usize,
    anchor: Anchor,
    path: Vec<Step>,
    /// The path of the value `anchor` asks for, once seen.
    found: Option<Vec<Step>>,
    /// The path of the innermost container holding `at`, once closed (or left open).
    inside: Option<Vec<Step>>,
    /// Where the scan found the text not to be JSON: the path of what was being read there.
    broken: Option<Vec<Step>>,
}

/// Deepest nesting scanned (serde_json's own limit is 128).
const MAX_DEPTH: usize = 256;

impl Scan<'_> {
    fn skip_whitespace(&mut self) {
        while self.b.get(self.pos).is_some_and(|c| matches!(c, b' ' | b'\t' | b'\n' | b'\r')) {
            self.pos += 1;
        }
    }

    /// Records the current path (with `last` after it) as the one asked for if `hit`.
    fn mark(&mut self, hit: bool, last: Option<Step>) {
        if hit && self.found.is_none() {
            self.found = Some(self.path.iter().cloned().chain(last).collect());
        }
    }

    /// The text is not JSON here, where `pending` was to be read: false (the scan stops).
    fn fail(&mut self, pending: Option<Step>) -> bool {
        if self.broken.is_none() {
            self.broken = Some(self.path.iter().cloned().chain(pending).collect());
        }
        false
    }

    /// Scans one value; false when the text stops making sense (or nests too deep) there.
    fn value(&mut self, depth: usize) -> bool {
        self.skip_whitespace();
        let start = self.pos;
        let ok = match self.b.get(start) {
            Some(b'{') if depth < MAX_DEPTH => {
                self.mark(self.anchor == Anchor::Starts && start == self.at, None);
                self.object(depth)
            }
            Some(b'[') if depth < MAX_DEPTH => {
                self.mark(self.anchor == Anchor::Starts && start == self.at, None);
                self.array(depth)
            }
            Some(b'"') => self.string().is_some() || self.fail(None),
            Some(_) => self.scalar() || self.fail(None),
            None => self.fail(None),
        };
        let container = matches!(self.b.get(start), Some(b'{' | b'['));
        if ok && !container {
            self.mark(self.anchor == Anchor::Ends && self.pos == self.at, None);
        }
        // a container holds `at` after its start up to its end (serde_json reads the closing
        // bracket before it reports what the container's visitor found); one left open (past a
        // syntax error, or at the end of a truncated text) holds everything after its start
        if container && self.inside.is_none() && start < self.at && (!ok || self.at <= self.pos) {
            self.inside = Some(self.path.clone());
        }
        ok
    }

    fn object(&mut self, depth: usize) -> bool {
        self.pos += 1;
        self.skip_whitespace();
        if self.b.get(self.pos) == Some(&b'}') {
            self.pos += 1;
            return true;
        }
        loop {
            self.skip_whitespace();
            if self.b.get(self.pos) != Some(&b'"') {
                return self.fail(Some(Step::Unknown));
            }
            let Some(key) = self.string() else { return self.fail(Some(Step::Unknown)) };
            // a key whose reading failed (unknown, repeated) is named under its object; serde_json
            // may have read the whitespace after it by then
            let end = self.pos;
            self.skip_whitespace();
            self.mark(self.anchor == Anchor::Ends && (end..=self.pos).contains(&self.at), Some(Step::Key(key.clone())));
            if self.b.get(self.pos) != Some(&b':') {
                return self.fail(None);
            }
            self.pos += 1;
            self.path.push(Step::Key(key));
            let ok = self.value(depth + 1);
            self.path.pop();
            if !ok {
                return false;
            }
            self.skip_whitespace();
            match self.b.get(self.pos) {
                Some(b',') => self.pos += 1,
                Some(b'}') => {
                    self.pos += 1;
                    return true;
                }
                _ => return self.fail(Some(Step::Unknown)),
            }
        }
    }

    fn array(&mut self, depth: usize) -> bool {
        self.pos += 1;
        self.skip_whitespace();
        if self.b.get(self.pos) == Some(&b']') {
            self.pos += 1;
            return true;
        }
        for index in 0.. {
            // an element is read once anything but the array's end follows (serde_json's
            // order): failing before that is the array's
            self.skip_whitespace();
            if matches!(self.b.get(self.pos), None | Some(b']')) {
                return self.fail(None);
            }
            self.path.push(Step::Index(index));
            let ok = self.value(depth + 1);
            self.path.pop();
            if !ok {
                return false;
            }
            self.skip_whitespace();
            match self.b.get(self.pos) {
                Some(b',') => self.pos += 1,
                Some(b']') => {
                    self.pos += 1;
                    return true;
                }
                _ => return self.fail(None),
            }
        }
        true
    }

    /// A number, `true`, `false` or `null` at `pos`, as JSON writes them; false otherwise.
    fn scalar(&mut self) -> bool {
        let rest = &self.b[self.pos..];
        for word in [&b"true"[..], b"false", b"null"] {
            if rest.starts_with(word) {
                self.pos += word.len();
                return true;
            }
        }
        let digits = |s: &mut Self| {
            let from = s.pos;
            while s.b.get(s.pos).is_some_and(u8::is_ascii_digit) {
                s.pos += 1;
            }
            s.pos > from
        };
        if self.b.get(self.pos) == Some(&b'-') {
            self.pos += 1;
        }
        if self.b.get(self.pos) == Some(&b'0') {
            self.pos += 1;
            if self.b.get(self.pos).is_some_and(u8::is_ascii_digit) {
                return false; // no leading zeros
            }
        } else if !digits(self) {
            return false;
        }
        if self.b.get(self.pos) == Some(&b'.') {
            self.pos += 1;
            if !digits(self) {
                return false;
            }
        }
        if self.b.get(self.pos).is_some_and(|c| matches!(c, b'e' | b'E')) {
            self.pos += 1;
            if self.b.get(self.pos).is_some_and(|c| matches!(c, b'+' | b'-')) {
                self.pos += 1;
            }
            if !digits(self) {
                return false;
            }
        }
        true
    }

    /// A string at `pos` (its opening quote), decoded; `None` if it does not end.
    fn string(&mut self) -> Option<String> {
        self.pos += 1;
        let mut out = Vec::new();
        loop {
            let c = *self.b.get(self.pos)?;
            self.pos += 1;
            match c {
                b'"' => return Some(String::from_utf8_lossy(&out).into_owned()),
                b'\\' => {
                    let e = *self.b.get(self.pos)?;
                    self.pos += 1;
                    let decoded = match e {
                        b'n' => '\n',
                        b't' => '\t',
                        b'r' => '\r',
                        b'b' => '\u{8}',
                        b'f' => '\u{c}',
                        b'u' => self.unicode()?,
                        other => other as char,
                    };
                    let mut buf = [0u8; 4];
                    out.extend_from_slice(decoded.encode_utf8(&mut buf).as_bytes());
                }
                // JSON strings hold no control characters
                0..0x20 => return None,
                _ => out.push(c),
            }
        }
    }

    /// The character of a `\u` escape (after the `u`), a surrogate pair joined.
    fn unicode(&mut self) -> Option<char> {
        let hex = |s: &mut Self| -> Option<u32> {
            let digits = std::str::from_utf8(s.b.get(s.pos..s.pos + 4)?).ok()?;
            s.pos += 4;
            u32::from_str_radix(digits, 16).ok()
        };
        let first = hex(self)?;
        if (0xd800..0xdc00).contains(&first) && self.b.get(self.pos..self.pos + 2) == Some(b"\\u") {
            self.pos += 2;
            let second = hex(self)?;
            return char::from_u32(0x10000 + ((first - 0xd800) << 10) + (second.wrapping_sub(0xdc00) & 0x3ff));
        }
        Some(char::from_u32(first).unwrap_or('\u{fffd}'))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each anchor names the value it is about, nested in objects and arrays.
    #[test]
    fn paths_of_values_at_positions() {
        let text = r#"{"robot": {"cables": [{"base": [1, 2]}, {"base": [3, "x"], "k\"ey": 7}]}}"#;
        let at = |needle: &str, after: bool| text.find(needle).unwrap() + if after { needle.len() } else { 0 };
        assert_eq!(path_at(text, at("\"x\"", true), Anchor::Ends), "robot.cables[1].base[1]");
        assert_eq!(path_at(text, at("[3", false), Anchor::Starts), "robot.cables[1].base");
        assert_eq!(path_at(text, at("2]", true), Anchor::Inside), "robot.cables[0].base");
        assert_eq!(path_at(text, at("\"k\\\"ey\"", true), Anchor::Ends), "robot.cables[1].k\"ey");
        assert_eq!(path_at(text, at("7", true), Anchor::Ends), "robot.cables[1].k\"ey");
        assert_eq!(path_at(text, text.len(), Anchor::Inside), "");
        // a truncated text: the innermost open container
        assert_eq!(path_at(&text[..at("[3", true)], at("[3", true), Anchor::Inside), "robot.cables[1].base");
        // broken JSON: a key not read yet, an element begun, between elements
        assert_eq!(path_at(r#"{"a": {"b": 1 "c": 2}}"#, 14, Anchor::Broken), "a.?");
        assert_eq!(path_at(r#"{"a": [1, -]}"#, 11, Anchor::Broken), "a[1]");
        assert_eq!(path_at(r#"{"a": [1, 2"#, 11, Anchor::Broken), "a");
        assert_eq!(offset("ab\ncd\nef", 3, 1), 7);
    }
}
