//! Long work from Python, and the limits that protect the machine.
//!
//! - Thread counts: `threads` above the number of cores
//!   ([`available_cores`]) is capped to it with a `ThreadsWarning`; 0 is a
//!   `ConfigError`. A count below the cores runs in a rayon pool kept for
//!   the next call with the same count (one pool at a time, so repeated
//!   calls neither rebuild pools nor leave threads behind); the cores or
//!   None run in rayon's global pool.
//! - Stops: the work runs with the GIL released while the calling thread
//!   wakes every [`POLL`], checks for Ctrl-C (`Python::check_signals`:
//!   KeyboardInterrupt) and calls `progress(done, total)`; a callback that
//!   returns `False` stops the work with `thermobear.Interrupted`. Items
//!   not started are skipped, and long items (time responses, transients)
//!   stop at their next time step (`crate::cancel`).

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc::RecvTimeoutError;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use pyo3::prelude::*;
use pyo3::types::PyBool;
use rayon::prelude::*;

use super::errors::{Interrupted, IntoPy, ThreadsWarning};
use crate::error::Error;

/// How often the calling thread looks for Ctrl-C and reports progress
/// while the workers run.
pub const POLL: Duration = Duration::from_millis(20);

/// The number of cores this process may use (CPU affinity and cgroup
/// quotas included), at least 1.
pub fn available_cores() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

/// `threads` as it will be used: None stays None (all cores); 0 is a
/// `ConfigError`; more than [`available_cores`] is capped to it with a
/// `ThreadsWarning` (more threads than cores only add switching and memory).
pub fn cap_threads(py: Python<'_>, threads: Option<usize>) -> PyResult<Option<usize>> {
    let cores = available_cores();
    match threads {
        None => Ok(None),
        Some(0) => Err(Error::config(
            "threads",
            0,
            "must be at least 1 (or None for all cores)",
        ))
        .py_err(),
        Some(n) if n > cores => {
            let msg = format!("threads={n} exceeds the {cores} available cores; using {cores}");
            let msg = std::ffi::CString::new(msg).unwrap_or_default();
            PyErr::warn(py, &py.get_type::<ThreadsWarning>(), &msg, 2)?;
            Ok(Some(cores))
        }
        Some(n) => Ok(Some(n)),
    }
}

/// The pool kept for the last thread count asked for below the cores.
static POOL: Mutex<Option<(usize, Arc<rayon::ThreadPool>)>> = Mutex::new(None);

/// The rayon pool for `threads` (already capped): None for rayon's global
/// pool (None, or at least as many threads as it has), else the kept pool
/// of that size (built, and the previous one released, when the count
/// changes; a released pool's threads end once their work is done).
fn pool(threads: Option<usize>) -> PyResult<Option<Arc<rayon::ThreadPool>>> {
    let n = match threads {
        Some(n) if n < rayon::current_num_threads() => n,
        _ => return Ok(None),
    };
    let mut kept = POOL.lock().unwrap_or_else(|e| e.into_inner());
    if let Some((k, p)) = kept.as_ref() {
        if *k == n {
            return Ok(Some(Arc::clone(p)));
        }
    }
    let p = rayon::ThreadPoolBuilder::new()
        .num_threads(n)
        .thread_name(|i| format!("thermobear-{i}"))
        .build()
        .map_err(|e| Error::config("threads", n, format!("cannot start a thread pool: {e}")))
        .py_err()?;
    let p = Arc::new(p);
    *kept = Some((n, Arc::clone(&p)));
    Ok(Some(p))
}

/// Call `progress(done, total)`; a callback that returns `False` (exactly
/// False: None, the usual return, goes on) becomes `thermobear.Interrupted`
/// with `done` and `total` attributes.
pub fn report(cb: &Bound<'_, PyAny>, done: usize, total: usize) -> PyResult<()> {
    let r = cb.call1((done, total))?;
    if r.is(PyBool::new(cb.py(), false).as_any()) {
        let err = Interrupted::new_err(format!(
            "stopped by the progress callback (it returned False) after {done} of {total}"
        ));
        let v = err.value(cb.py());
        v.setattr("done", done)?;
        v.setattr("total", total)?;
        return Err(err);
    }
    Ok(())
}

