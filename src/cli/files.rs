//! Output files written safely (README, "Limits and safety"): `-` is standard output; a path
//! that names one of the program's own streams (`/dev/stdout`, `/dev/stderr`, `/dev/fd/N`,
//! `/proc/self/fd/N`, as given or through links) is written into that stream, after what it
//! already holds, never replacing or truncating the file it may be redirected to; a
//! symbolic link is followed and its target replaced; a target that is not a regular file (a
//! device such as `/dev/null`, a FIFO) is written directly, never replaced; a
//! folder is refused; a regular file is replaced atomically (a temporary file in the same folder,
//! renamed into place, so a failure never leaves a half-written file); a new file gets the
//! permissions the umask allows (0666 less the umask), an existing one keeps its own. The
//! temporary file is removed on every error and, through [`guard_signals`], on SIGINT, SIGTERM
//! and SIGHUP. An output that is an input of the same run, or another of its outputs, is refused
//! before anything is written ([`distinct`]). A run with several outputs writes them all or
//! nothing ([`Batch`]): every one written in full before any is put in place.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use super::error::CliError;
use super::faults::{CliFault, OutputFault};
use super::output::is_dash;

/// The file a path names once its symbolic links are followed (the link's target is what is
/// replaced, the link stays); a dangling link names the file it would create.
fn through_links(path: &Path) -> std::io::Result<PathBuf> {
    let mut p = path.to_owned();
    // As the kernel does (ELOOP after 40 links).
    for _ in 0..40 {
        match std::fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => {
                let to = std::fs::read_link(&p)?;
                p = match p.parent() {
                    Some(dir) if to.is_relative() => dir.join(to),
                    _ => to,
                };
            }
            _ => return Ok(p),
        }
    }
    Err(OutputFault::io(
        std::io::ErrorKind::Other,
        CliFault::LinkLoop,
    ))
}

/// `-o` names a folder.
fn is_a_folder() -> std::io::Error {
    OutputFault::io(std::io::ErrorKind::Other, CliFault::IsAFolder)
}

/// The file descriptor of this process that `path` names, as given or through its links:
/// `/dev/stdin`, `/dev/stdout`, `/dev/stderr` (0, 1, 2), `/dev/fd/N`, `/proc/self/fd/N`,
/// `/proc/thread-self/fd/N` or `/proc/PID/fd/N` with this process's PID. `None` for any other
/// path.
pub(crate) fn stream_of(path: &Path) -> Option<u32> {
    let mut p = path.to_owned();
    for _ in 0..40 {
        if let Some(fd) = fd_named(&p) {
            return Some(fd);
        }
        // A relative path, or one through `..`, named by its folder's real path.
        if let (Some(dir), Some(name)) = (p.parent(), p.file_name()) {
            let dir = if dir.as_os_str().is_empty() {
                Path::new(".")
            } else {
                dir
            };
            if let Some(fd) = std::fs::canonicalize(dir)
                .ok()
                .and_then(|d| fd_named(&d.join(name)))
            {
                return Some(fd);
            }
        }
        match std::fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => {
                let to = std::fs::read_link(&p).ok()?;
                p = match p.parent() {
                    Some(dir) if to.is_relative() => dir.join(to),
                    _ => to,
                };
            }
            _ => return None,
        }
    }
    None
}

/// The file descriptor `path` names as written (see [`stream_of`]).
fn fd_named(path: &Path) -> Option<u32> {
    let text = path.to_str()?;
    match text {
        "/dev/stdin" => return Some(0),
        "/dev/stdout" => return Some(1),
        "/dev/stderr" => return Some(2),
        _ => {}
    }
    let own = format!("/proc/{}/fd/", std::process::id());
    let number = [
        "/dev/fd/",
        "/proc/self/fd/",
        "/proc/thread-self/fd/",
        own.as_str(),
    ]
    .iter()
    .find_map(|prefix| text.strip_prefix(prefix))?;
    if number.is_empty() || !number.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    number.parse().ok()
}

