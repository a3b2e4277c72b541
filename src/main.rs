//! The `cablenav` command-line tool: a thin wrapper over [`cablenav::cli::run`].

use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let read = |path: &str| std::fs::read_to_string(path).map_err(|e| cablenav::Error::new(path, format!("cannot read: {e}")));
    let write = |path: &str, bytes: &[u8]| std::fs::write(path, bytes).map_err(|e| cablenav::Error::new(path, format!("cannot write: {e}")));
    match std::panic::catch_unwind(|| cablenav::cli::run(&args, &read, &write)) {
        Ok(Ok(out)) => {
            println!("{}", out.trim_end());
            ExitCode::SUCCESS
        }
        Ok(Err(e)) => {
            eprintln!("cablenav: {}", e.to_string().lines().next().unwrap_or("error"));
            ExitCode::from(2)
        }
        Err(_) => {
            eprintln!("cablenav: internal error (a bug: please report the command and scenario)");
            ExitCode::from(70)
        }
    }
}
