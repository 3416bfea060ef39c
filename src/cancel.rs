//! Cooperative cancellation of long work.
//!
//! A caller that can stop work (the Python bindings: Ctrl-C, or a progress
//! callback returning False) runs it inside [`with_flag`]; long loops of
//! the core (time steps of a transient, of a rotor time response) call
//! [`check`], which returns [`Error::Interrupted`] once the flag of the
//! current thread is set. Without a flag, [`check`] never stops anything,
//! so Rust callers are unaffected.
//!
//! The flag belongs to the thread that runs the closure: work that a loop
//! hands to other threads (nested rayon iterations) does not see it and
//! simply runs to its end.

use std::cell::RefCell;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

use crate::error::{Error, Result};

thread_local! {
    static FLAG: RefCell<Option<Arc<AtomicBool>>> = const { RefCell::new(None) };
}

/// Restores the flag a thread had before [`with_flag`] (also on panic).
struct Restore(Option<Arc<AtomicBool>>);

impl Drop for Restore {
    fn drop(&mut self) {
        let prev = self.0.take();
        FLAG.with(|c| *c.borrow_mut() = prev);
    }
}

/// Run `f` on this thread with `flag` as its cancel flag.
pub fn with_flag<R>(flag: &Arc<AtomicBool>, f: impl FnOnce() -> R) -> R {
    let prev = FLAG.with(|c| c.replace(Some(Arc::clone(flag))));
    let _restore = Restore(prev);
    f()
}

/// `Err(Error::Interrupted)` once the cancel flag of this thread is set.
pub fn check() -> Result<()> {
    let stop = FLAG.with(|c| c.borrow().as_ref().is_some_and(|f| f.load(Ordering::Relaxed)));
    if stop {
        Err(Error::Interrupted)
    } else {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn check_follows_the_flag_of_this_thread_only() {
        assert!(check().is_ok());
        let flag = Arc::new(AtomicBool::new(false));
        with_flag(&flag, || {
            assert!(check().is_ok());
            flag.store(true, Ordering::Relaxed);
            assert!(matches!(check(), Err(Error::Interrupted)));
            // Another thread has no flag.
            assert!(std::thread::spawn(check).join().unwrap().is_ok());
        });
        // Restored after the closure.
        assert!(check().is_ok());
    }
}
