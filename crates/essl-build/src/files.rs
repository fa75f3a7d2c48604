//! Shader files: their stages, the `NAME.vert` + `NAME.frag` pairs to link, and reading them
//! safely (a size limit, a UTF-8 check). `essl lint` finds its files with these too.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use essl::Stage;

/// The largest shader essl reads: 16 MiB. Larger files are refused, not read.
pub const MAX_FILE_SIZE: u64 = 16 * 1024 * 1024;

/// A shader file and its stage.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ShaderFile {
    /// Its path, as given or as found under a folder given.
    pub path: PathBuf,
    /// Its stage.
    pub stage: Stage,
}

/// The pairs to link: for each folder and base name (the file name before its last extension),
/// the vertex and the fragment shader of that name (`light.vert` + `light.frag`,
/// `light.fixed.vert` + `light.fixed.frag`). Indices into `files`, sorted by the vertex path.
/// Where a name has several vertex (or fragment) files (`a.vert` and `a.vs`), the first in the
/// order `.vert`, `.vs`, `.vsh` (`.frag`, `.fs`, `.fsh`) is used. Only files whose extension
/// names their stage pair up.
pub fn pairs(files: &[ShaderFile]) -> Vec<(usize, usize)> {
    fn rank(path: &Path) -> usize {
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
        ["vert", "frag", "vs", "fs", "vsh", "fsh"]
            .iter()
            .position(|e| *e == ext)
            .unwrap_or(9)
    }
    // `shaders/a.vert` pairs with `./shaders/a.frag`: compare the folders themselves, each
    // written form resolved once (a folder of 10,000 shaders is one `canonicalize`).
    let mut folder_of: HashMap<&Path, usize> = HashMap::new();
    let mut folders: HashMap<PathBuf, usize> = HashMap::new();
    let mut by_name: HashMap<(usize, &std::ffi::OsStr), [Option<usize>; 2]> = HashMap::new();
    for (i, file) in files.iter().enumerate() {
        if Stage::from_path(&file.path) != Some(file.stage) {
            continue;
        }
        let (Some(stem), Some(parent)) = (file.path.file_stem(), file.path.parent()) else {
            continue;
        };
        let folder = *folder_of.entry(parent).or_insert_with(|| {
            let real = std::fs::canonicalize(parent).unwrap_or_else(|_| parent.to_path_buf());
            let next = folders.len();
            *folders.entry(real).or_insert(next)
        });
        let slot = &mut by_name.entry((folder, stem)).or_default()
            [(file.stage == Stage::Fragment) as usize];
        if slot.is_none_or(|j| rank(&file.path) < rank(&files[j].path)) {
            *slot = Some(i);
        }
    }
    let mut out: Vec<(usize, usize)> = by_name
        .into_values()
        .filter_map(|[v, f]| Some((v?, f?)))
        .collect();
    // Files listed in path order (as `essl lint` lists them) need no path comparisons.
    out.sort_unstable();
    if !out.is_sorted_by(|a, b| files[a.0].path <= files[b.0].path) {
        out.sort_by(|a, b| files[a.0].path.cmp(&files[b.0].path).then(a.0.cmp(&b.0)));
    }
    out
}

/// Why a file could not be read as a shader.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ReadError {
    /// The file could not be opened or read.
    #[error("{}", io_message(.0))]
    Io(#[from] std::io::Error),
    /// The file is larger than [`MAX_FILE_SIZE`].
    #[error("the file is {0} bytes; essl reads shaders of at most {MAX_FILE_SIZE} bytes (16 MiB)")]
    TooLarge(u64),
    /// The file is not UTF-8: the byte offset of the first invalid byte.
    #[error(
        "the file is not UTF-8: invalid byte at offset {0} (GLSL ES sources are ASCII; save it \
         as UTF-8)"
    )]
    NotUtf8(usize),
}

