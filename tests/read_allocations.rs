//! Reading a large scene allocates a bounded number of times per object (issue 17, item 5): a
//! valid file is parsed without tracking field paths and validated without writing field names,
//! so no `String` is formatted per vector, number or surface. A counting global allocator (in
//! this test binary only) counts the allocations (and reallocations) of the reading thread while
//! it reads. Before the change a sphere cost about 25 (19 allocations and 6 reallocations: the
//! path's keys, `surfaces[i].center[0]` and its siblings); now it costs 2 (its material's name,
//! as read and as validated).

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};

use phong::problem::{self, ProblemError};

#[path = "../scenes/many_spheres.rs"]
mod many_spheres;

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

thread_local! {
    /// Whether this thread's allocations are counted (const-initialised: reading it allocates
    /// nothing).
    static COUNTING: Cell<bool> = const { Cell::new(false) };
}

fn count() {
    if COUNTING.try_with(Cell::get).unwrap_or(false) {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
    }
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count();
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count();
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// The allocations made while `f` runs on this thread.
fn allocations<T>(f: impl FnOnce() -> T) -> (usize, T) {
    let before = ALLOCATIONS.load(Ordering::SeqCst);
    COUNTING.with(|c| c.set(true));
    let out = f();
    COUNTING.with(|c| c.set(false));
    (ALLOCATIONS.load(Ordering::SeqCst) - before, out)
}

const SPHERES: usize = 10_000;

fn write_scene(dir: &Path, text: &str) -> std::path::PathBuf {
    let path = dir.join("many.json");
    std::fs::write(&path, text).expect("the scene is written");
    path
}

#[test]
fn reading_a_large_scene_allocates_at_most_three_times_per_object() {
    let dir = tempfile::tempdir().unwrap();
    let path = write_scene(dir.path(), &many_spheres::scene(SPHERES).to_string());
    for precision in ["f64", "f32"] {
        let (n, surfaces) = allocations(|| match precision {
            "f64" => problem::load::<f64>(&path).map(|(_, p)| p.surfaces().len()),
            _ => problem::load::<f32>(&path).map(|(_, p)| p.surfaces().len()),
        });
        let surfaces = surfaces.expect("a valid scene");
        assert_eq!(surfaces, SPHERES + 1);
        let per_object = n as f64 / surfaces as f64;
        assert!(
            per_object <= 3.0,
            "{precision}: {n} allocations for {surfaces} surfaces, {per_object:.2} per object"
        );
    }
}

#[test]
fn an_error_deep_in_a_large_scene_still_names_its_field() {
    let dir = tempfile::tempdir().unwrap();
    let mut scene = many_spheres::scene(SPHERES);
    scene["surfaces"][9_000]["radius"] = serde_json::json!(-1);
    scene["surfaces"][9_500]["center"] = serde_json::json!([0, "1", 0]);
    // The validation error: the parse succeeds without the second change.
    let mut valid_json = scene.clone();
    valid_json["surfaces"][9_500]["center"] = serde_json::json!([0, 1, 0]);
    let path = write_scene(dir.path(), &valid_json.to_string());
    match problem::load::<f64>(&path) {
        Err(e @ ProblemError::Invalid { .. }) => {
            assert_eq!(e.field(), Some("surfaces[9000].radius"));
            assert_eq!(e.message(), "-1 is not a radius");
        }
        other => panic!("expected a validation error, got {other:?}"),
    }
    // The parse error: found by the second, tracked reading, with its path.
    let path = write_scene(dir.path(), &scene.to_string());
    match problem::load::<f64>(&path) {
        Err(e @ ProblemError::Syntax { .. }) => {
            assert_eq!(e.field(), Some("surfaces[9500].center[1]"));
            assert!(e.message().starts_with("invalid type: string \"1\""), "{e}");
            assert!(
                e.to_string()
                    .contains(": surfaces[9500].center[1]: invalid type"),
                "{e}"
            );
        }
        other => panic!("expected a syntax error, got {other:?}"),
    }
}
