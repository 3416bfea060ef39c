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
//!
//! The same loops count their steps with [`advance`] into a counter a
//! caller installs with [`with_progress`] (the bindings report it to a
//! progress callback), and size themselves with [`step_count`], which
//! refuses more than [`MAX_TIME_STEPS`] steps before any memory is taken.

use std::cell::RefCell;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Arc;

use crate::error::{Error, Result};

/// The most time steps one transient or time response may take. Ten
/// million steps of a spindle transient are hours of work, and a record of
/// every step would hold gigabytes; a step this small is a mistake, not a
/// model.
pub const MAX_TIME_STEPS: usize = 10_000_000;

thread_local! {
    static FLAG: RefCell<Option<Arc<AtomicBool>>> = const { RefCell::new(None) };
    static PROGRESS: RefCell<Option<Arc<AtomicUsize>>> = const { RefCell::new(None) };
}

/// The number of steps of `dt_s` that cover `duration_s` (`round` or
/// `ceil` by the caller's rule, at least 1), or a `ConfigError` naming
/// `dt_s` and `duration_s` when it exceeds [`MAX_TIME_STEPS`] (or is not a
/// number). `dt_name` is the caller's name for the step.
pub fn step_count(duration_s: f64, dt_s: f64, dt_name: &str, round: fn(f64) -> f64) -> Result<usize> {
    let steps = round(duration_s / dt_s);
    if steps.is_nan() || steps > MAX_TIME_STEPS as f64 {
        let short = |x: f64| {
            if x == 0.0 || (1e-4..1e15).contains(&x.abs()) {
                format!("{x}")
            } else {
                format!("{x:e}")
            }
        };
        let (dt, duration) = (short(dt_s), short(duration_s));
        return Err(Error::config(
            dt_name,
            &dt,
            format!(
                "duration_s = {duration} s in steps of {dt_name} = {dt} s is {steps:e} steps, more than \
                 the {MAX_TIME_STEPS} a run may take; use {dt_name} >= {:e} s or a shorter duration_s",
                duration_s / MAX_TIME_STEPS as f64
            ),
        ));
    }
    Ok((steps as usize).max(1))
}

/// Run `f` on this thread with `counter` as the step counter [`advance`]
/// adds to.
pub fn with_progress<R>(counter: &Arc<AtomicUsize>, f: impl FnOnce() -> R) -> R {
    let prev = PROGRESS.with(|c| c.replace(Some(Arc::clone(counter))));
    let _restore = RestoreProgress(prev);
    f()
}

/// Count one step of a long loop (nothing without [`with_progress`]).
pub fn advance() {
    PROGRESS.with(|c| {
        if let Some(n) = c.borrow().as_ref() {
            n.fetch_add(1, Ordering::Relaxed);
        }
    });
}

/// Restores the counter a thread had before [`with_progress`].
struct RestoreProgress(Option<Arc<AtomicUsize>>);

impl Drop for RestoreProgress {
    fn drop(&mut self) {
        let prev = self.0.take();
        PROGRESS.with(|c| *c.borrow_mut() = prev);
    }
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

/// The cancel flag of this thread, if any: work that splits itself over
/// other threads (rayon) hands it to them with [`with_current`], so that
/// a stop reaches every part of the work.
pub fn current() -> Option<Arc<AtomicBool>> {
    FLAG.with(|c| c.borrow().clone())
}

/// Run `f` on this thread with `flag` (from [`current`] on the thread that
/// split the work) as its cancel flag; `None` runs it without one.
pub fn with_current<R>(flag: Option<&Arc<AtomicBool>>, f: impl FnOnce() -> R) -> R {
    let prev = FLAG.with(|c| c.replace(flag.cloned()));
    let _restore = Restore(prev);
    f()
}

/// Time steps a long integration loop takes between two looks at the
/// cancel flag: loops call [`check`] at every step index that is a
/// multiple of it. A step of the gear model takes 20-100 ns, so a stop is
/// seen within about half a millisecond, at a cost far below the
/// measurement noise of a step.
pub const CHECK_EVERY_STEPS: usize = 4096;

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

    #[test]
    fn with_current_hands_the_flag_to_another_thread() {
        let flag = Arc::new(AtomicBool::new(true));
        with_flag(&flag, || {
            let mine = current();
            assert!(mine.is_some());
            let other = std::thread::spawn(move || with_current(mine.as_ref(), check));
            assert!(matches!(other.join().unwrap(), Err(Error::Interrupted)));
            // None clears the flag for the closure only.
            assert!(with_current(None, check).is_ok());
            assert!(check().is_err());
        });
        assert!(current().is_none());
    }

    #[test]
    fn step_count_refuses_more_than_the_cap_naming_both_times() {
        assert_eq!(step_count(10.0, 3.0, "dt_s", f64::ceil).unwrap(), 4);
        assert_eq!(step_count(10.0, 3.0, "dt_s", f64::round).unwrap(), 3);
        assert_eq!(
            step_count(1.0, 1.0 / MAX_TIME_STEPS as f64, "dt_s", f64::round).unwrap(),
            MAX_TIME_STEPS
        );
        for dt in [1e-300, 0.0, f64::NAN] {
            let e = step_count(375.0, dt, "dt_s", f64::ceil).unwrap_err().to_string();
            assert!(e.contains("dt_s") && e.contains("duration_s = 375"), "{e}");
        }
    }

    #[test]
    fn advance_counts_into_the_installed_counter_only() {
        advance();
        let n = Arc::new(AtomicUsize::new(0));
        with_progress(&n, || {
            advance();
            advance();
        });
        advance();
        assert_eq!(n.load(Ordering::Relaxed), 2);
    }
}
