//! essl-check: the one checking pipeline behind every front door — `essl lint` and
//! `essl translate`, the build-script checker (`essl-build`), the editor server, and the
//! Node/npm bindings.
//!
//! Paths or texts and settings in, checked units out:
//!
//! 1. [`find`] names the shaders: shader files (their stages from names, `essl.toml` or a
//!    pragma), folders walked as git sees them, standard input, and the shaders inside HTML
//!    and JS/TS files ([`extract`]); [`find_text`] does the same for one text an editor or a
//!    bundler holds.
//! 2. [`Configs`] gives each file the settings of its nearest `essl.toml` ([`config`]) with
//!    the caller's [`Overrides`] on top.
//! 3. [`run`] (or [`check_text`]) checks each unit — a shader file, a `NAME.vert` +
//!    `NAME.frag` pair ([`pairs`]), or a host file's shaders — on a thread pool: each shader's
//!    text is assembled ([`Assembly`]: a host's range, `#include`s in place), fixed in rounds
//!    under `--fix`, compiled, linted and linked, and every diagnostic is moved onto the file
//!    and line the author wrote ([`CheckedShader::diagnostics`]).
//!
//! Reading goes through [`Files`], so that an editor's open buffers and a bundler's modules
//! stand in front of the disk. What to print, and where, is the caller's: this crate writes
//! nothing but what [`write_atomically`] is asked to.

#![warn(missing_docs)]

mod assembly;
mod check;
mod chunk;
mod codes;
pub mod config;
pub mod extract;
mod find;
mod imports;
mod include;
mod minify;
mod pairs;
mod preset;
mod read;
mod result;
mod run;
mod settings;
mod write;

pub use assembly::{Assembly, Unfixable};
pub use check::{units, CheckOptions, FixMode, Phase, Unit, MAX_FIX_ROUNDS};
pub use codes::CheckCode;
pub use config::{Config, ConfigError};
pub use find::{
    find, find_text, stage_from_name, FindError, FindOptions, Found, Host, Input, Skipped,
    UsageError,
};
pub use include::{has_include, MAX_DEPTH as MAX_INCLUDE_DEPTH};
pub use minify::{minify, MinifyError};
pub use pairs::{pairs, partner, ShaderFile};
pub use preset::{Prepared, Preset, PresetError};
pub use read::{io_message, read_source, Files, ReadError, MAX_FILE_SIZE};
pub use result::{
    CheckedProgram, CheckedShader, CheckedUnit, FileDiagnostics, FixedFile, ProgramDiagnostic,
    Unread,
};
pub use run::{check_text, finish, link, run, Run};
pub use settings::{Configs, Overrides, Settings};
pub use write::write_atomically;
