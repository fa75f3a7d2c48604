//! Finding the shaders to check: files and folders on the command line, their stages, the
//! `NAME.vert` + `NAME.frag` pairs to link, and reading them safely (size limit, UTF-8 check).

use std::collections::BTreeMap;
use std::fmt;
use std::path::{Path, PathBuf};

use essl::Stage;

/// The largest shader `essl` reads: 16 MiB. Larger files are refused, not read.
pub const MAX_FILE_SIZE: u64 = 16 * 1024 * 1024;

/// A shader file to check.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Input {
    /// Its path, as given or as found under a folder given.
    pub path: PathBuf,
    /// Its stage (from the extension or `--stage`).
    pub stage: Stage,
}

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
    let entries = match std::fs::read_dir(dir) {
        Ok(entries) => entries,
        Err(e) => {
            errors.push(CollectError::Io {
                path: dir.to_path_buf(),
                message: io_message(&e),
            });
            return;
        }
    };
    // The entry's own type (from the directory listing on most file systems: no `stat` per
    // file). A symbolic link to a folder is not followed; one with a shader's name is read.
    let mut children: Vec<(PathBuf, std::fs::FileType)> = entries
        .filter_map(|e| {
            let e = e.ok()?;
            Some((e.path(), e.file_type().ok()?))
        })
        // `essl lint .` shows `a.frag`, not `./a.frag`.
        .map(|(p, t)| match p.strip_prefix(".") {
            Ok(rest) if dir == Path::new(".") => (rest.to_path_buf(), t),
            _ => (p, t),
        })
        .collect();
    // Siblings: their names order them (a depth-first walk of sorted siblings visits paths in
    // `Path` order, so `found` stays sorted for one folder).
    children.sort_by(|a, b| a.0.file_name().cmp(&b.0.file_name()));
    for (path, file_type) in children {
        if path
            .file_name()
            .and_then(|n| n.to_str())
            .is_some_and(|n| n.starts_with('.'))
        {
            continue;
        }
        if file_type.is_dir() {
            walk(&path, found, errors);
        } else if let Some(stage) = Stage::from_path(&path) {
            found.push((path, stage));
        }
    }
}

/// An I/O error's message without Rust's `(os error 2)` suffix.
pub fn io_message(e: &std::io::Error) -> String {
    match e.kind() {
        std::io::ErrorKind::NotFound => "no such file or directory".to_string(),
        std::io::ErrorKind::PermissionDenied => "permission denied".to_string(),
        _ => {
            let s = e.to_string();
            match s.find(" (os error") {
                Some(i) => s[..i].to_string(),
                None => s,
            }
        }
    }
}

/// The pairs to link: for each folder and base name (the file name before its last extension),
/// the vertex and the fragment shader of that name (`light.vert` + `light.frag`,
/// `light.fixed.vert` + `light.fixed.frag`). Indices into `inputs`, sorted by the vertex path.
/// Where a name has several vertex (or fragment) files (`a.vert` and `a.vs`), the first in the
/// order `.vert`, `.vs`, `.vsh` (`.frag`, `.fs`, `.fsh`) is used.
pub fn pairs(inputs: &[Input]) -> Vec<(usize, usize)> {
    fn rank(path: &Path) -> usize {
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
        ["vert", "frag", "vs", "fs", "vsh", "fsh"]
            .iter()
            .position(|e| *e == ext)
            .unwrap_or(9)
    }
    let mut by_name: BTreeMap<(PathBuf, &std::ffi::OsStr), [Option<usize>; 2]> = BTreeMap::new();
    for (i, input) in inputs.iter().enumerate() {
        // Only files whose extension names the stage pair up (not `--stage` files).
        if Stage::from_path(&input.path) != Some(input.stage) {
            continue;
        }
        let (Some(stem), Some(parent)) = (input.path.file_stem(), input.path.parent()) else {
            continue;
        };
        // `shaders/a.vert` pairs with `./shaders/a.frag`: compare the folders themselves.
        let folder = std::fs::canonicalize(parent).unwrap_or_else(|_| parent.to_path_buf());
        let slot = &mut by_name.entry((folder, stem)).or_default()
            [(input.stage == Stage::Fragment) as usize];
        if slot.is_none_or(|j| rank(&input.path) < rank(&inputs[j].path)) {
            *slot = Some(i);
        }
    }
    let mut out: Vec<(usize, usize)> = by_name
        .into_values()
        .filter_map(|[v, f]| Some((v?, f?)))
        .collect();
    out.sort_by(|a, b| inputs[a.0].path.cmp(&inputs[b.0].path));
    out
}

/// Why a file could not be read as a shader.
#[derive(Debug)]
pub enum ReadError {
    /// The file could not be opened or read.
    Io(std::io::Error),
    /// The file is larger than [`MAX_FILE_SIZE`].
    TooLarge(u64),
    /// The file is not UTF-8: the byte offset of the first invalid byte.
    NotUtf8(usize),
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ReadError::Io(e) => f.write_str(&io_message(e)),
            ReadError::TooLarge(n) => write!(
                f,
                "the file is {n} bytes; essl reads shaders of at most {MAX_FILE_SIZE} bytes (16 MiB)"
            ),
            ReadError::NotUtf8(offset) => write!(
                f,
                "the file is not UTF-8: invalid byte at offset {offset} (GLSL ES sources are ASCII; \
                 save it as UTF-8)"
            ),
        }
    }
}

/// Reads a shader: refuses files over [`MAX_FILE_SIZE`] before reading them, and text that is
/// not UTF-8 (naming the first invalid byte's offset).
pub fn read_source(path: &Path) -> Result<String, ReadError> {
    use std::io::Read;
    let file = std::fs::File::open(path).map_err(ReadError::Io)?;
    let len = file.metadata().map_err(ReadError::Io)?.len();
    if len > MAX_FILE_SIZE {
        return Err(ReadError::TooLarge(len));
    }
    let mut bytes = Vec::with_capacity(len as usize);
    // Read at most one byte past the limit, in case the file grew since `metadata`.
    file.take(MAX_FILE_SIZE + 1)
        .read_to_end(&mut bytes)
        .map_err(ReadError::Io)?;
    if bytes.len() as u64 > MAX_FILE_SIZE {
        return Err(ReadError::TooLarge(bytes.len() as u64));
    }
    String::from_utf8(bytes).map_err(|e| ReadError::NotUtf8(e.utf8_error().valid_up_to()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn input(path: &str, stage: Stage) -> Input {
        Input {
            path: PathBuf::from(path),
            stage,
        }
    }

    #[test]
    fn pairs_by_folder_and_base_name() {
        let inputs = vec![
            input("d/a.fixed.frag", Stage::Fragment),
            input("d/a.fixed.vert", Stage::Vertex),
            input("d/a.frag", Stage::Fragment),
            input("d/a.vert", Stage::Vertex),
            input("d/a.vs", Stage::Vertex),
            input("d/b.vert", Stage::Vertex),
            input("e/a.frag", Stage::Fragment),
            input("d/c.glsl", Stage::Vertex),
            input("d/c.frag", Stage::Fragment),
        ];
        assert_eq!(pairs(&inputs), vec![(1, 0), (3, 2)]);
    }
}