/// Reads a shader: refuses files over [`MAX_FILE_SIZE`] before reading them, and text that is
/// not UTF-8 (naming the first invalid byte's offset).
pub fn read_source(path: &Path) -> Result<String, ReadError> {
    use std::io::Read;
    let file = std::fs::File::open(path)?;
    let len = file.metadata()?.len();
    if len > MAX_FILE_SIZE {
        return Err(ReadError::TooLarge(len));
    }
    let mut bytes = Vec::with_capacity(len as usize);
    // Read at most one byte past the limit, in case the file grew since `metadata`.
    file.take(MAX_FILE_SIZE + 1).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > MAX_FILE_SIZE {
        return Err(ReadError::TooLarge(bytes.len() as u64));
    }
    String::from_utf8(bytes).map_err(|e| ReadError::NotUtf8(e.utf8_error().valid_up_to()))
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

/// The shader files under `dir`, depth first in name order (so sorted by path): files whose
/// extension names a stage, skipping hidden entries, symbolic links to folders, and what
/// `keep` refuses. Folders that cannot be listed are returned beside them.
pub fn walk(
    dir: &Path,
    keep: &mut dyn FnMut(&Path) -> bool,
) -> (Vec<ShaderFile>, Vec<(PathBuf, std::io::Error)>) {
    let mut found = Vec::new();
    let mut errors = Vec::new();
    walk_into(dir, keep, &mut found, &mut errors);
    (found, errors)
}

fn walk_into(
    dir: &Path,
    keep: &mut dyn FnMut(&Path) -> bool,
    found: &mut Vec<ShaderFile>,
    errors: &mut Vec<(PathBuf, std::io::Error)>,
) {
    let entries = match std::fs::read_dir(dir) {
        Ok(entries) => entries,
        Err(e) => {
            errors.push((dir.to_path_buf(), e));
            return;
        }
    };
    // The entry's own type comes from the listing on most file systems: no `stat` per file.
    let mut children: Vec<(PathBuf, std::fs::FileType)> = entries
        .filter_map(|e| {
            let e = e.ok()?;
            Some((e.path(), e.file_type().ok()?))
        })
        .collect();
    children.sort_by(|a, b| a.0.file_name().cmp(&b.0.file_name()));
    for (path, file_type) in children {
        let hidden = path
            .file_name()
            .and_then(|n| n.to_str())
            .is_some_and(|n| n.starts_with('.'));
        if hidden || !keep(&path) {
            continue;
        }
        if file_type.is_dir() {
            walk_into(&path, keep, found, errors);
        } else if let Some(stage) = Stage::from_path(&path) {
            found.push(ShaderFile { path, stage });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn file(path: impl Into<PathBuf>, stage: Stage) -> ShaderFile {
        ShaderFile {
            path: path.into(),
            stage,
        }
    }

    #[test]
    fn pairs_by_folder_and_base_name() {
        let files = vec![
            file("d/a.fixed.frag", Stage::Fragment),
            file("d/a.fixed.vert", Stage::Vertex),
            file("d/a.frag", Stage::Fragment),
            file("d/a.vert", Stage::Vertex),
            file("d/a.vs", Stage::Vertex),
            file("d/b.vert", Stage::Vertex),
            file("e/a.frag", Stage::Fragment),
            file("d/c.glsl", Stage::Vertex),
            file("d/c.frag", Stage::Fragment),
        ];
        assert_eq!(pairs(&files), vec![(1, 0), (3, 2)]);
    }

    #[test]
    fn pairs_come_in_vertex_path_order_however_files_are_listed() {
        let files = vec![
            file("z.vert", Stage::Vertex),
            file("b/a.frag", Stage::Fragment),
            file("a.frag", Stage::Fragment),
            file("z.frag", Stage::Fragment),
            file("b/a.vert", Stage::Vertex),
            file("a.vert", Stage::Vertex),
        ];
        assert_eq!(pairs(&files), vec![(5, 2), (4, 1), (0, 3)]);
    }

    #[test]
    fn a_folder_pairs_with_itself_however_it_is_written() {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path().join("d");
        std::fs::create_dir(&d).unwrap();
        let files = vec![
            file(d.join("a.vert"), Stage::Vertex),
            file(d.join("../d/a.frag"), Stage::Fragment),
        ];
        assert_eq!(pairs(&files), vec![(0, 1)]);
    }

    #[test]
    fn walk_sorts_skips_hidden_and_filters() {
        let dir = tempfile::tempdir().unwrap();
        for name in ["b.frag", "a.vert", ".hidden.frag", "notes.txt", "sub/c.vs"] {
            let path = dir.path().join(name);
            std::fs::create_dir_all(path.parent().unwrap()).unwrap();
            std::fs::write(path, "").unwrap();
        }
        let names = |files: Vec<ShaderFile>| -> Vec<String> {
            files
                .iter()
                .map(|f| {
                    let rel = f.path.strip_prefix(dir.path()).unwrap();
                    format!("{} {}", rel.display(), f.stage.as_str())
                })
                .collect()
        };
        let (found, errors) = walk(dir.path(), &mut |_| true);
        assert!(errors.is_empty());
        assert_eq!(
            names(found),
            ["a.vert vertex", "b.frag fragment", "sub/c.vs vertex"]
        );
        let (found, _) = walk(dir.path(), &mut |p| !p.ends_with("sub"));
        assert_eq!(names(found), ["a.vert vertex", "b.frag fragment"]);
        let (_, errors) = walk(&dir.path().join("missing"), &mut |_| true);
        assert_eq!(errors.len(), 1);
    }

    #[test]
    fn reading_refuses_what_is_not_utf8() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a.frag");
        std::fs::write(&path, b"void main() {}\n\xff").unwrap();
        let e = read_source(&path).unwrap_err();
        assert_eq!(
            e.to_string(),
            "the file is not UTF-8: invalid byte at offset 15 (GLSL ES sources are ASCII; save it as UTF-8)"
        );
        let e = read_source(&dir.path().join("none.frag")).unwrap_err();
        assert_eq!(e.to_string(), "no such file or directory");
    }
}
