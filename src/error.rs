//! The one error type of the core. `src/py/errors.rs` is the only place that turns it into
//! Python exceptions, so every failure reaches Python as a specific, documented exception.

/// Every way a core operation can fail.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// An argument has the right type but an unusable value (shape, NaN, empty, unknown name).
    /// Becomes `ValueError`.
    #[error("{arg}: {reason}")]
    InvalidValue { arg: String, reason: String },

    /// An index argument points outside the array it indexes. Becomes `IndexError`.
    #[error("{arg}: {reason}")]
    IndexOutOfRange { arg: String, reason: String },

    /// An argument has an unsupported type or dtype. Becomes `TypeError`.
    #[error("{arg}: {reason}")]
    WrongType { arg: String, reason: String },

    /// An iterative solver stopped before reaching its tolerance. Becomes `toonmesh.ConvergenceError`.
    #[error("{0}")]
    NotConverged(String),

    /// No GPU adapter (hardware or software) could be found. Becomes `toonmesh.GpuUnavailableError`.
    #[error("{0}")]
    NoAdapter(String),

    /// The GPU device failed while working (out of memory, device lost, validation).
    /// Becomes `toonmesh.GpuError`.
    #[error("{0}")]
    Gpu(String),

    /// The caller asked the work to stop (Ctrl-C) and it stopped between two steps.
    /// Becomes the pending `KeyboardInterrupt` (or whatever the signal handler raised).
    #[error("interrupted")]
    Interrupted,

    /// A bug in toonmesh (for example a caught panic). Becomes `RuntimeError`.
    #[error("internal error: {0}")]
    Internal(String),
}

impl Error {
    pub fn invalid(arg: impl Into<String>, reason: impl Into<String>) -> Self {
        Error::InvalidValue { arg: arg.into(), reason: reason.into() }
    }

    pub fn out_of_range(arg: impl Into<String>, reason: impl Into<String>) -> Self {
        Error::IndexOutOfRange { arg: arg.into(), reason: reason.into() }
    }

    pub fn wrong_type(arg: impl Into<String>, reason: impl Into<String>) -> Self {
        Error::WrongType { arg: arg.into(), reason: reason.into() }
    }

    /// The same error placed in item `place` of a list argument: the argument `vertices`
    /// becomes `meshes[2].vertices`, and `mesh` (the item itself) `meshes[2]`.
    pub fn in_item(self, place: &str) -> Self {
        let name = |arg: String| if arg == "mesh" { place.to_string() } else { format!("{place}.{arg}") };
        match self {
            Error::InvalidValue { arg, reason } => Error::invalid(name(arg), reason),
            Error::IndexOutOfRange { arg, reason } => Error::out_of_range(name(arg), reason),
            Error::WrongType { arg, reason } => Error::wrong_type(name(arg), reason),
            other => other,
        }
    }

    /// The same error naming the argument `from` as `to`, where a caller passes its own
    /// argument on under another name (the renderer's `smooth_iterations` as `iterations`).
    pub fn renamed(self, from: &str, to: &str) -> Self {
        match self {
            Error::InvalidValue { arg, reason } if arg == from => Error::invalid(to, reason),
            Error::IndexOutOfRange { arg, reason } if arg == from => Error::out_of_range(to, reason),
            Error::WrongType { arg, reason } if arg == from => Error::wrong_type(to, reason),
            other => other,
        }
    }
}

pub type Result<T, E = Error> = std::result::Result<T, E>;

/// Refuses the argument `arg` unless it has `n` entries, `expected` saying what they match
/// ("expected one width per point (3), got 2").
pub fn as_many(arg: &str, got: usize, (expected, n): (&str, usize)) -> Result<()> {
    if got != n {
        return Err(Error::invalid(arg, format!("expected {expected} ({n}), got {got}")));
    }
    Ok(())
}

/// The name of field `name` of the argument called `prefix` in errors: `"prefix.name"`, or
/// `"name"` alone for a setting that is being made (`prefix` empty), whose fields are its
/// constructor's arguments. Scene checks name the place: `"meshes[0].material.shininess"`.
pub fn field(prefix: &str, name: &str) -> String {
    if prefix.is_empty() {
        name.to_string()
    } else {
        format!("{prefix}.{name}")
    }
}

/// The name among `names` closest to a misspelt `name` (within two edits), for a hint.
pub fn closest<'a>(name: &str, names: &[&'a str]) -> Option<&'a str> {
    let distance = |a: &str| {
        let b: Vec<char> = name.chars().collect();
        let mut row: Vec<usize> = (0..=b.len()).collect();
        for (i, ca) in a.chars().enumerate() {
            let mut diagonal = row[0];
            row[0] = i + 1;
            for (j, &cb) in b.iter().enumerate() {
                let above = row[j + 1];
                row[j + 1] = (diagonal + (ca != cb) as usize).min(row[j] + 1).min(above + 1);
                diagonal = above;
            }
        }
        row[b.len()]
    };
    names.iter().map(|&n| (distance(n), n)).filter(|(d, _)| *d <= 2).min().map(|(_, n)| n)
}
