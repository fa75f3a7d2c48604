//! Replays WebGL2 call scripts through essl-gl.
//!
//! A call script (`docs/gl-scripts.md`) is a sequence of WebGL2 calls written as JSON — the
//! method's name, its arguments, the error it must leave, what to keep and what to record.
//! `tests/gl-scripts/run-chromium.py` runs a script in headless Chromium and commits what
//! Chromium drew and answered; this crate runs the same script through [`essl_gl::Context`]
//! ([`replay`]) and compares the two ([`compare`]): every error the script names, every
//! recorded answer (within the tolerances the format allows), and the picture.
//!
//! Written by hand because the format is this project's own: the interpreter is a table from
//! WebGL2's method names to essl-gl's methods (`calls`), with the IDL's conversions of
//! JavaScript values (`args`).
//!
//! ```no_run
//! let script = essl_gl_script::read_script("tests/gl-scripts/deferred.json".as_ref())?;
//! let replay = essl_gl_script::replay(&script, &essl_gl_script::ReplayOptions::default())?;
//! assert!(replay.results.failures.is_empty());
//! replay.picture.write_png("deferred.png".as_ref())?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod args;
mod calls;
pub mod compare;
mod results;
mod run;
mod script;
pub mod value;

use std::path::PathBuf;

pub use args::CallError;
pub use calls::call;
pub use compare::{compare, Comparison, Mismatch};
pub use results::{Failure, Phase, Results};
pub use run::{replay, Replay, ReplayOptions};
pub use script::{parse_script, read_script, Arg, Call, Script};

/// Why a script could not be read or run at all (a call that fails is a [`Failure`] in the
/// results instead).
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ScriptError {
    /// A file could not be read.
    #[error("{}: {message}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// What the system said.
        message: String,
    },
    /// The text is not JSON.
    #[error("not JSON: {0}")]
    Json(String),
    /// The JSON does not follow the format.
    #[error("{at}: {message}")]
    Malformed {
        /// Where (`setup[3] (bindTexture)`), empty for the script's top level.
        at: String,
        /// What is wrong.
        message: String,
    },
    /// The context could not be made (no adapter).
    #[error("no context: {0}")]
    Context(#[from] essl_gl::ContextError),
    /// An extension the script enables is not offered.
    #[error("extension {0} is not supported")]
    Extension(String),
}
