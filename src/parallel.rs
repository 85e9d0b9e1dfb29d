//! The thread pool every parallel routine runs in.
//!
//! A private pool rather than rayon's global one, for two reasons: the thread count can be
//! changed at run time (`set_num_threads`), and a process forked after the pool started gets a
//! fresh pool instead of waiting forever on threads that the fork did not copy.
//! Results never depend on the thread count: work is split by fixed chunk sizes and partial sums
//! are combined in a fixed order.

use std::sync::{mpsc, Arc, Mutex};
use std::time::Duration;

use rayon::ThreadPool;

use crate::cancel::Cancel;
use crate::error::{Error, Result};

/// The most worker threads a pool may have: far above any machine's cores, low enough that a
/// mistyped count cannot exhaust the process's threads.
pub const MAX_THREADS: usize = 1024;

struct PoolState {
    pid: u32,
    threads: usize,
    pool: Arc<ThreadPool>,
}

static POOL: Mutex<Option<PoolState>> = Mutex::new(None);
static REQUESTED: Mutex<Option<usize>> = Mutex::new(None);

fn default_threads() -> usize {
    if let Some(n) = std::env::var("TOONMESH_NUM_THREADS").ok().and_then(|s| s.parse::<usize>().ok()) {
        if n > 0 {
            return n.min(MAX_THREADS);
        }
    }
    std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1)
}

/// The pool for this process, created on first use (and again in a forked child).
pub fn pool() -> Arc<ThreadPool> {
    let pid = std::process::id();
    let mut guard = POOL.lock().unwrap_or_else(|e| e.into_inner());
    let wanted = REQUESTED.lock().unwrap_or_else(|e| e.into_inner()).unwrap_or_else(default_threads);
    match guard.as_ref() {
        Some(s) if s.pid == pid && s.threads == wanted => return s.pool.clone(),
        Some(s) if s.pid != pid => {
            // The parent's worker threads do not exist in a forked child: dropping the pool
            // would wait for them, so it is leaked instead.
            std::mem::forget(guard.take());
        }
        _ => {}
    }
    let build = |n: usize| {
        rayon::ThreadPoolBuilder::new().num_threads(n).thread_name(|i| format!("toonmesh-{i}")).build()
    };
    // Where the system refuses that many threads, one thread still gives the same results.
    let pool =
        Arc::new(build(wanted).or_else(|_| build(1)).expect("the system refused to start even one thread"));
    *guard = Some(PoolState { pid, threads: wanted, pool: pool.clone() });
    pool
}

/// Sets the number of worker threads (0 restores the default: `TOONMESH_NUM_THREADS` or the
/// number of cores). Fewer than 0, or more than `MAX_THREADS`, is refused.
pub fn set_num_threads(n: i64) -> Result<()> {
    let n = usize::try_from(n)
        .map_err(|_| Error::invalid("n", format!("must be >= 0 (0 restores the default), got {n}")))?;
    if n > MAX_THREADS {
        return Err(Error::invalid("n", format!("at most {MAX_THREADS} threads, got {n}")));
    }
    *REQUESTED.lock().unwrap_or_else(|e| e.into_inner()) = if n == 0 { None } else { Some(n) };
    Ok(())
}

/// The number of worker threads the next parallel call will use.
pub fn num_threads() -> usize {
    REQUESTED.lock().unwrap_or_else(|e| e.into_inner()).unwrap_or_else(default_threads)
}

/// Runs `work`, turning a panic into `Error::Internal` so that none reaches the caller (a
/// panic must not cross into Python).
pub fn catching_panics<T>(work: impl FnOnce() -> Result<T>) -> Result<T> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(work)).unwrap_or_else(|p| {
        let what = p
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| p.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unknown panic".into());
        Err(Error::Internal(what))
    })
}

/// Runs `f` inside the pool.
pub fn install<R: Send>(f: impl FnOnce() -> R + Send) -> R {
    pool().install(f)
}

/// Runs `work` in the pool, panics caught, while the calling thread asks `stop` every `every`
/// whether to stop it, for a caller that must watch for something else meanwhile (a signal):
/// once `stop` says yes, the work's `Cancel` is raised and `stop` is not asked again.
pub fn watched<T: Send>(
    work: impl FnOnce(&Cancel) -> Result<T> + Send,
    every: Duration,
    mut stop: impl FnMut() -> bool,
) -> Result<T> {
    let cancel = Cancel::new();
    let (done, finished) = mpsc::channel();
    pool().in_place_scope(|scope| {
        let cancel = &cancel;
        scope.spawn(move |_| {
            let _ = done.send(catching_panics(|| work(cancel)));
        });
        loop {
            match finished.recv_timeout(every) {
                Ok(result) => return result,
                Err(mpsc::RecvTimeoutError::Timeout) if !cancel.is_requested() && stop() => cancel.request(),
                Err(mpsc::RecvTimeoutError::Timeout) => {}
                Err(mpsc::RecvTimeoutError::Disconnected) => {
                    return Err(Error::Internal("the worker stopped without a result".into()))
                }
            }
        }
    })
}

/// Fixed chunk length for deterministic parallel reductions.
pub const REDUCE_CHUNK: usize = 4096;

/// Sums `f(i)` for i in 0..n in fixed chunks, combined in order: the same bits for any
/// thread count.
pub fn deterministic_sum(n: usize, f: impl Fn(usize) -> f64 + Sync) -> f64 {
    use rayon::prelude::*;
    let chunks = n.div_ceil(REDUCE_CHUNK);
    let partial: Vec<f64> = (0..chunks)
        .into_par_iter()
        .map(|c| {
            let end = ((c + 1) * REDUCE_CHUNK).min(n);
            let mut s = 0.0;
            for i in c * REDUCE_CHUNK..end {
                s += f(i);
            }
            s
        })
        .collect();
    partial.iter().sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn watched_work_stops_when_asked_and_panics_are_errors() {
        let spin = |cancel: &Cancel| loop {
            cancel.check()?;
            std::thread::sleep(Duration::from_millis(1));
        };
        let mut asked = 0;
        let stopped: Result<()> = watched(spin, Duration::from_millis(1), || {
            asked += 1;
            asked == 3
        });
        assert!(matches!(stopped, Err(Error::Interrupted)));
        assert_eq!(asked, 3);
        let panicked: Result<()> = watched(|_| panic!("boom"), Duration::from_millis(1), || false);
        assert!(matches!(panicked, Err(Error::Internal(m)) if m == "boom"));
        assert_eq!(watched(|_| Ok(7), Duration::from_millis(1), || false).unwrap(), 7);
    }
}
