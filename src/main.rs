//! The `strider` command: see [`strider_cli::main`] for the subcommands. The counting
//! allocator lets `strider bench` report heap allocations per frame.

#[global_allocator]
static ALLOCATOR: strider_cli::CountingAllocator = strider_cli::CountingAllocator;

fn main() -> std::process::ExitCode {
    strider_cli::main()
}
