//! The `phong` binary: a thin shell around [`phong::cli`], its allocator, and the CPU check.

use std::alloc::{GlobalAlloc, Layout, System};

/// The system's allocator, except that an allocation it refuses ends the program with
/// `phong::cli::memory::out_of_memory`'s clear error (exit 2, a file being written removed)
/// instead of Rust's abort (exit 134), unless the code that asked is ready to see it refused
/// (`phong::text::memory::handled`: a `try_reserve` that reports what it needs itself).
///
/// Stable Rust has no hook for an allocation failure (`std::alloc::set_alloc_error_hook` is
/// unstable), so this is the one place it can be caught. It also asks for huge pages for large
/// blocks ([`huge_pages`]). This and `cpu_check` below are the crate's only `unsafe` code (the
/// library forbids it): `GlobalAlloc` is an unsafe trait, `madvise` an unsafe call.
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
        new_block(unsafe { System.alloc(layout) }, layout.size())
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        // SAFETY: as `alloc`.
        new_block(unsafe { System.alloc_zeroed(layout) }, layout.size())
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: `ptr` was allocated by this allocator, that is by `System`, with `layout`.
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // A grown block is not given huge pages (not a `new_block`): buffers that grow and
        // shrink (the grade workbook's) kept 53 MB more resident with them, and a scene's large
        // blocks are allocated at their size.
        // SAFETY: `ptr` was allocated by `System` with `layout`; the caller upholds the rest.
        checked(unsafe { System.realloc(ptr, layout, new_size) }, new_size)
    }
}

/// What the allocator hands back for `size` bytes at `p` from `System`: a refusal (null) goes
/// to [`refused`].
fn checked(p: *mut u8, size: usize) -> *mut u8 {
    if p.is_null() {
        refused(size);
    }
    p
}

/// [`checked`] for a new block, which is given huge pages when large ([`huge_pages`]).
fn new_block(p: *mut u8, size: usize) -> *mut u8 {
    let p = checked(p, size);
    if !p.is_null() && size >= HUGE_PAGES_FROM {
        huge_pages(p, size);
    }
    p
}

/// The size from which a block asks for huge pages: two of x86-64's 2 MiB pages.
const HUGE_PAGES_FROM: usize = 4 << 20;

/// Asks Linux to back the whole 2 MiB pages of a large block with huge pages
/// (`madvise(MADV_HUGEPAGE)`; most distributions enable transparent huge pages only where asked,
/// `/sys/kernel/mm/transparent_hugepage/enabled` = madvise). A scene of 100,000 spheres touches
/// about 80 MB while it is read and its BVH built: 20,000 page faults in 4 KiB pages, 7,000 so
/// (docs/benchmarks.md, "Speed at scale"). The advice changes no byte of the block;
/// where the kernel refuses it (no transparent huge pages) nothing changes.
#[cfg(target_os = "linux")]
fn huge_pages(p: *mut u8, size: usize) {
    const HUGE: usize = 2 << 20;
    let start = (p as usize).next_multiple_of(HUGE);
    let end = (p as usize + size) & !(HUGE - 1);
    if start < end {
        // SAFETY: [start, end) lies inside the block `System` just gave (rounded inward to
        // whole huge pages, hence to whole pages); MADV_HUGEPAGE only marks the mapping and
        // neither moves nor frees memory, and an error (EINVAL without huge pages) is harmless.
        unsafe {
            libc::madvise(start as *mut libc::c_void, end - start, libc::MADV_HUGEPAGE);
        }
    }
}

#[cfg(not(target_os = "linux"))]
fn huge_pages(_: *mut u8, _: usize) {}

#[global_allocator]
static ALLOCATOR: Allocator = Allocator;

/// The CPU check (`phong::cli::cpu`), on x86-64 Linux, where `.cargo/config.toml` builds for
/// the building machine's CPU: run by the loader among the ELF constructors (`.init_array`),
/// before the standard library starts (the release build compiles its start-up code for the
/// building CPU too). A CPU without a feature the build uses gets the error in both languages,
/// written by the `write` system call, and exit 2 by `exit_group`: no code of the build runs
/// but these few integer instructions.
#[cfg(all(target_arch = "x86_64", target_os = "linux"))]
mod cpu_check {
    use std::arch::asm;

    use phong::cli::cpu::{
        Lacking, NEED_1_ECX, NEED_7_EBX, NEED_7_ECX, NEED_EXT_ECX, NEED_XCR0, REFUSAL,
    };

    #[used]
    #[link_section = ".init_array"]
    static CHECK: extern "C" fn() = check;

