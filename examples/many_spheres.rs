//! Writes the many-spheres scene: `cargo run --release --example many_spheres -- [N] > FILE`
//! (N = 100000 by default). The file is generated rather than kept in the repository: 100,000
//! spheres are 7 MB of JSON, and the generator is deterministic.

#[path = "../scenes/many_spheres.rs"]
mod many_spheres;

fn main() {
    let n = match std::env::args().nth(1) {
        None => 100_000,
        Some(a) => match a.parse() {
            Ok(n) if n > 0 => n,
            _ => {
                eprintln!("error: N must be a whole number > 0, not \"{a}\"");
                std::process::exit(2);
            }
        },
    };
    println!("{}", many_spheres::scene(n));
}
