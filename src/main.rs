//! The `pounding` binary: the command line (`cli/`) on the library's core; with no subcommand it
//! opens the window.

use clap::Parser;

mod cli;

use cli::{Cli, is_broken_pipe, run};
use std::io::Write;

fn main() {
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    let result =
        run(Cli::parse(), &mut out).and_then(|()| out.flush().map_err(anyhow::Error::from));
    match result {
        Ok(()) => {}
        Err(e) if is_broken_pipe(&e) => {}
        Err(e) => {
            drop(out);
            eprintln!("error: {e:#}");
            std::process::exit(2);
        }
    }
}
