//! The draw pool's threads (src/cpu/pool.rs): pinned one to a CPU while the calling thread
//! waits for the pool, kept off the caller's CPU while it works beside them (a background
//! draw). A test binary of its own: the pool is global, and other tests drawing at the same
//! time would move it.

#![cfg(target_os = "linux")]

use fixedgl::{gl, Context};

/// The CPUs in a `Cpus_allowed_list` value such as `0-3,6`.
fn cpu_list(list: &str) -> Vec<usize> {
    let mut cpus = Vec::new();
    for part in list.trim().split(',').filter(|p| !p.is_empty()) {
        let (lo, hi) = part.split_once('-').unwrap_or((part, part));
        let (lo, hi) = (lo.parse::<usize>(), hi.parse::<usize>());
        let (Ok(lo), Ok(hi)) = (lo, hi) else {
            panic!("unreadable CPU list {list:?}");
        };
        cpus.extend(lo..=hi);
    }
    cpus
}

/// The CPUs a thread's status (`/proc/.../status`) allows it.
fn allowed(status: &str) -> Vec<usize> {
    let line = status
        .lines()
        .find_map(|l| l.strip_prefix("Cpus_allowed_list:"))
        .expect("Cpus_allowed_list in the status");
    cpu_list(line)
}

/// The CPU sets of the pool's threads (named `fixedgl-draw-N`), by thread name.
fn pool_threads() -> Vec<(String, Vec<usize>)> {
    let mut found = Vec::new();
    for task in std::fs::read_dir("/proc/self/task").expect("/proc/self/task") {
        let dir = task.expect("task").path();
        let (Ok(comm), Ok(status)) = (
            std::fs::read_to_string(dir.join("comm")),
            std::fs::read_to_string(dir.join("status")),
        ) else {
            continue; // a thread that ended meanwhile
        };
        if comm.starts_with("fixedgl-draw-") {
            found.push((comm.trim().to_string(), allowed(&status)));
        }
    }
    found.sort();
    found
}

#[test]
fn the_pool_is_pinned_while_waited_for_and_off_the_callers_cpu_beside_a_background_draw() {
    let process = allowed(&std::fs::read_to_string("/proc/self/status").expect("status"));
    let mut ctx = Context::new(64, 64).expect("context");
    // Rayon's default: one thread per CPU of the process, unless the environment says otherwise.
    let pins = std::env::var_os("FIXEDGL_PIN_THREADS").is_none_or(|v| v != "0")
        && std::env::var_os("RAYON_NUM_THREADS").is_none();
    let pinned = |threads: &[(String, Vec<usize>)]| {
        let mut cpus: Vec<usize> = threads.iter().flat_map(|(_, c)| c.clone()).collect();
        cpus.sort();
        threads.iter().all(|(_, c)| c.len() == 1) && cpus == process
    };
    let free = |threads: &[(String, Vec<usize>)]| threads.iter().all(|(_, c)| *c == process);
    // Every CPU of the process but one (the caller's at the hand-off), the same for all.
    let beside = |threads: &[(String, Vec<usize>)]| {
        let Some((_, first)) = threads.first() else {
            return false;
        };
        let all_but_one =
            first.len() + 1 == process.len() && first.iter().all(|c| process.contains(c));
        threads.iter().all(|(_, c)| c == first) && (all_but_one || process.len() == 1)
    };

    let threads = pool_threads();
    assert!(!threads.is_empty(), "no fixedgl-draw thread");
    match pins {
        true => {
            assert_eq!(threads.len(), process.len(), "{threads:?}");
            assert!(pinned(&threads), "started: {threads:?} on {process:?}");
        }
        false => assert!(free(&threads), "not to be pinned: {threads:?}"),
    }

    // A batch far above the size that is drawn in the background (points outside the view
    // volume: no fragments), left drawing or drawn when End returns.
    ctx.begin(gl::POINTS);
    for i in 0..200_000 {
        ctx.vertex3f(5.0, i as f32, 0.0);
    }
    ctx.end();
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    let threads = pool_threads();
    match pins {
        true => assert!(beside(&threads), "beside a background draw: {threads:?}"),
        false => assert!(free(&threads), "not to be pinned: {threads:?}"),
    }

    // glFinish waits for the pool: pinned again (where it pins at all).
    ctx.finish();
    let threads = pool_threads();
    match pins {
        true => assert!(pinned(&threads), "after Finish: {threads:?}"),
        false => assert!(free(&threads), "not to be pinned: {threads:?}"),
    }
}
