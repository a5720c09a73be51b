//! The end of a run the system refuses memory to: the error, in the run's language, on standard
//! error, the temporary files being written removed, exit 2 (README, "Limits and safety"),
//! rather than Rust's abort ("memory allocation of N bytes failed", exit 134, a temporary file
//! left behind). The `phong` binary's allocator (`src/main.rs`) calls [`out_of_memory`] when
//! the system refuses an allocation that no code is ready to see refused
//! ([`crate::text::memory::handled`]).
//!
//! Nothing here may allocate: the message is rendered beforehand (`prepare`), the size is
//! written into a buffer on the stack, standard error is written through a duplicate of its
//! file descriptor (no lock, no buffer), and the program ends with `_exit(2)`
//! (`signal_hook::low_level::exit`), which runs no destructor and flushes nothing, so no
//! buffered part of a report reaches its file.

use std::io::Write as _;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;

use super::faults::CliFault;
use crate::problem::error::what_and_fix;
use crate::text::Lang;

/// The error's text before and after its size, in the run's language.
static MESSAGE: Mutex<Option<(String, String)>> = Mutex::new(None);

/// Renders the error in `lang`, for [`out_of_memory`] to write without allocating. Called when
/// the program starts (the locale's language) and again when the command's is known.
pub(crate) fn prepare(lang: Lang) {
    const MARK: &str = "\u{0}";
    let text = format!(
        "{}: {}\n",
        crate::report::messages::error_word(lang),
        what_and_fix(&CliFault::MemoryRefused { size: MARK.into() }, lang)
    );
    let (before, after) = text.split_once(MARK).unwrap_or((&text, ""));
    if let Ok(mut m) = MESSAGE.lock() {
        *m = Some((before.to_owned(), after.to_owned()));
    }
}

/// `bytes` as whole megabytes (10^6 bytes, rounded up; at least 1), `26 MB`, written into
/// `buf`: the text's length.
fn megabytes(bytes: usize, buf: &mut [u8; 32]) -> usize {
    let mut n = bytes.div_ceil(1_000_000).max(1);
    let mut digits = [0u8; 20];
    let mut len = 0;
    while n > 0 || len == 0 {
        digits[len] = b'0' + (n % 10) as u8;
        n /= 10;
        len += 1;
    }
    for i in 0..len {
        buf[i] = digits[len - 1 - i];
    }
    buf[len..len + 3].copy_from_slice(b" MB");
    len + 3
}

/// Ends the program: the temporary files being written removed, the error on standard error,
/// exit 2. `size` is the allocation refused, in bytes. Allocates nothing; a second refusal
/// while it runs (another thread's) ends the program at once with exit 2.
pub fn out_of_memory(size: usize) -> ! {
    static ENDING: AtomicBool = AtomicBool::new(false);
    if ENDING.swap(true, Ordering::SeqCst) {
        signal_hook::low_level::exit(2);
    }
    super::files::remove_pending_now();
    let mut number = [0u8; 32];
    let len = megabytes(size, &mut number);
    if let (Some(mut err), Ok(message)) = (stderr(), MESSAGE.try_lock()) {
        if let Some((before, after)) = message.as_ref() {
            let _ = err.write_all(before.as_bytes());
            let _ = err.write_all(&number[..len]);
            let _ = err.write_all(after.as_bytes());
        }
    }
    signal_hook::low_level::exit(2)
}

/// Standard error as a file of its own (a duplicate of its descriptor: no lock, no buffer).
#[cfg(unix)]
fn stderr() -> Option<std::fs::File> {
    use std::os::fd::AsFd as _;
    let fd = std::io::stderr().as_fd().try_clone_to_owned().ok()?;
    Some(std::fs::File::from(fd))
}

/// Standard error (unbuffered in std) where descriptors are not Unix's.
#[cfg(not(unix))]
fn stderr() -> Option<std::io::Stderr> {
    Some(std::io::stderr())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_are_whole_megabytes_rounded_up() {
        let text = |bytes| {
            let mut buf = [0u8; 32];
            let len = megabytes(bytes, &mut buf);
            String::from_utf8(buf[..len].to_vec()).unwrap()
        };
        assert_eq!(text(0), "1 MB");
        assert_eq!(text(1), "1 MB");
        assert_eq!(text(25_165_824), "26 MB");
        assert_eq!(text(2_147_483_648), "2148 MB");
        assert_eq!(text(usize::MAX), "18446744073710 MB");
    }
}
