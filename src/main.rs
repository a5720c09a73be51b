//! The `phong` binary: a thin shell around [`phong::cli`].

fn main() -> std::process::ExitCode {
    phong::cli::main()
}
