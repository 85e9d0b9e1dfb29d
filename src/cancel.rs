//! Stopping long work early. The caller holds a `Cancel` and may raise it from another thread
//! (the Python layer does so on Ctrl-C); long loops call `check` between steps and return
//! `Error::Interrupted` once it is raised. A check is one relaxed atomic load, so loops may
//! check at every step without a measurable cost.

use std::sync::atomic::{AtomicBool, Ordering};

use crate::error::{Error, Result};

#[derive(Debug, Default)]
pub struct Cancel {
    requested: AtomicBool,
}

impl Cancel {
    pub const fn new() -> Self {
        Cancel { requested: AtomicBool::new(false) }
    }

    /// A flag nobody raises, for callers that never cancel.
    pub fn never() -> &'static Cancel {
        static NEVER: Cancel = Cancel::new();
        &NEVER
    }

    /// Asks the work to stop at its next check.
    pub fn request(&self) {
        self.requested.store(true, Ordering::Relaxed);
    }

    pub fn is_requested(&self) -> bool {
        self.requested.load(Ordering::Relaxed)
    }

    /// `Err(Error::Interrupted)` once a stop was requested.
    #[inline]
    pub fn check(&self) -> Result<()> {
        if self.is_requested() {
            Err(Error::Interrupted)
        } else {
            Ok(())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn check_fails_only_after_a_request() {
        let c = Cancel::new();
        assert!(c.check().is_ok());
        c.request();
        assert_eq!(c.check(), Err(Error::Interrupted));
        assert!(Cancel::never().check().is_ok());
    }
}