    extern "C" fn check() {
        let lacking = lacking();
        if !lacking.any() {
            return;
        }
        // By reference: a copy of the table could be made with the vector instructions the CPU
        // lacks; only the general registers are used from here on.
        for (before, after) in REFUSAL.iter() {
            write(before.as_bytes());
            let mut first = true;
            lacking.each(|name| {
                if !first {
                    write(b", ");
                }
                first = false;
                write(name.as_bytes());
            });
            write(after.as_bytes());
        }
        // SAFETY: exit_group(2) ends the process; it takes one integer and returns nowhere.
        unsafe { asm!("syscall", in("rax") 231, in("rdi") 2, options(noreturn, nostack)) }
    }

    /// CPUID and XGETBV against the bits this build needs, in instructions every x86-64 CPU
    /// has (the compiler, building for the newer CPU, would use its BMI instructions for the
    /// bit tests): per register, the needed bits the CPU does not set.
    fn lacking() -> Lacking {
        let (one, seven, seven_ecx, extended): (u32, u32, u32, u32);
        let xcr0: u64;
        // SAFETY: CPUID and XGETBV read registers only; XGETBV runs only where CPUID's leaf 1
        // says the OS enabled it (OSXSAVE, bit 27 of ECX). RBX, which CPUID writes and the
        // compiler reserves, is saved in a register of its own and restored.
        unsafe {
            asm!(
                "mov {save}, rbx",
                // Leaf 0: the highest standard leaf, kept in r8d.
                "xor eax, eax",
                "xor ecx, ecx",
                "cpuid",
                "mov r8d, eax",
                // Leaf 1: ECX (every x86-64 CPU has leaf 1).
                "mov eax, 1",
                "xor ecx, ecx",
                "cpuid",
                "mov r9d, ecx",
                // Leaf 7, subleaf 0: EBX and ECX, where the CPU has leaf 7.
                "xor r10d, r10d",
                "xor r12d, r12d",
                "cmp r8d, 7",
                "jb 2f",
                "mov eax, 7",
                "xor ecx, ecx",
                "cpuid",
                "mov r10d, ebx",
                "mov r12d, ecx",
                "2:",
                // Leaf 0x8000_0001: ECX, where the CPU has it.
                "xor r11d, r11d",
                "mov eax, 0x80000000",
                "xor ecx, ecx",
                "cpuid",
                "cmp eax, 0x80000001",
                "jb 3f",
                "mov eax, 0x80000001",
                "xor ecx, ecx",
                "cpuid",
                "mov r11d, ecx",
                "3:",
                // XCR0, where the OS enabled XGETBV; else none of its registers are saved.
                "xor eax, eax",
                "xor edx, edx",
                "bt r9d, 27",
                "jnc 4f",
                "xor ecx, ecx",
                "xgetbv",
                "4:",
                "shl rdx, 32",
                "or rax, rdx",
                "mov rbx, {save}",
                // The needed bits not set: NEED & !register, in each.
                "not r9d",
                "and r9d, {need1}",
                "not r10d",
                "and r10d, {need7}",
                "not r12d",
                "and r12d, {need7c}",
                "not r11d",
                "and r11d, {needx}",
                "not rax",
                "and rax, {needxcr0}",
                save = out(reg) _,
                need1 = const NEED_1_ECX,
                need7 = const NEED_7_EBX,
                need7c = const NEED_7_ECX,
                needx = const NEED_EXT_ECX,
                needxcr0 = const NEED_XCR0 as i32,
                out("r8") _,
                out("r9") one,
                out("r10") seven,
                out("r12") seven_ecx,
                out("r11") extended,
                out("rax") xcr0,
                out("rcx") _,
                out("rdx") _,
                options(nostack, nomem),
            );
        }
        Lacking {
            one_ecx: one,
            seven_ebx: seven,
            seven_ecx,
            extended_ecx: extended,
            xcr0,
        }
    }

    /// `bytes` to standard error (file descriptor 2) by the `write` system call, again after a
    /// short write, given up on an error.
    fn write(mut bytes: &[u8]) {
        while !bytes.is_empty() {
            let written: isize;
            // SAFETY: write(2, pointer, length) reads `bytes.len()` bytes of a live slice; the
            // kernel clobbers rcx and r11 and nothing else.
            unsafe {
                asm!(
                    "syscall",
                    inlateout("rax") 1isize => written,
                    in("rdi") 2,
                    in("rsi") bytes.as_ptr(),
                    in("rdx") bytes.len(),
                    lateout("rcx") _,
                    lateout("r11") _,
                    options(nostack),
                );
            }
            if written <= 0 {
                return;
            }
            bytes = &bytes[written as usize..];
        }
    }
}

fn main() -> std::process::ExitCode {
    phong::cli::main()
}
