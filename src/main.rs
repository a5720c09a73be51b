//! The `phong` binary: a thin shell around [`phong::cli`], and its allocator.

use std::alloc::{GlobalAlloc, Layout, System};

/// The system's allocator, except that an allocation it refuses ends the program with
/// `phong::cli::memory::out_of_memory`'s clear error (exit 2, a file being written removed)
/// instead of Rust's abort (exit 134), unless the code that asked is ready to see it refused
/// (`phong::text::memory::handled`: a `try_reserve` that reports what it needs itself).
///
/// Stable Rust has no hook for an allocation failure (`std::alloc::set_alloc_error_hook` is
/// unstable), so this is the one place it can be caught. This is the crate's only `unsafe`
/// code (the library forbids it): `GlobalAlloc` is an unsafe trait.
struct Allocator;

/// What a refused allocation of `size` bytes does: nothing where the code handles it (the null
/// pointer goes back to it), else the end of the program.
fn refused(size: usize) {
    if !phong::text::memory::is_handled() {
        phong::cli::memory::out_of_memory(size);
    }
}

// SAFETY: every method forwards its arguments unchanged to `System`, which upholds
// `GlobalAlloc`'s contract, and returns what `System` returned; on a null pointer it may
// instead never return (`out_of_memory` ends the process without unwinding), which the
// contract allows (the default handler aborts). `refused` allocates nothing while it runs
// (`phong::cli::memory`), so the allocator is not re-entered with its own failure.
unsafe impl GlobalAlloc for Allocator {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: the caller upholds `alloc`'s contract, which is `System.alloc`'s.
        let p = unsafe { System.alloc(layout) };
        if p.is_null() {
            refused(layout.size());
        }
        p
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        // SAFETY: as `alloc`.
        let p = unsafe { System.alloc_zeroed(layout) };
        if p.is_null() {
            refused(layout.size());
        }
        p
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: `ptr` was allocated by this allocator, that is by `System`, with `layout`.
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: `ptr` was allocated by `System` with `layout`; the caller upholds the rest.
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if p.is_null() {
            refused(new_size);
        }
        p
    }
}

#[global_allocator]
static ALLOCATOR: Allocator = Allocator;

fn main() -> std::process::ExitCode {
    phong::cli::main()
}
