//! `tether`: the command line. Errors reach the user as one line on stderr and exit code 1.

mod cli;

use clap::Parser;

/// Rust's system allocator, counted (Rerun's viewer does the same): the embedded viewer's memory
/// limit then weighs the heap the program holds — its recordings first — and not the resident
/// size, which a software Vulkan driver's own allocations inflate (docs/window.md, "Memory").
#[cfg(feature = "gui")]
#[global_allocator]
static ALLOCATOR: rerun::external::re_memory::AccountingAllocator<std::alloc::System> =
    rerun::external::re_memory::AccountingAllocator::new(std::alloc::System);

fn main() -> std::process::ExitCode {
    let args = cli::Cli::parse();
    match cli::run(args) {
        Ok(code) => std::process::ExitCode::from(code),
        Err(error) => {
            eprintln!("error: {error:#}");
            std::process::ExitCode::FAILURE
        }
    }
}
