//! The tracer calls `core::shade` for every shaded point: with `NoRecord` it must not allocate.
//! A counting global allocator (in this test binary only) proves it. It counts only the
//! allocations of the thread that shades, while it shades: the test harness's own threads (its
//! "has been running for over 60 seconds" timer, output capture) allocate at times of their own,
//! and on a loaded machine they did so during the count once.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::sync::atomic::{AtomicUsize, Ordering};

use phong::core::real::v3;
use phong::core::{
    shade, AllVisible, Cone, Falloff, Light, LightKind, LightSet, Material, NoRecord, Real,
    ShadingPoint, Vector,
};

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

thread_local! {
    /// Whether this thread's allocations are counted (const-initialised: reading it allocates
    /// nothing).
    static COUNTING: Cell<bool> = const { Cell::new(false) };
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if COUNTING.try_with(Cell::get).unwrap_or(false) {
            ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        }
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// Shades 1000 points with three kinds of light and returns how many allocations that made.
fn allocations_of_shading<R: Real>() -> usize {
    let lights = LightSet {
        ambient: Some(v3::<R>([0.1; 3])),
        lights: vec![
            Light {
                color: v3::<R>([1.0; 3]),
                kind: LightKind::Point {
                    position: v3::<R>([1.0, 2.0, 3.0]),
                    falloff: Falloff::Quadratic,
                },
            },
            Light {
                color: v3::<R>([1.0; 3]),
                kind: LightKind::Directional {
                    direction: v3::<R>([0.0, 0.0, -1.0]),
                },
            },
            Light {
                color: v3::<R>([1.0; 3]),
                kind: LightKind::Spot {
                    position: v3::<R>([0.0, 0.0, 4.0]),
                    falloff: Falloff::Linear,
                    cone: Cone::new(v3::<R>([0.0, 0.0, -1.0]), R::from_f64(30.0), R::TWO),
                },
            },
        ],
    };
    let m = Material {
        o_a: Some(v3::<R>([0.5, 0.4, 0.6])),
        o_d: Some(v3::<R>([0.7, 0.8, 0.6])),
        o_s: Some(v3::<R>([0.2, 0.3, 0.4])),
        n_s: R::from_f64(8.0),
        o_r: None,
        transmission: None,
    };
    let mut sum = v3::<R>([0.0; 3]);
    let before = ALLOCATIONS.load(Ordering::SeqCst);
    COUNTING.with(|c| c.set(true));
    for i in 0..1000 {
        let at = ShadingPoint {
            p: v3::<R>([f64::from(i) * 1e-3, 0.0, 0.0]),
            n: v3::<R>([0.0, 0.0, 1.0]),
            v: Some(v3::<R>([0.0, 0.6, -0.8])),
        };
        sum += shade(&at, &m, &lights, &mut AllVisible, &mut NoRecord).color;
    }
    COUNTING.with(|c| c.set(false));
    let made = ALLOCATIONS.load(Ordering::SeqCst) - before;
    assert!(sum.is_finite());
    made
}

#[test]
fn shading_without_a_record_does_not_allocate() {
    // One test (not two) so that no other test thread allocates while the count runs.
    assert_eq!(allocations_of_shading::<f32>(), 0, "f32");
    assert_eq!(allocations_of_shading::<f64>(), 0, "f64");
}