/// Writes to the program's file descriptor `fd` whatever `write` writes: standard output and
/// standard error through Rust's own handles (so that the bytes come in order with the
/// program's other output), another descriptor opened for appending, so that what the file
/// it may be redirected to holds is kept. A reader that has gone (EPIPE) is not an error of
/// ours.
fn to_stream(fd: u32, write: Writer<'_>) -> std::io::Result<()> {
    let result = match fd {
        1 => {
            let mut out = std::io::BufWriter::new(std::io::stdout().lock());
            write(&mut out).and_then(|()| out.flush())
        }
        2 => {
            let mut out = std::io::BufWriter::new(std::io::stderr().lock());
            write(&mut out).and_then(|()| out.flush())
        }
        n => {
            let file = std::fs::OpenOptions::new()
                .append(true)
                .open(format!("/proc/self/fd/{n}"))?;
            let mut out = std::io::BufWriter::new(file);
            write(&mut out).and_then(|()| out.flush())
        }
    };
    match result {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        other => other,
    }
}

/// What writes an output's bytes, to whatever it is given.
pub(crate) type Writer<'a> = &'a mut dyn FnMut(&mut dyn Write) -> std::io::Result<()>;

/// Where an output goes, once its links are followed.
enum Target {
    /// One of the program's own streams ([`stream_of`]): written after what it holds.
    Stream(u32),
    /// A regular file, or a new one: replaced atomically; the permissions of the file replaced,
    /// kept.
    File(PathBuf, Option<std::fs::Permissions>),
    /// A device, a FIFO, a terminal: written to, never replaced.
    Device(PathBuf),
}

/// Where `path` writes to; a folder (or a missing path ending in `/`) is refused.
fn target_of(path: &Path) -> std::io::Result<Target> {
    if let Some(fd) = stream_of(path) {
        return Ok(Target::Stream(fd));
    }
    let target = through_links(path)?;
    match std::fs::metadata(&target) {
        Ok(m) if m.is_dir() => Err(is_a_folder()),
        Ok(m) if m.is_file() => Ok(Target::File(target, Some(m.permissions()))),
        Ok(_) => Ok(Target::Device(target)),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            if path.as_os_str().to_string_lossy().ends_with('/') {
                return Err(is_a_folder());
            }
            Ok(Target::File(target, None))
        }
        Err(e) => Err(e),
    }
}

/// Writes what `write` writes straight into the device (or FIFO) `path`.
fn to_device(path: &Path, write: Writer<'_>) -> std::io::Result<()> {
    let f = std::fs::OpenOptions::new().write(true).open(path)?;
    let mut out = std::io::BufWriter::new(f);
    write(&mut out)?;
    out.flush()
}

/// Writes to `path` what `write` writes, as it writes it: one of the program's own streams
/// ([`stream_of`]) after what it holds; a regular file (or a new one) atomically, through a
/// temporary file that an error removes; anything else (a device, a FIFO) directly.
pub(crate) fn write_target_with(path: &Path, write: Writer<'_>) -> std::io::Result<()> {
    match target_of(path)? {
        Target::Stream(fd) => to_stream(fd, write),
        Target::File(target, existing) => stage(&target, write, existing)?.persist(),
        Target::Device(target) => to_device(&target, write),
    }
}

/// The outputs of a run written all or nothing (`phong grade`'s report, summary, totals and
/// class page; `phong tradeoff`'s table and plot; `phong solve -o DIR/`'s files): each is
/// written in full first, a file to its temporary file beside it, standard output, another
/// of the program's streams or a device to a buffer (in memory, spilling to an unnamed
/// temporary file when large); only once every one is written does [`Batch::commit`] copy the
/// buffers out and rename the temporary files into place. An error before the commit (a full
/// disk, a folder that cannot be written, a bug) drops the batch: the temporary files and the
/// folders it made are removed, and no output is changed. The renames come last, after the
/// streams, since they are what may fail least: a rename that still fails (another user's file
/// in a sticky folder such as /tmp) leaves the outputs renamed before it.
pub(crate) struct Batch {
    held: Vec<(Option<PathBuf>, Held)>,
    /// The folders this batch made, outermost first: removed, when empty, unless committed.
    folders: Vec<PathBuf>,
    committed: bool,
}

