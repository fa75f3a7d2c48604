//! Reading files safely (a size limit, a UTF-8 check), and [`Files`], through which the
//! pipeline reads: the disk, with the texts an editor holds open in front of it, each file
//! read once per run however many shaders include it.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use essl::source::SourceFile;

/// The largest file essl reads: 16 MiB. Larger files are refused, not read.
pub const MAX_FILE_SIZE: u64 = 16 * 1024 * 1024;

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

/// Where the pipeline reads files from: texts given in memory (an editor's open documents, a
/// bundler's transformed modules) first, then the disk. A file read from disk is kept for the
/// rest of the run, so that a header that a hundred shaders include is read and indexed once.
#[derive(Debug, Default)]
pub struct Files {
    given: HashMap<PathBuf, Arc<SourceFile>>,
    read: Mutex<HashMap<PathBuf, Arc<SourceFile>>>,
}

impl Files {
    /// Files read from disk only.
    pub fn disk() -> Files {
        Files::default()
    }

    /// Puts `text` in front of the file at `path`: reads of `path` return it.
    pub fn give(&mut self, path: impl Into<PathBuf>, text: impl Into<String>) {
        let path = path.into();
        let file = SourceFile::new(path.display().to_string(), text);
        self.given.insert(path, Arc::new(file));
    }

    /// Whether a text was given for `path`.
    pub fn is_given(&self, path: &Path) -> bool {
        self.given.contains_key(path)
    }

    /// Whether `path` names a file: one given, or one on disk.
    pub fn exists(&self, path: &Path) -> bool {
        self.given.contains_key(path) || path.is_file()
    }

    /// The file at `path` (named in diagnostics as the path is written).
    pub fn read(&self, path: &Path) -> Result<Arc<SourceFile>, ReadError> {
        if let Some(f) = self.given.get(path) {
            return Ok(f.clone());
        }
        if let Some(f) = self.cache().get(path) {
            return Ok(f.clone());
        }
        let text = read_source(path)?;
        let file = Arc::new(SourceFile::new(path.display().to_string(), text));
        self.cache().insert(path.to_path_buf(), file.clone());
        Ok(file)
    }

    /// The file at `path`, not kept for the rest of the run: a shader's own file, read once
    /// (keeping every file of a folder of 10,000 shaders would cost a map entry each for
    /// nothing).
    pub fn read_once(&self, path: &Path) -> Result<Arc<SourceFile>, ReadError> {
        if let Some(f) = self.given.get(path) {
            return Ok(f.clone());
        }
        let text = read_source(path)?;
        Ok(Arc::new(SourceFile::new(path.display().to_string(), text)))
    }

    /// Forgets what was read from disk (a file may have changed); given texts stay.
    pub fn forget_disk(&self) {
        self.cache().clear();
    }

    fn cache(&self) -> std::sync::MutexGuard<'_, HashMap<PathBuf, Arc<SourceFile>>> {
        // A panic while the lock was held left nothing half-written: a map insert is whole.
        self.read.lock().unwrap_or_else(|e| e.into_inner())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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

    #[test]
    fn given_texts_come_first_and_disk_reads_are_kept() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a.glsl");
        std::fs::write(&path, "disk").unwrap();
        let mut files = Files::disk();
        let first = files.read(&path).unwrap();
        std::fs::write(&path, "changed").unwrap();
        assert!(Arc::ptr_eq(&first, &files.read(&path).unwrap()));
        files.forget_disk();
        assert_eq!(files.read(&path).unwrap().text(), "changed");
        files.give(&path, "open");
        assert_eq!(files.read(&path).unwrap().text(), "open");
        assert!(files.exists(&dir.path().join("a.glsl")));
    }
}