/// Run `work(stop, done)` on a worker thread with the GIL released. Every
/// [`POLL`] the calling thread checks for Ctrl-C and reports
/// `progress(done, total)` (when `done` moved); on either stop it sets
/// `stop`, which `work` reads between its items and the core's long loops
/// read through `crate::cancel` (the worker runs with `stop` as its cancel
/// flag), and once `work` returns raises the stop's exception. Without a stop, `progress(total, total)`
/// closes the run (when not already reported). `done` is also the worker's
/// step counter (`crate::cancel::advance`): a single long item (a
/// transient) reports its time steps through it.
pub fn watched<R, W>(py: Python<'_>, total: usize, progress: Option<&Bound<'_, PyAny>>, work: W) -> PyResult<R>
where
    R: Send,
    W: FnOnce(&Arc<AtomicBool>, &AtomicUsize) -> R + Send,
{
    let stop = Arc::new(AtomicBool::new(false));
    let done = Arc::new(AtomicUsize::new(0));
    let (tx, rx) = std::sync::mpsc::channel::<R>();
    std::thread::scope(|scope| -> PyResult<R> {
        let (stop, done) = (&stop, &done);
        scope.spawn(move || {
            let res = crate::cancel::with_flag(stop, || crate::cancel::with_progress(done, || work(stop, done)));
            // The receiver outlives this thread (joined at the end of the scope).
            let _ = tx.send(res);
        });
        let rx = Mutex::new(rx);
        let mut interrupt: Option<PyErr> = None;
        let mut reported = usize::MAX;
        loop {
            let got = py.detach(|| match rx.lock() {
                Ok(r) => r.recv_timeout(POLL),
                Err(_) => Err(RecvTimeoutError::Disconnected),
            });
            match got {
                Ok(res) => {
                    if let Some(e) = interrupt {
                        return Err(e);
                    }
                    py.check_signals()?;
                    if let (Some(cb), true) = (progress, reported != total) {
                        report(cb, total, total)?;
                    }
                    return Ok(res);
                }
                // The worker panicked: the scope re-raises its panic.
                Err(RecvTimeoutError::Disconnected) => {
                    return Err(pyo3::exceptions::PyRuntimeError::new_err("a worker thread panicked"))
                }
                Err(RecvTimeoutError::Timeout) => {}
            }
            if interrupt.is_none() {
                let d = done.load(Ordering::Relaxed);
                let checked = py.check_signals().and_then(|_| match progress {
                    Some(cb) if d != reported => {
                        reported = d;
                        report(cb, d, total)
                    }
                    _ => Ok(()),
                });
                if let Err(e) = checked {
                    stop.store(true, Ordering::Relaxed);
                    interrupt = Some(e);
                }
            }
        }
    })
}

/// Map `f` over `items` in parallel in a pool of `threads` threads (None:
/// the global pool; capped by [`cap_threads`]), the GIL released, under
/// [`watched`]: Ctrl-C or a progress callback returning False skips the
/// items not started and raises. The work runs as one parallel iteration
/// (no barrier between parts of it, which on a loaded machine would leave
/// threads waiting for a descheduled one). Every item is computed on its
/// own, so results do not depend on the thread count.
pub fn map_interruptible<T, R, F>(
    py: Python<'_>,
    items: &[T],
    threads: Option<usize>,
    progress: Option<&Bound<'_, PyAny>>,
    f: F,
) -> PyResult<Vec<R>>
where
    T: Sync,
    R: Send,
    F: Fn(&T) -> R + Sync + Send,
{
    let threads = cap_threads(py, threads)?;
    let pool = pool(threads)?;
    let res = watched(py, items.len(), progress, |stop, done| {
        let run = || -> Vec<Option<R>> {
            items
                .par_iter()
                .map(|x| {
                    if stop.load(Ordering::Relaxed) {
                        return None;
                    }
                    let r = crate::cancel::with_flag(stop, || f(x));
                    done.fetch_add(1, Ordering::Relaxed);
                    Some(r)
                })
                .collect()
        };
        match &pool {
            Some(p) => p.install(run),
            None => run(),
        }
    })?;
    // No stop was raised: every item ran.
    Ok(res.into_iter().flatten().collect())
}

/// The number of cores a `threads` argument is capped to.
#[pyfunction(name = "available_cores")]
fn py_available_cores() -> usize {
    available_cores()
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(py_available_cores, m)?)?;
    Ok(())
}