/// One output of a [`Batch`], written and waiting.
enum Held {
    File(Staged),
    Stream(u32, tempfile::SpooledTempFile),
    Device(PathBuf, tempfile::SpooledTempFile),
}

/// How much of an output to a stream or a device a [`Batch`] keeps in memory before it spills
/// to an unnamed temporary file.
const HELD_IN_MEMORY: usize = 1 << 20;

impl Batch {
    pub(crate) fn new() -> Batch {
        Batch {
            held: Vec::new(),
            folders: Vec::new(),
            committed: false,
        }
    }

    /// Writes, in full, the output `path` (standard output: `None` or `-`), by the rules of
    /// this module, to be put in place by [`Batch::commit`]. The error names the output.
    pub(crate) fn add(&mut self, path: Option<&Path>, write: Writer<'_>) -> Result<(), CliError> {
        let path = path.filter(|p| !is_dash(p));
        let held = match path {
            None => hold(write).map(|h| Held::Stream(1, h)),
            Some(p) => target_of(p).and_then(|t| match t {
                Target::Stream(fd) => hold(write).map(|h| Held::Stream(fd, h)),
                Target::File(target, existing) => stage(&target, write, existing).map(Held::File),
                Target::Device(target) => hold(write).map(|h| Held::Device(target, h)),
            }),
        };
        let held = held.map_err(|source| CliError::Write {
            path: path.map(Path::to_owned),
            source,
        })?;
        self.held.push((path.map(Path::to_owned), held));
        Ok(())
    }

    /// Makes the folder `dir` (and the folders above it that are missing), to be removed again
    /// when the batch is dropped without its commit.
    pub(crate) fn create_folder(&mut self, dir: &Path) -> Result<(), CliError> {
        let mut missing = Vec::new();
        let mut d = Some(dir);
        while let Some(f) = d.filter(|f| !f.as_os_str().is_empty()) {
            if std::fs::symlink_metadata(f).is_ok() {
                break;
            }
            missing.push(f.to_owned());
            d = f.parent();
        }
        std::fs::create_dir_all(dir).map_err(|source| CliError::CreateFolder {
            path: dir.to_owned(),
            source,
        })?;
        self.folders.extend(missing.into_iter().rev());
        Ok(())
    }

    /// Puts every output in place: the buffers copied out to their streams and devices, in
    /// the order they were added, then the temporary files renamed over their files.
    pub(crate) fn commit(mut self) -> Result<(), CliError> {
        let mut files = Vec::new();
        for (path, held) in std::mem::take(&mut self.held) {
            let written = match held {
                Held::File(staged) => {
                    files.push((path, staged));
                    continue;
                }
                Held::Stream(fd, mut h) => {
                    rewind(&mut h).and_then(|()| to_stream(fd, &mut |w| copy(&mut h, w)))
                }
                Held::Device(target, mut h) => {
                    rewind(&mut h).and_then(|()| to_device(&target, &mut |w| copy(&mut h, w)))
                }
            };
            written.map_err(|source| CliError::Write { path, source })?;
        }
        // From the first rename on, the folders hold an output.
        self.committed = true;
        for (path, staged) in files {
            staged
                .persist()
                .map_err(|source| CliError::Write { path, source })?;
        }
        Ok(())
    }
}

impl Drop for Batch {
    fn drop(&mut self) {
        // The temporary files first, then the folders they were in (only when empty).
        self.held.clear();
        if !self.committed {
            for f in self.folders.iter().rev() {
                let _ = std::fs::remove_dir(f);
            }
        }
    }
}

/// What `write` writes, held in a buffer until the commit.
fn hold(write: Writer<'_>) -> std::io::Result<tempfile::SpooledTempFile> {
    let mut held = tempfile::spooled_tempfile(HELD_IN_MEMORY);
    write(&mut held)?;
    Ok(held)
}

