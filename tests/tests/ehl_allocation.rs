//! The EHL solver allocates nothing inside its Newton iterations: after the `Solver` is built,
//! a solve performs only the allocations of its result (the three profile vectors), however many
//! iterations it takes. Checked with a counting global allocator (this test binary only).

use bearing_ehl::{ContactCase, Solver, SolverOptions};
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

struct Counting;
static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        // SAFETY: forwards the caller's layout contract to the system allocator.
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: `ptr` was allocated by `System.alloc` with this layout.
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        // SAFETY: same contract as `System.realloc`.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn newton_loop_does_not_allocate() {
    let mut solver = Solver::new(SolverOptions::fast()).unwrap();
    // Two cases needing very different iteration counts (light and heavy piezoviscous load).
    let light = ContactCase::from_moes(20.0, 3.0).unwrap();
    let heavy = ContactCase::new(6.0e5, 2.0, 0.006, 2.26e11, 2.5e-8, 0.02).unwrap();
    let _ = solver.solve(&light).unwrap();
    for case in [light, heavy] {
        let before = ALLOCATIONS.load(Ordering::Relaxed);
        let sol = solver.solve(&case).unwrap();
        let during = ALLOCATIONS.load(Ordering::Relaxed) - before;
        assert!(sol.iterations >= 3);
        assert_eq!(
            during, 3,
            "{} allocations in a {}-iteration solve",
            during, sol.iterations
        );
    }
}
