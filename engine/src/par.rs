//! Work spread over scoped threads: each thread takes the next item not yet taken, so large and
//! small items balance themselves. No thread pool, no dependency: the conversion, the sizing and
//! the collision shapes run a handful of such loops, each a few milliseconds to seconds long.

use std::sync::atomic::{AtomicUsize, Ordering};

/// The threads a loop over the machine's cores should use: its cores, at most `cap`.
pub fn threads(cap: usize) -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get()).min(cap).max(1)
}

/// `work(state, item)` for every item, on up to `threads` threads (this one among them; at most
/// one per item), each with its own `state()` (a deflater, a scratch buffer). The results are in
/// the order of `items`, whatever the threads' timing. A panic in any thread is raised here, as
/// it would be without threads.
pub fn map_ordered<T: Sync, S, R: Send>(
    items: &[T],
    threads: usize,
    state: impl Fn() -> S + Sync,
    work: impl Fn(&mut S, &T) -> R + Sync,
) -> Vec<R> {
    let threads = threads.clamp(1, items.len().max(1));
    if threads == 1 {
        let mut s = state();
        return items.iter().map(|t| work(&mut s, t)).collect();
    }
    let next = AtomicUsize::new(0);
    let run = || {
        let mut s = state();
        let mut mine = Vec::new();
        loop {
            let i = next.fetch_add(1, Ordering::Relaxed);
            let Some(t) = items.get(i) else { break mine };
            mine.push((i, work(&mut s, t)));
        }
    };
    let mut all: Vec<(usize, R)> = std::thread::scope(|scope| {
        let helpers: Vec<_> = (1..threads).map(|_| scope.spawn(run)).collect();
        let mut all = run();
        for h in helpers {
            all.extend(h.join().unwrap_or_else(|p| std::panic::resume_unwind(p)));
        }
        all
    });
    all.sort_by_key(|(i, _)| *i);
    all.into_iter().map(|(_, r)| r).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// In order on any number of threads, each thread with its own state; uneven items.
    #[test]
    fn results_in_the_items_order() {
        let items: Vec<u64> = (0..200).map(|i| (i * 7919) % 1000).collect();
        let slow = |n: &mut u64, x: &u64| {
            *n += 1;
            (0..*x * 50).fold(*x, |a, b| a.wrapping_mul(31).wrapping_add(b))
        };
        let one: Vec<u64> = items.iter().map(|x| slow(&mut 0, x)).collect();
        for t in [1, 2, 3, 8, 500] {
            assert_eq!(map_ordered(&items, t, || 0u64, slow), one, "{t} threads");
        }
        assert!(map_ordered(&[] as &[u64], 4, || 0u64, slow).is_empty());
    }
}
