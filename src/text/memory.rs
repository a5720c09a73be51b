//! Allocations the code is ready to see refused.
//!
//! The `phong` binary's allocator (`src/main.rs`) ends the program with a clear error (exit 2,
//! a file being written removed: `cli::memory`) when the system refuses memory, rather than
//! Rust's abort ("memory allocation of N bytes failed", exit 134). A few places ask for a
//! large block with `try_reserve` and say themselves what it needs (a render's image, a mesh's
//! triangles): they do so inside [`handled`], where a refusal is returned to them as usual.
//!
//! The count is a thread-local `Cell` with a constant initialiser and no destructor, so reading
//! it from inside the allocator allocates nothing.

use std::cell::Cell;

thread_local! {
    static HANDLED: Cell<u32> = const { Cell::new(0) };
}

/// Runs `f`, in which a refused allocation is handled by the code that asked for it (a
/// `try_reserve` whose error it reports).
pub fn handled<T>(f: impl FnOnce() -> T) -> T {
    /// Ends the scope even if `f` panics.
    struct Scope;
    impl Drop for Scope {
        fn drop(&mut self) {
            HANDLED.with(|h| h.set(h.get().saturating_sub(1)));
        }
    }
    HANDLED.with(|h| h.set(h.get() + 1));
    let _scope = Scope;
    f()
}

/// Whether this thread is inside [`handled`] (false while the thread is being torn down).
pub fn is_handled() -> bool {
    HANDLED.try_with(|h| h.get() > 0).unwrap_or(false)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_scope_is_this_thread_s_and_ends() {
        assert!(!is_handled());
        let inside = handled(|| {
            let other = std::thread::spawn(is_handled).join().unwrap();
            (is_handled(), handled(is_handled), other)
        });
        assert_eq!(inside, (true, true, false));
        assert!(!is_handled());
        let _ = std::panic::catch_unwind(|| handled(|| panic!("x")));
        assert!(!is_handled());
    }
}
