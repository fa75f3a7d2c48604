//! Finding the shaders to check: files and folders on the command line and their stages.
//! Pairing them into programs and reading them safely are `essl_build::files`' (a build
//! script finds shaders the same way).

use std::fmt;
use std::path::{Path, PathBuf};

use essl::Stage;

pub use essl_build::files::{io_message, pairs, read_source};

/// A shader file to check: its path (as given or as found under a folder given) and its stage
/// (from the extension or `--stage`).
pub type Input = essl_build::files::ShaderFile;

/// What the command line named that cannot be checked.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CollectError {
    /// A usage error: the command line itself is wrong (exit status 2, nothing is checked).
    Usage(String),
    /// A path that does not exist or cannot be listed (exit status 2; the others are checked).
    Io {
        /// The path.
        path: PathBuf,
        /// What went wrong.
        message: String,
    },
}

impl fmt::Display for CollectError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CollectError::Usage(m) => f.write_str(m),
            CollectError::Io { path, message } => write!(f, "{}: {message}", path.display()),
        }
    }
}

/// The shaders found, sorted by path and without duplicates, and the paths that could not be
/// listed.
#[derive(Clone, Debug, Default)]
pub struct Collected {
    /// The shaders to check, sorted by path.
    pub inputs: Vec<Input>,
    /// Paths that do not exist or could not be read as folders.
    pub errors: Vec<CollectError>,
}

/// Finds the shaders named by `paths`: a file is checked with the stage its extension implies
/// (`.vert`/`.vs`/`.vsh`, `.frag`/`.fs`/`.fsh`) or, for other extensions, the `forced` stage
/// (`--stage`); without one such a file is a usage error. A folder is searched recursively for
/// files whose extension names a stage (others, hidden entries and symbolic links to folders are
/// skipped).
pub fn collect(paths: &[PathBuf], forced: Option<Stage>) -> Result<Collected, CollectError> {
    let mut found: Vec<(PathBuf, Stage)> = Vec::new();
    let mut errors = Vec::new();
    for path in paths {
        match std::fs::metadata(path) {
            Ok(meta) if meta.is_dir() => walk(path, &mut found, &mut errors),
            Ok(_) => {
                let stage = match Stage::from_path(path).or(forced) {
                    Some(stage) => stage,
                    None => {
                        return Err(CollectError::Usage(format!(
                            "cannot tell the stage of `{}` from its extension: name it `.vert` or \
                             `.frag` (also `.vs`, `.fs`, `.vsh`, `.fsh`), or pass \
                             `--stage vertex` or `--stage fragment`",
                            path.display()
                        )))
                    }
                };
                found.push((path.clone(), stage));
            }
            Err(e) => errors.push(CollectError::Io {
                path: path.clone(),
                message: io_message(&e),
            }),
        }
    }
    // The same file named twice (`a.frag` and `./a.frag`, or a file and its folder) is
    // checked once, under the first name in path order. One path names every file once.
    let mut seen = std::collections::HashSet::new();
    let several = paths.len() > 1;
    if several {
        found.sort_by(|a, b| a.0.cmp(&b.0));
        found.dedup_by(|later, first| later.0 == first.0);
    }
    let inputs = found
        .into_iter()
        .filter(|(path, _)| {
            !several || seen.insert(std::fs::canonicalize(path).unwrap_or_else(|_| path.clone()))
        })
        .map(|(path, stage)| Input { path, stage })
        .collect();
    Ok(Collected { inputs, errors })
}

fn walk(dir: &Path, found: &mut Vec<(PathBuf, Stage)>, errors: &mut Vec<CollectError>) {
    let (files, failed) = essl_build::files::walk(dir, &mut |_| true);
    // `essl lint .` shows `a.frag`, not `./a.frag`.
    let shown = |p: PathBuf| match p.strip_prefix(".") {
        Ok(rest) if dir == Path::new(".") => rest.to_path_buf(),
        _ => p,
    };
    found.extend(files.into_iter().map(|f| (shown(f.path), f.stage)));
    errors.extend(failed.into_iter().map(|(path, e)| CollectError::Io {
        path,
        message: io_message(&e),
    }));
}
