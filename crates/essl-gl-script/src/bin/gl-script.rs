//! `gl-script`: replays a WebGL2 call script (`docs/gl-scripts.md`) through essl-gl, with the
//! arguments of `tests/gl-scripts/run-chromium.py`, so that one script drives both and their
//! pictures, results and frame times can be set side by side.
//!
//! ```text
//! gl-script SCRIPT.json -o OUT.png --results OUT.json [--times N] [--compare DIR]
//! ```
//!
//! Exits 0 when the replay did what the script says, 1 when a call failed (the failures are on
//! stderr and in the results), 2 on bad arguments or an unreadable script, and with
//! `--compare DIR` (Chromium's `NAME.json` and `NAME.png` in `DIR`) 1 also when the answers or
//! the picture differ beyond what `docs/gl-scripts.md` allows.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::Parser;
use essl_gl_script::{compare, read_script, replay, ReplayOptions, Results};
use essl_scene::RgbaImage;

/// Replay a WebGL2 call script through essl-gl.
#[derive(Parser, Debug)]
#[command(name = "gl-script", version, about, long_about = None)]
struct Cli {
    /// The script (docs/gl-scripts.md).
    script: PathBuf,
    /// PNG to write: the default framebuffer after the frame.
    #[arg(short, long)]
    output: PathBuf,
    /// Results JSON to write (the same format as Chromium's).
    #[arg(long)]
    results: PathBuf,
    /// Time N more frames, each followed by a 1-pixel readPixels; report the median.
    #[arg(long, default_value_t = 0, value_name = "N")]
    times: usize,
    /// Compare with Chromium's NAME.json and NAME.png in DIR.
    #[arg(long, value_name = "DIR")]
    compare: Option<PathBuf>,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let fail = |message: String| {
        eprintln!("gl-script: {message}");
        ExitCode::from(2)
    };
    let script = match read_script(&cli.script) {
        Ok(s) => s,
        Err(e) => return fail(e.to_string()),
    };
    let options = ReplayOptions { times: cli.times };
    let ours = match replay(&script, &options) {
        Ok(r) => r,
        Err(e) => return fail(e.to_string()),
    };
    if let Err(e) = ours.picture.write_png(&cli.output) {
        return fail(e.to_string());
    }
    if let Err(e) = std::fs::write(&cli.results, ours.results.to_json()) {
        return fail(format!("{}: {e}", cli.results.display()));
    }
    let mut ok = ours.results.failures.is_empty();
    for f in &ours.results.failures {
        eprintln!("{f}");
    }
    if let Some(ms) = ours.results.ms_per_frame {
        println!("{ms:.3} ms/frame");
    }
    if let Some(dir) = &cli.compare {
        let name = cli
            .script
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        let theirs = std::fs::read_to_string(dir.join(format!("{name}.json")))
            .map_err(|e| e.to_string())
            .and_then(|t| Results::from_json(&t).map_err(|e| e.to_string()));
        let picture = RgbaImage::read_png(&dir.join(format!("{name}.png")));
        let (theirs, picture) = match (theirs, picture) {
            (Ok(t), Ok(p)) => (t, p),
            (Err(e), _) => return fail(e),
            (_, Err(e)) => return fail(e.to_string()),
        };
        match compare(
            &name,
            &script,
            (&ours.results, &ours.picture),
            (&theirs, &picture),
        ) {
            Ok(c) => {
                for m in &c.mismatches {
                    eprintln!("record {m}");
                }
                println!(
                    "picture: {:.3}% within {}/255 (needs {}%)",
                    c.picture.fraction_within() * 100.0,
                    c.bar.within,
                    c.bar.fraction * 100.0
                );
                ok &= c.matches();
            }
            Err(e) => return fail(e.to_string()),
        }
    }
    if ok {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}
