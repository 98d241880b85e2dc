//! The thread pool the CPU backend draws on: rayon's global pool, started by the first
//! [`Context`](crate::Context) (or by [`start_pool`]) with one thread per CPU the process may
//! run on, each thread pinned to a CPU of its own while the calling thread waits for it.
//!
//! Why pinned: a frame hands the pool many short jobs (a pass's tiles, set-up's pieces), and
//! between them the pool's threads sleep. Linux wakes a sleeping thread on a CPU it finds idle
//! at that instant, which the waking thread's own CPU is not yet (the caller is still running
//! when it queues the job), and it does not move a thread that ran within the last half
//! millisecond ("cache hot") to a CPU that idles only briefly. With jobs this short, both pool
//! threads could stay stacked on one CPU for frames on end while the other idled, and the
//! frame took as long as on one thread: `perf sched timehist` of `bench render-to-texture`
//! shows the two workers taking turns on CPU 0 while CPU 1 idles (llvmpipe's two rasteriser
//! threads do the same in its slow frames). Pinned, the pool's halves run side by side.
//!
//! Beside a background draw (see [`super::Renderer`]) the calling thread's front end is the
//! frame's critical path, busy beside the pool: three busy threads on two CPUs. Pinned, the
//! calling thread shares its CPU half and half with a pool thread (gauss-smooth-400 went from
//! 18.2 to 19.7 ms a frame with the pool pinned throughout); left to the scheduler, a pool
//! thread still takes its turns on the caller's CPU (`perf sched`: ~15% of it) while the other
//! CPU idles between jobs. So when a background draw starts, the pool's threads are kept off
//! the CPU the caller is on ([`workers_beside_caller`]): the caller has a CPU to itself and the
//! pool the others, where rayon's work stealing shares the jobs out (gauss-smooth-400 19.4 →
//! 17.6 ms). The next wait for the pool pins them again ([`pin_workers`]). Each switch is one
//! `sched_setaffinity` call per pool thread, made only when the mode (or the caller's CPU at a
//! hand-off) changes.
//!
//! The pool is shared by every context of the process: with several contexts drawing on
//! several threads at once, the last switch wins. Only the speed depends on it, never a pixel.
//!
//! Pinning is skipped where it cannot mean one thread per CPU: a pool of another size than the
//! process's CPU set, a global pool something else started first, systems other than Linux,
//! or `FIXEDGL_PIN_THREADS=0` in the environment.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

/// The global pool's threads that pin themselves.
struct Workers {
    /// Each thread's id and its own CPU.
    threads: Vec<(i32, usize)>,
    /// The CPUs of the process the pool was started on.
    cpus: Vec<usize>,
}

/// The global pool's [`Workers`].
static WORKERS: Mutex<Workers> = Mutex::new(Workers {
    threads: Vec::new(),
    cpus: Vec::new(),
});

/// Where the global pool's threads may run now: [`PINNED`] (each on its CPU, as they start),
/// or every CPU of the process but the one given.
static MODE: AtomicUsize = AtomicUsize::new(PINNED);

/// [`MODE`]: each pool thread on its own CPU.
const PINNED: usize = usize::MAX;

/// Starts rayon's global pool, which every draw uses, if it is not running yet; `Err` with the
/// system's message when its threads cannot be created (rayon reports that only by panicking,
/// on this first use, and never retries: every later use would panic too).
pub(crate) fn start_threads() -> Result<(), String> {
    static START: std::sync::Once = std::sync::Once::new();
    // Fails when the global pool is already running (the caller's own, or the command line's
    // `--threads`): that pool is used as it is. A failure to create threads shows below.
    START.call_once(|| {
        let _ = start_pool(None);
    });
    std::panic::catch_unwind(rayon::current_num_threads)
        .map(|_| ())
        .map_err(|payload| {
            payload
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| payload.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_else(|| "rayon's thread pool did not start".to_string())
        })
}

/// Starts rayon's global pool with `threads` threads (`None`: rayon's default, one per CPU the
/// process may run on, or `RAYON_NUM_THREADS`), each pinned to a CPU of its own while the
/// calling thread waits for the pool when there is one CPU per thread (see the module docs).
/// `Err` when the global pool is already running or its threads cannot be created. For a
/// program that wants another thread count than the default: call it before the first
/// [`Context`](crate::Context).
pub fn start_pool(threads: Option<usize>) -> Result<(), rayon::ThreadPoolBuildError> {
    let cpus = pin_cpus();
    builder(threads, cpus.clone(), true).build_global()?;
    // Read by `set_mode` only, once a draw has the pool: after this.
    WORKERS.lock().unwrap_or_else(|e| e.into_inner()).cpus = cpus;
    Ok(())
}

/// A pool builder for `threads` threads that pin themselves one to each of `cpus` when there
/// are as many, and are listed in [`WORKERS`] if `global`.
fn builder(threads: Option<usize>, cpus: Vec<usize>, global: bool) -> rayon::ThreadPoolBuilder {
    // Named, for `top -H`, `perf` and tests/pool.rs.
    let mut builder = rayon::ThreadPoolBuilder::new().thread_name(|i| format!("fixedgl-draw-{i}"));
    if let Some(n) = threads {
        builder = builder.num_threads(n);
    }
    if !cpus.is_empty() {
        builder = builder.start_handler(move |index| {
            // Only one thread per CPU: a pool of another size keeps the scheduler's placement.
            if rayon::current_num_threads() != cpus.len() {
                return;
            }
            if let Some(&cpu) = cpus.get(index) {
                if pin(0, &[cpu]) && global {
                    let mut workers = WORKERS.lock().unwrap_or_else(|e| e.into_inner());
                    workers.threads.push((thread_id(), cpu));
                }
            }
        });
    }
    builder
}

