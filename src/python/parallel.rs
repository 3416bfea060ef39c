//! Long work from Python: run a parallel map in chunks with the GIL
//! released, check for Ctrl-C between chunks and report progress.

use pyo3::prelude::*;
use rayon::prelude::*;

/// Map `f` over `items` in parallel (rayon), `chunk` items at a time with the
/// GIL released. Between chunks: `Python::check_signals` (Ctrl-C raises
/// KeyboardInterrupt) and `progress(done, total)` if given. Each item is
/// computed independently, so results do not depend on the thread count.
pub fn chunked_map<T, R, F>(
    py: Python<'_>,
    items: &[T],
    chunk: usize,
    progress: Option<&Bound<'_, PyAny>>,
    f: F,
) -> PyResult<Vec<R>>
where
    T: Sync,
    R: Send,
    F: Fn(&T) -> R + Sync + Send,
{
    let total = items.len();
    let mut out = Vec::with_capacity(total);
    let chunk = chunk.max(1);
    for part in items.chunks(chunk) {
        let mut res: Vec<R> = py.detach(|| part.par_iter().map(&f).collect());
        out.append(&mut res);
        py.check_signals()?;
        if let Some(cb) = progress {
            cb.call1((out.len(), total))?;
        }
    }
    Ok(out)
}

/// A chunk size that keeps Ctrl-C responsive (about 16 chunks, at least
/// 2 x threads items each).
pub fn default_chunk(n: usize) -> usize {
    let threads = rayon::current_num_threads().max(1);
    (n / 16).max(2 * threads).max(1)
}
