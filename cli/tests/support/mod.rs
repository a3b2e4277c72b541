//! What the command-line tests share: the CLI run over an in-memory file system.

use cablenav::Error;
use cablenav_cli::{run, CliError};
use serde_json::Value;
use std::cell::RefCell;
use std::collections::HashMap;

/// The CLI over an in-memory file system: the files it starts with, and whatever `--out` wrote.
pub struct Files(pub RefCell<HashMap<String, String>>);

impl Files {
    /// The files `(name, text)`.
    pub fn new(files: &[(&str, String)]) -> Files {
        Files(RefCell::new(files.iter().map(|(name, text)| (name.to_string(), text.clone())).collect()))
    }

    /// `cablenav ARGS`: its output, or its error.
    pub fn cli(&self, args: &[&str]) -> Result<String, CliError> {
        let read = |p: &str| self.0.borrow().get(p).cloned().ok_or_else(|| Error::new(p, "no such file"));
        let write = |p: &str, bytes: &[u8]| {
            self.0.borrow_mut().insert(p.to_string(), String::from_utf8_lossy(bytes).into_owned());
            Ok(())
        };
        run(args.iter().copied(), &read, &write, &|_| Ok(vec![]), &mut |_| {})
    }

    /// `cablenav ARGS`'s output as JSON (it must succeed).
    pub fn json(&self, args: &[&str]) -> Value {
        serde_json::from_str(&self.cli(args).unwrap_or_else(|e| panic!("{args:?}: {e}"))).unwrap()
    }
}