fn rewind(held: &mut tempfile::SpooledTempFile) -> std::io::Result<()> {
    use std::io::Seek;
    held.seek(std::io::SeekFrom::Start(0)).map(|_| ())
}

fn copy(from: &mut tempfile::SpooledTempFile, to: &mut dyn Write) -> std::io::Result<()> {
    std::io::copy(from, to).map(|_| ())
}

/// The temporary files being written, removed by [`remove_pending`] when a signal stops the
/// program.
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// A temporary file listed in [`PENDING`] while it lives.
struct Pending(PathBuf);

impl Pending {
    fn new(path: &Path) -> Pending {
        if let Ok(mut list) = PENDING.lock() {
            list.push(path.to_owned());
        }
        Pending(path.to_owned())
    }
}

impl Drop for Pending {
    fn drop(&mut self) {
        if let Ok(mut list) = PENDING.lock() {
            list.retain(|p| p != &self.0);
        }
    }
}

/// Removes every temporary file still being written (the signal handler's work).
fn remove_pending() {
    // A panicking writer poisons the lock; the list is still right.
    let list = PENDING.lock().unwrap_or_else(|e| e.into_inner());
    for p in list.iter() {
        let _ = std::fs::remove_file(p);
    }
}

/// Removes every temporary file still being written, unless the list is being changed at this
/// moment (then nothing): what [`super::memory::out_of_memory`] does, from inside the
/// allocator, where waiting for the lock could wait for ever (the thread holding it may be the
/// one refused memory). `remove_file` of a path shorter than std's stack buffer (384 bytes)
/// allocates nothing.
pub(crate) fn remove_pending_now() {
    let list = match PENDING.try_lock() {
        Ok(list) => list,
        Err(std::sync::TryLockError::Poisoned(e)) => e.into_inner(),
        Err(std::sync::TryLockError::WouldBlock) => return,
    };
    for p in list.iter() {
        let _ = std::fs::remove_file(p);
    }
}

/// On SIGINT, SIGTERM or SIGHUP, the temporary files being written are removed before the
/// program ends by the signal as it would have; SIGXFSZ (a file over the size limit) becomes
/// the write error EFBIG, so the temporary file is removed as on any other error. Call once.
pub(crate) fn guard_signals() {
    #[cfg(unix)]
    {
        use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM, SIGXFSZ};
        let flag = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
        let _ = signal_hook::flag::register(SIGXFSZ, flag);
        if let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) {
            let (ready, started) = std::sync::mpsc::sync_channel::<()>(1);
            let spawned = std::thread::Builder::new()
                .name("signals".into())
                .spawn(move || {
                    let _ = ready.send(());
                    if let Some(signal) = signals.forever().next() {
                        remove_pending();
                        let _ = signal_hook::low_level::emulate_default_handler(signal);
                        std::process::exit(128 + signal);
                    }
                });
            // Until the thread runs: its start (std's alternative signal stack) takes its
            // memory before the work does. Started after, under a memory limit the work had
            // taken, it failed with std's panic message before phong's own error.
            if spawned.is_ok() {
                let _ = started.recv();
            }
        }
    }
}

/// A regular file's new contents, written in full to a temporary file in its folder (synced,
/// with the permissions it will have), waiting to be renamed into place. Dropped, the temporary
/// file is removed.
struct Staged {
    tmp: tempfile::TempPath,
    target: PathBuf,
    // Dropped after `tmp`: listed until the file is gone.
    _pending: Pending,
}

impl Staged {
    /// The temporary file renamed over the file (on failure it is removed).
    fn persist(self) -> std::io::Result<()> {
        self.tmp.persist(&self.target).map_err(|e| e.error)
    }
}

