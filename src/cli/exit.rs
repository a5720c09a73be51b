//! The exit status of `phong`, as fd's `exit_codes.rs` names its own: every command ends in one
//! [`Exit`], and it becomes a process exit code here only.

use std::process::ExitCode;

/// How a command ended. Ordered from best to worst: a command that did several things (a batch
/// of files) ends with the worst of them, their [`Ord::max`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Exit {
    /// 0: everything solved and written, or every checked answer accepted.
    Success,
    /// 1: a checked answer is wrong (or is the likely intended reading, under `--strict`).
    Wrong,
    /// 2: bad input (a file that cannot be read, parsed or validated), bad usage, or output
    /// that cannot be written.
    BadInput,
}

impl Exit {
    /// The process exit code: 0, 1 or 2.
    pub(crate) fn code(self) -> u8 {
        match self {
            Exit::Success => 0,
            Exit::Wrong => 1,
            Exit::BadInput => 2,
        }
    }
}

impl From<Exit> for ExitCode {
    fn from(exit: Exit) -> ExitCode {
        ExitCode::from(exit.code())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_worst_exit_wins() {
        assert_eq!(Exit::Success.max(Exit::Wrong).code(), 1);
        assert_eq!(Exit::BadInput.max(Exit::Wrong).code(), 2);
        assert_eq!(Exit::Success.code(), 0);
    }
}
