//! Errors of the colregs crate.

use thiserror::Error;

/// What can go wrong when using the COLREGs layer.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ColregsError {
    /// A [`RuleParameters`](crate::RuleParameters) field is out of range.
    #[error("rule parameter `{field}` is {value}, expected {expected}")]
    InvalidParameter {
        /// The field's name.
        field: &'static str,
        /// The value given.
        value: f64,
        /// What the field accepts.
        expected: &'static str,
    },
    /// A recording handed to the observed judgement
    /// ([`observed::judge`](crate::observed::judge)) is malformed.
    #[error("recording: {what}")]
    InvalidRecording {
        /// What is wrong, naming the vessel and the field.
        what: String,
    },
}