/// Writes what `write` writes for the regular file `path` to a temporary file in the same
/// folder, to be renamed into place ([`Staged::persist`]). `existing`: the permissions of the
/// file replaced, kept; a new file is created with 0666 less the umask, as any program's. The
/// temporary file is closed once written (a batch may hold thousands).
fn stage(
    path: &Path,
    write: Writer<'_>,
    existing: Option<std::fs::Permissions>,
) -> std::io::Result<Staged> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    // The temporary file is opened here (`make_in`), not by tempfile's `tempfile_in`, whose
    // error is the system's wrapped with the temporary file's random name (`… at path
    // "/sys/.phong-Ab12Cd.tmp"`, a name the user never gave) and without its error number (so
    // it could not be said in Portuguese). Here it is the system's error as it came.
    let mut tmp = tempfile::Builder::new()
        .prefix(".phong-")
        .suffix(".tmp")
        .make_in(dir, |path| create_new(path, existing.is_none()))
        .map_err(|e| folder_problem(dir).unwrap_or(e))?;
    let pending = Pending::new(tmp.path());
    {
        let mut out = std::io::BufWriter::new(tmp.as_file_mut());
        write(&mut out)?;
        out.flush()?;
    }
    if let Some(p) = existing {
        tmp.as_file().set_permissions(p)?;
    }
    tmp.as_file().sync_all()?;
    Ok(Staged {
        tmp: tmp.into_temp_path(),
        target: path.to_owned(),
        _pending: pending,
    })
}

/// Creates the temporary file `path`, new (it fails if anything has that name: tempfile then
/// tries another), for reading and writing, as tempfile would: with 0666 less the umask when it
/// is to be a new file (`new`; open(2) takes the umask away), else 0600 until the permissions
/// of the file it replaces are set on it.
fn create_new(path: &Path, new: bool) -> std::io::Result<std::fs::File> {
    let mut options = std::fs::OpenOptions::new();
    options.read(true).write(true).create_new(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.mode(if new { 0o666 } else { 0o600 });
    }
    #[cfg(not(unix))]
    let _ = new;
    options.open(path)
}

/// Why no file can be written in `dir`, when it is missing or is not a folder: the folder the
/// user named, with its fix, said in the user's language where it is shown
/// ([`super::faults::SystemError`]; `None` when it is a folder). A command that writes several
/// files asks this of each one's folder before writing any.
pub(crate) fn folder_problem(dir: &Path) -> Option<std::io::Error> {
    let folder = dir.to_owned();
    match std::fs::metadata(dir) {
        Err(m) if m.kind() == std::io::ErrorKind::NotFound => Some(OutputFault::io(
            std::io::ErrorKind::NotFound,
            CliFault::NoFolder { folder },
        )),
        Ok(m) if !m.is_dir() => Some(OutputFault::io(
            std::io::ErrorKind::NotADirectory,
            CliFault::NotAFolder { folder },
        )),
        _ => None,
    }
}

/// What identifies a file for [`distinct`]: its device and inode when it exists, else its
/// absolute path (links followed).
#[derive(PartialEq, Eq)]
enum FileKey {
    Inode(u64, u64),
    Path(PathBuf),
}

/// The key of a file given as an input or an output; `None` for `-`, for the program's own
/// streams (`/dev/stdout` twice writes both, in order) and for what is not a regular file
/// (`/dev/null` may be given twice).
fn file_key(path: &Path) -> Option<FileKey> {
    if is_dash(path) || stream_of(path).is_some() {
        return None;
    }
    match std::fs::metadata(path) {
        Ok(m) if !m.is_file() => None,
        #[cfg(unix)]
        Ok(m) => {
            use std::os::unix::fs::MetadataExt;
            Some(FileKey::Inode(m.dev(), m.ino()))
        }
        #[cfg(not(unix))]
        Ok(_) => std::fs::canonicalize(path).ok().map(FileKey::Path),
        Err(_) => {
            let target = through_links(path).ok()?;
            let name = target.file_name()?;
            let dir = match target.parent() {
                Some(d) if !d.as_os_str().is_empty() => d,
                _ => Path::new("."),
            };
            Some(FileKey::Path(std::fs::canonicalize(dir).ok()?.join(name)))
        }
    }
}

