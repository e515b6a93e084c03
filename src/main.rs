//! The `strider` command: `check`, `run` and `nodes`, or the headless demo without a
//! subcommand. Everything happens in [`strider_cli::main`].

fn main() -> std::process::ExitCode {
    strider_cli::main()
}