/// Pins the global pool's threads each to its CPU (see the module docs): for a caller about to
/// wait for the pool or to run a parallel job. Nothing when they already are, or when the pool
/// does not pin.
pub(crate) fn pin_workers() {
    set_mode(PINNED);
}

/// Keeps the global pool's threads off the CPU the calling thread is running on, on every
/// other CPU of the process (see the module docs): for a background draw, beside which the
/// caller goes on. Nothing when the pool does not pin.
pub(crate) fn workers_beside_caller() {
    match current_cpu() {
        Some(cpu) => set_mode(cpu),
        None => pin_workers(),
    }
}

/// Puts the global pool's threads where `mode` (see [`MODE`]) says, if they are not there.
fn set_mode(mode: usize) {
    if MODE.load(Ordering::Relaxed) == mode {
        return;
    }
    let workers = WORKERS.lock().unwrap_or_else(|e| e.into_inner());
    MODE.store(mode, Ordering::Relaxed);
    let Workers { threads, cpus } = &*workers;
    let others: Vec<usize> = cpus.iter().copied().filter(|&c| c != mode).collect();
    for &(tid, cpu) in threads {
        match mode {
            PINNED => pin(tid, &[cpu]),
            // A process of one CPU: that one.
            _ if others.is_empty() => pin(tid, cpus),
            _ => pin(tid, &others),
        };
    }
}

/// The CPUs to pin the pool's threads to: those the calling thread may run on, or none when
/// pinning is off.
fn pin_cpus() -> Vec<usize> {
    match std::env::var_os("FIXEDGL_PIN_THREADS").is_some_and(|v| v == "0") {
        true => Vec::new(),
        false => allowed_cpus(),
    }
}

/// The CPUs the calling thread may run on, in order.
#[cfg(target_os = "linux")]
fn allowed_cpus() -> Vec<usize> {
    affinity(0)
}

/// The CPUs thread `tid` may run on (0: the calling thread), in order.
#[cfg(target_os = "linux")]
fn affinity(tid: i32) -> Vec<usize> {
    // SAFETY: `cpu_set_t` is plain bits (all zeroes is the empty set), and sched_getaffinity
    // writes at most `size_of::<cpu_set_t>()` bytes into it.
    let set = unsafe {
        let mut set: libc::cpu_set_t = std::mem::zeroed();
        if libc::sched_getaffinity(tid, std::mem::size_of::<libc::cpu_set_t>(), &mut set) != 0 {
            return Vec::new();
        }
        set
    };
    let max = 8 * std::mem::size_of::<libc::cpu_set_t>();
    // SAFETY: CPU_ISSET reads bit `cpu` of the set, below its size.
    (0..max)
        .filter(|&cpu| unsafe { libc::CPU_ISSET(cpu, &set) })
        .collect()
}

/// Restricts thread `tid` (0: the calling thread) to `cpus`; whether the system accepted it
/// (a refusal leaves the thread where it was allowed to run).
#[cfg(target_os = "linux")]
fn pin(tid: i32, cpus: &[usize]) -> bool {
    // SAFETY: as in `affinity`; CPU_SET writes bit `cpu`, kept below the set's size.
    unsafe {
        let mut set: libc::cpu_set_t = std::mem::zeroed();
        let max = 8 * std::mem::size_of::<libc::cpu_set_t>();
        for &cpu in cpus.iter().filter(|&&c| c < max) {
            libc::CPU_SET(cpu, &mut set);
        }
        libc::sched_setaffinity(tid, std::mem::size_of::<libc::cpu_set_t>(), &set) == 0
    }
}

/// The CPU the calling thread is running on (it may move the next instant).
#[cfg(target_os = "linux")]
fn current_cpu() -> Option<usize> {
    // SAFETY: sched_getcpu has no preconditions (a vDSO call).
    usize::try_from(unsafe { libc::sched_getcpu() }).ok()
}

/// The calling thread's id, as `sched_setaffinity` takes it.
#[cfg(target_os = "linux")]
fn thread_id() -> i32 {
    // SAFETY: gettid has no preconditions.
    unsafe { libc::gettid() }
}

#[cfg(not(target_os = "linux"))]
fn allowed_cpus() -> Vec<usize> {
    Vec::new()
}

#[cfg(not(target_os = "linux"))]
fn pin(_tid: i32, _cpus: &[usize]) -> bool {
    false
}

#[cfg(not(target_os = "linux"))]
fn current_cpu() -> Option<usize> {
    None
}

#[cfg(not(target_os = "linux"))]
fn thread_id() -> i32 {
    0
}

#[cfg(all(test, target_os = "linux"))]
mod tests {
    use super::*;

    #[test]
    fn a_pool_of_one_thread_per_cpu_is_pinned_one_to_a_cpu() {
        let cpus = allowed_cpus();
        assert!(!cpus.is_empty(), "sched_getaffinity gave no CPU");
        let pool = builder(Some(cpus.len()), cpus.clone(), false)
            .build()
            .expect("pool");
        let mut seen = pool.broadcast(|_| affinity(0));
        // Each thread runs on exactly one CPU, and together they cover the set.
        assert!(seen.iter().all(|set| set.len() == 1), "{seen:?}");
        seen.sort();
        assert_eq!(seen.concat(), cpus);
    }

    #[test]
    fn a_pool_of_another_size_is_left_to_the_scheduler() {
        let cpus = allowed_cpus();
        let pool = builder(Some(cpus.len() + 1), cpus.clone(), false)
            .build()
            .expect("pool");
        let seen = pool.broadcast(|_| affinity(0));
        assert!(seen.iter().all(|set| *set == cpus), "{seen:?}");
    }
}