/// Refuses, before anything is written, an output that is an input of the same run or another
/// of its outputs (`phong grade subs.csv -o subs.csv` would replace the submissions). Each
/// output is named by its flag.
pub(crate) fn distinct(
    inputs: &[&Path],
    outputs: &[(&str, Option<&Path>)],
) -> Result<(), CliError> {
    let outs: Vec<(&str, &Path, FileKey)> = outputs
        .iter()
        .filter_map(|&(flag, p)| {
            let p = p?;
            Some((flag, p, file_key(p)?))
        })
        .collect();
    for (i, (flag, out, key)) in outs.iter().enumerate() {
        if let Some(input) = inputs.iter().find(|p| file_key(p).as_ref() == Some(key)) {
            return Err(CliError::conflict(CliFault::OutputIsInput {
                flag: (*flag).to_owned(),
                output: out.to_path_buf(),
                input: input.to_path_buf(),
            }));
        }
        if let Some((other, _, _)) = outs[..i].iter().find(|(_, _, k)| k == key) {
            return Err(CliError::conflict(CliFault::SameOutput {
                other: (*other).to_owned(),
                flag: (*flag).to_owned(),
                output: out.to_path_buf(),
            }));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pending_temporary_file_is_removed_by_the_signal_cleanup() {
        let dir = tempfile::tempdir().unwrap();
        let tmp = dir.path().join(".phong-x.tmp");
        std::fs::write(&tmp, b"half").unwrap();
        let pending = Pending::new(&tmp);
        remove_pending();
        assert!(!tmp.exists());
        drop(pending);
        assert!(PENDING.lock().unwrap().iter().all(|p| p != &tmp));
    }

    /// A folder where no file can be made (`/proc` refuses every new file, root's too): the
    /// error is the system's, as it came (its number kept, to be said in Portuguese), without
    /// the temporary file's name, and no temporary file is left.
    #[cfg(target_os = "linux")]
    #[test]
    fn a_file_that_cannot_be_made_is_the_systems_error_without_the_temporary_name() {
        let e = write_target_with(Path::new("/proc/phong-x.txt"), &mut |w| w.write_all(b"x"))
            .unwrap_err();
        assert!(e.raw_os_error().is_some(), "{e:?}");
        assert!(!e.to_string().contains(".phong-"), "{e}");
        assert!(!e.to_string().contains("at path"), "{e}");
    }

    #[cfg(unix)]
    #[test]
    fn a_new_file_is_made_with_the_umasks_mode_and_a_replaced_one_keeps_its_own() {
        use std::os::unix::fs::PermissionsExt;
        let dir = tempfile::tempdir().unwrap();
        let new = dir.path().join("new.txt");
        write_target_with(&new, &mut |w| w.write_all(b"new")).unwrap();
        assert_eq!(std::fs::read(&new).unwrap(), b"new");
        let mode = std::fs::metadata(&new).unwrap().permissions().mode() & 0o777;
        // 0666 less some umask: readable and writable by its owner, executable by no one.
        assert_eq!(mode & 0o600, 0o600, "{mode:o}");
        assert_eq!(mode & 0o111, 0, "{mode:o}");
        std::fs::set_permissions(&new, std::fs::Permissions::from_mode(0o640)).unwrap();
        write_target_with(&new, &mut |w| w.write_all(b"again")).unwrap();
        assert_eq!(std::fs::read(&new).unwrap(), b"again");
        let mode = std::fs::metadata(&new).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode, 0o640);
        // Nothing left beside it.
        let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
        assert_eq!(names.len(), 1);
    }

    #[test]
    fn a_link_is_followed_to_the_file_it_names() {
        let dir = tempfile::tempdir().unwrap();
        let link = dir.path().join("link");
        #[cfg(unix)]
        {
            std::os::unix::fs::symlink("target.csv", &link).unwrap();
            assert_eq!(through_links(&link).unwrap(), dir.path().join("target.csv"));
        }
    }
}
