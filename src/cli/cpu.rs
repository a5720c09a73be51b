//! The CPU a build of phong needs, checked before anything else runs.
//!
//! On x86-64 Linux, `cargo install --path .` builds phong for the CPU of the machine that builds it
//! (`.cargo/config.toml`: `-C target-cpu=native`), so that the wide tracer's lanes are as wide as
//! that CPU's registers (AVX2: one 256-bit register for 8 lanes of f32 or 4 of f64, where the SSE2
//! of every x86-64 CPU needs two halves; AVX-512: 8 lanes of f64 in one). Such a binary copied to
//! an older CPU would die of an illegal instruction at the first AVX one, and early: the release
//! build's link-time optimisation compiles the standard library's start-up code for that CPU too.
//! So the binary (`src/main.rs`) checks before the standard library starts, from the ELF
//! constructors the loader runs first, in instructions of its own (`asm!`: the compiler would use
//! the newer CPU's BMI instructions for plain bit tests): CPUID and XGETBV against the features
//! this build was compiled to use ([`FEATURES`], [`NEED_1_ECX`] and the other masks), and, when one
//! is missing ([`Lacking`]), [`REFUSAL`] in both languages by the `write` system call, then exit 2.
//!
//! Why the message is data and is written in both languages: every function of this build,
//! the standard library's and the message rendering's included, may hold the instructions the
//! CPU lacks; only the few integer instructions of the check are safe to run. So the sentence
//! is two constant strings per language (no formatting code), the language is not looked up
//! (that is phong's code), and both lines are written.

/// The refusal, in English and in Portuguese: the text before the list of missing features
/// and the text after it. One value with both languages; the binary writes both.
pub static REFUSAL: [(&str, &str); 2] = [
    (
        "error: this phong was built for a CPU with ",
        ", which this CPU lacks, so it stops here instead of crashing. Fix: build phong on \
         this machine (`cargo install --path .` in phong's folder), or build a copy that runs \
         on any x86-64 CPU: RUSTFLAGS=\"-C target-cpu=x86-64\" cargo install --path .\n",
    ),
    (
        "erro: esta phong foi compilada para um processador com ",
        ", que este processador não tem; por isso ela para aqui em vez de falhar. Correção: \
         compile a phong nesta máquina (`cargo install --path .` na pasta da phong), ou \
         compile uma cópia que roda em qualquer processador x86-64: \
         RUSTFLAGS=\"-C target-cpu=x86-64\" cargo install --path .\n",
    ),
];

/// Where CPUID reports a feature.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Leaf {
    /// Leaf 1, register ECX.
    OneEcx,
    /// Leaf 7 (subleaf 0), register EBX.
    SevenEbx,
    /// Leaf 7 (subleaf 0), register ECX.
    SevenEcx,
    /// Leaf 0x8000_0001, register ECX.
    ExtendedEcx,
}

/// A CPU feature a build may be compiled to use.
#[derive(Clone, Copy, Debug)]
pub struct Feature {
    /// Its `target_feature` name, as the error names it.
    pub name: &'static str,
    /// Whether this build was compiled to use it.
    pub built: bool,
    /// Where CPUID reports it, and its bit there.
    pub leaf: Leaf,
    pub bit: u32,
    /// The bits of XCR0 (the registers the operating system saves) it needs as well: the YMM
    /// state for AVX and its kin, the opmask and ZMM state for AVX-512.
    pub state: u64,
}

const YMM: u64 = 0b110;
const ZMM: u64 = 0b1110_0110;

macro_rules! features {
    ($($name:literal, $leaf:ident, $bit:literal, $state:expr;)*) => {
        /// The x86-64 features `-C target-cpu=native` turns on for the CPUs of the last fifteen
        /// years that the compiler may use in code that does not ask for them (not AES, VAES,
        /// PCLMULQDQ, VPCLMULQDQ, SHA or RDRAND, which only their intrinsics use), in the order
        /// the error lists them.
        pub const FEATURES: &[Feature] = &[$(Feature {
            name: $name,
            built: cfg!(target_feature = $name),
            leaf: Leaf::$leaf,
            bit: $bit,
            state: $state,
        }),*];
    };
}

features! {
    "sse3", OneEcx, 0, 0;
    "ssse3", OneEcx, 9, 0;
    "sse4.1", OneEcx, 19, 0;
    "sse4.2", OneEcx, 20, 0;
    "popcnt", OneEcx, 23, 0;
    "movbe", OneEcx, 22, 0;
    "lzcnt", ExtendedEcx, 5, 0;
    "avx", OneEcx, 28, YMM;
    "f16c", OneEcx, 29, YMM;
    "fma", OneEcx, 12, YMM;
    "avx2", SevenEbx, 5, YMM;
    "bmi1", SevenEbx, 3, 0;
    "bmi2", SevenEbx, 8, 0;
    "avx512f", SevenEbx, 16, ZMM;
    "avx512dq", SevenEbx, 17, ZMM;
    "avx512cd", SevenEbx, 28, ZMM;
    "avx512bw", SevenEbx, 30, ZMM;
    "avx512vl", SevenEbx, 31, ZMM;
    "avx512ifma", SevenEbx, 21, ZMM;
    "avx512vbmi", SevenEcx, 1, ZMM;
    "avx512vbmi2", SevenEcx, 6, ZMM;
    "gfni", SevenEcx, 8, 0;
    "avx512vnni", SevenEcx, 11, ZMM;
    "avx512bitalg", SevenEcx, 12, ZMM;
    "avx512vpopcntdq", SevenEcx, 14, ZMM;
}

