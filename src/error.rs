//! The one error type of the core: every failure names the input field it comes from and why.

use std::fmt;

/// An error that names the offending field (a JSON path such as `robot.cables[3].base`, or a
/// command-line option) and the reason, so a user can find and fix it.
#[derive(Debug, Clone, PartialEq)]
pub struct Error {
    /// Where the problem is: a JSON path into the scenario, or an option name.
    pub field: String,
    /// What is wrong there.
    pub reason: String,
}

impl Error {
    /// An error at `field` for `reason`.
    pub fn new(field: impl Into<String>, reason: impl Into<String>) -> Self {
        Error { field: field.into(), reason: reason.into() }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.field.is_empty() {
            write!(f, "{}", self.reason)
        } else {
            write!(f, "{}: {}", self.field, self.reason)
        }
    }
}

impl std::error::Error for Error {}

/// Shorthand for results of the core.
pub type Result<T> = std::result::Result<T, Error>;

/// `Ok(x)` when `x` is finite, else an error naming `field`.
pub fn finite(field: &str, x: f64) -> Result<f64> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(Error::new(field, format!("must be a finite number, got {x}")))
    }
}
