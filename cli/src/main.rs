//! The `cablenav` binary: [`cablenav_cli::run`] over the file system, with a progress bar on
//! stderr for long commands when stderr is a terminal, and the documented exit codes
//! (`cablenav --help`).

mod progress;

use std::io::Write;
use std::process::ExitCode;

fn main() -> ExitCode {
    let read = |path: &str| std::fs::read_to_string(path).map_err(|e| cablenav::Error::new(path, format!("cannot read: {e}")));
    let write = |path: &str, bytes: &[u8]| std::fs::write(path, bytes).map_err(|e| cablenav::Error::new(path, format!("cannot write: {e}")));
    let list = |path: &str| -> cablenav::Result<Vec<String>> {
        let entries = std::fs::read_dir(path).map_err(|e| cablenav::Error::new(path, format!("cannot list: {e}")))?;
        Ok(entries.filter_map(|e| e.ok()?.file_name().into_string().ok()).collect())
    };
    let mut bar = progress::Bar::for_stderr();
    let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| cablenav_cli::run(std::env::args_os().skip(1), &read, &write, &list, &mut |p| bar.update(p))));
    bar.finish();
    match outcome {
        Ok(Ok(out)) => match writeln!(std::io::stdout(), "{}", out.trim_end()) {
            // A closed pipe (`cablenav … | head`) is the reader's choice, not an error.
            Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => {
                eprintln!("cablenav: cannot write the output: {e}");
                ExitCode::from(74)
            }
            _ => ExitCode::SUCCESS,
        },
        Ok(Err(e)) => {
            eprintln!("{e}");
            ExitCode::from(e.exit_code())
        }
        Err(_) => {
            eprintln!("cablenav: internal error (a bug: please report the command and scenario)");
            ExitCode::from(70)
        }
    }
}