/// The bits this build needs of one CPUID register (`Some(leaf)`), or of XCR0 (`None`): over
/// the features it was compiled to use.
const fn needed(leaf: Option<Leaf>) -> u64 {
    let mut bits = 0;
    let mut i = 0;
    while i < FEATURES.len() {
        let f = &FEATURES[i];
        if f.built {
            bits |= match leaf {
                Some(leaf) if leaf as u8 == f.leaf as u8 => 1 << f.bit,
                Some(_) => 0,
                None => f.state,
            };
        }
        i += 1;
    }
    bits
}

/// The bits of CPUID leaf 1's ECX this build needs.
pub const NEED_1_ECX: u32 = needed(Some(Leaf::OneEcx)) as u32;
/// The bits of CPUID leaf 7's EBX this build needs.
pub const NEED_7_EBX: u32 = needed(Some(Leaf::SevenEbx)) as u32;
/// The bits of CPUID leaf 7's ECX this build needs.
pub const NEED_7_ECX: u32 = needed(Some(Leaf::SevenEcx)) as u32;
/// The bits of CPUID leaf 0x8000_0001's ECX this build needs.
pub const NEED_EXT_ECX: u32 = needed(Some(Leaf::ExtendedEcx)) as u32;
/// The bits of XCR0 this build needs.
pub const NEED_XCR0: u64 = needed(None);

/// What the CPU lacks of what this build needs: per CPUID register the needed bits it does not
/// set, and the needed bits of XCR0 the operating system does not (all of them where the OS
/// did not enable XGETBV). The binary reads it in its own instructions (`src/main.rs`); all zero
/// where nothing is missing.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Lacking {
    pub one_ecx: u32,
    pub seven_ebx: u32,
    pub seven_ecx: u32,
    pub extended_ecx: u32,
    pub xcr0: u64,
}

impl Lacking {
    /// From the registers as CPUID and XGETBV give them (`xcr0` None where the OS did not
    /// enable XGETBV): what a test computes with the same rule as the binary's instructions.
    pub fn of(
        one_ecx: u32,
        seven_ebx: u32,
        seven_ecx: u32,
        extended_ecx: u32,
        xcr0: Option<u64>,
    ) -> Lacking {
        Lacking {
            one_ecx: NEED_1_ECX & !one_ecx,
            seven_ebx: NEED_7_EBX & !seven_ebx,
            seven_ecx: NEED_7_ECX & !seven_ecx,
            extended_ecx: NEED_EXT_ECX & !extended_ecx,
            xcr0: NEED_XCR0 & !xcr0.unwrap_or(0),
        }
    }

    /// Whether anything is missing.
    #[inline(always)]
    pub fn any(self) -> bool {
        (self.one_ecx | self.seven_ebx | self.seven_ecx | self.extended_ecx) != 0 || self.xcr0 != 0
    }

    /// Calls `each` with the name of every feature this build uses that is missing, in
    /// [`FEATURES`]' order: a test of a bit against a constant each, nothing more (this runs on
    /// the CPU that lacks them).
    #[inline(always)]
    pub fn each(self, mut each: impl FnMut(&'static str)) {
        for f in FEATURES {
            let register = match f.leaf {
                Leaf::OneEcx => self.one_ecx,
                Leaf::SevenEbx => self.seven_ebx,
                Leaf::SevenEcx => self.seven_ecx,
                Leaf::ExtendedEcx => self.extended_ecx,
            };
            if f.built && (register & 1 << f.bit != 0 || self.xcr0 & f.state != 0) {
                each(f.name);
            }
        }
    }

    /// The names [`Lacking::each`] gives.
    pub fn names(self) -> Vec<&'static str> {
        let mut names = Vec::new();
        self.each(|name| names.push(name));
        names
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    // That the building machine lacks nothing is every test that runs the binary: a refusal
    // would fail them all (and tests/integration/cpu.rs runs it on QEMU's "max" CPU).

    #[test]
    fn a_cpu_with_nothing_lacks_every_feature_the_build_uses_in_order() {
        let none = Lacking::of(0, 0, 0, 0, None);
        let built: Vec<&str> = FEATURES
            .iter()
            .filter(|f| f.built)
            .map(|f| f.name)
            .collect();
        assert_eq!(none.names(), built);
        assert_eq!(none.any(), !built.is_empty());
    }

    #[test]
    #[cfg(target_feature = "avx2")]
    fn an_os_that_does_not_save_the_ymm_registers_lacks_avx_but_not_sse() {
        // Every CPUID bit set: only the registers' state is missing.
        let lacking = Lacking::of(u32::MAX, u32::MAX, u32::MAX, u32::MAX, Some(0b11));
        let names = lacking.names();
        assert!(names.contains(&"avx") && names.contains(&"avx2") && names.contains(&"fma"));
        assert!(!names.contains(&"sse4.2") && !names.contains(&"bmi2"));
    }

    #[test]
    fn the_refusal_names_the_fix_in_both_languages() {
        for (before, after) in REFUSAL.iter() {
            assert!(!before.is_empty() && after.ends_with('\n'));
            assert!(after.contains("cargo install --path ."), "{after}");
            assert!(after.contains("target-cpu=x86-64"), "{after}");
        }
    }
}
