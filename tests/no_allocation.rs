//! The tracer will call `core::shade` for every pixel: with `NoRecord` it must not allocate.
//! A counting global allocator (in this test binary only) proves it.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use glam::DVec3;
use phong::core::{
    shade, AllVisible, Cone, Falloff, Light, LightKind, LightSet, Material, NoRecord, ShadingPoint,
};

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn shading_without_a_record_does_not_allocate() {
    let lights = LightSet {
        ambient: Some(DVec3::splat(0.1)),
        lights: vec![
            Light {
                color: DVec3::ONE,
                kind: LightKind::Point {
                    position: DVec3::new(1.0, 2.0, 3.0),
                    falloff: Falloff::Quadratic,
                },
            },
            Light {
                color: DVec3::ONE,
                kind: LightKind::Directional {
                    direction: DVec3::new(0.0, 0.0, -1.0),
                },
            },
            Light {
                color: DVec3::ONE,
                kind: LightKind::Spot {
                    position: DVec3::new(0.0, 0.0, 4.0),
                    falloff: Falloff::Linear,
                    cone: Cone::new(DVec3::new(0.0, 0.0, -1.0), 30.0, 2.0),
                },
            },
        ],
    };
    let m = Material {
        o_a: Some(DVec3::new(0.5, 0.4, 0.6)),
        o_d: Some(DVec3::new(0.7, 0.8, 0.6)),
        o_s: Some(DVec3::new(0.2, 0.3, 0.4)),
        n_s: 8.0,
        o_r: None,
    };
    let before = ALLOCATIONS.load(Ordering::SeqCst);
    let mut sum = DVec3::ZERO;
    for i in 0..1000 {
        let x = f64::from(i) * 1e-3;
        let at = ShadingPoint {
            p: DVec3::new(x, 0.0, 0.0),
            n: DVec3::Z,
            v: Some(DVec3::new(0.0, 0.6, -0.8)),
        };
        sum += shade(&at, &m, &lights, &mut AllVisible, &mut NoRecord).color;
    }
    let after = ALLOCATIONS.load(Ordering::SeqCst);
    assert!(sum.is_finite());
    assert_eq!(
        after - before,
        0,
        "shade allocated {} times",
        after - before
    );
}
