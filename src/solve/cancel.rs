//! Stopping a run from outside (Ctrl-C in the Python package): a
//! [`CancelToken`] is installed for the duration of a run with
//! [`CancelToken::scope`], the progress path sets it ([`CancelToken::cancel`])
//! and every solver checks it with [`check`] where it reports progress (a
//! few hundred times per run, so the cost is nil), returning
//! [`SolveError::Cancelled`]. Studies carry the caller's token into their
//! worker threads ([`current`]). Without a token installed nothing can
//! cancel a run: the command line never installs one.

use std::cell::RefCell;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

use super::SolveError;

thread_local! {
    /// The token of the run on this thread, if any.
    static TOKEN: RefCell<Option<CancelToken>> = const { RefCell::new(None) };
}

/// A shared flag that stops the runs it is installed for.
#[derive(Debug, Clone, Default)]
pub struct CancelToken(Arc<AtomicBool>);

impl CancelToken {
    /// A token not yet cancelled.
    pub fn new() -> Self {
        Self::default()
    }

    /// Asks every run under this token to stop at its next check.
    pub fn cancel(&self) {
        self.0.store(true, Ordering::Relaxed);
    }

    /// Whether [`CancelToken::cancel`] was called.
    pub fn is_cancelled(&self) -> bool {
        self.0.load(Ordering::Relaxed)
    }

    /// Runs `f` with this token installed on the current thread (the
    /// previous one is restored afterwards, also on a panic).
    pub fn scope<R>(&self, f: impl FnOnce() -> R) -> R {
        struct Restore(Option<CancelToken>);
        impl Drop for Restore {
            fn drop(&mut self) {
                let previous = self.0.take();
                TOKEN.with(|t| *t.borrow_mut() = previous);
            }
        }
        let _restore = Restore(TOKEN.with(|t| t.replace(Some(self.clone()))));
        f()
    }
}

/// The token installed on this thread, to install it in worker threads
/// ([`in_scope`]).
pub fn current() -> Option<CancelToken> {
    TOKEN.with(|t| t.borrow().clone())
}

/// Runs `f` under `token` when there is one (a study's worker threads run
/// under the token of the thread that started the study).
pub fn in_scope<R>(token: Option<&CancelToken>, f: impl FnOnce() -> R) -> R {
    match token {
        Some(token) => token.scope(f),
        None => f(),
    }
}

/// `Err(SolveError::Cancelled)` when the run on this thread was cancelled.
#[inline]
pub fn check() -> Result<(), SolveError> {
    TOKEN.with(|t| match &*t.borrow() {
        Some(token) if token.is_cancelled() => Err(SolveError::Cancelled),
        _ => Ok(()),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn check_fails_only_under_a_cancelled_token() {
        assert_eq!(check(), Ok(()));
        let token = CancelToken::new();
        token.scope(|| {
            assert_eq!(check(), Ok(()));
            token.cancel();
            assert_eq!(check(), Err(SolveError::Cancelled));
        });
        // The token is gone after its scope.
        assert_eq!(check(), Ok(()));
        assert!(current().is_none());
    }
}
