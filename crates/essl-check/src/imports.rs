//! Following what a script's shader substitutions import: `${main}` where `main` is
//! `import main from './vertex-main.glsl'` is the default export of
//! `vertex-main.glsl.ts`, read from disk beside the importing script (relative specifiers
//! only; a package's modules are a preset's business), each script read once per host.

use std::cell::RefCell;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::rc::Rc;
use std::sync::Arc;

use essl::source::SourceFile;

use crate::extract::js::{self, Consts, Unknown};
use crate::extract::{Imports, Piece};
use crate::read::read_source;

/// A script read for its exports.
pub(crate) struct Script {
    /// Its path.
    pub path: PathBuf,
    /// Its text.
    pub file: Arc<SourceFile>,
    /// Its top-level names.
    pub consts: Consts,
}

type Cache = Rc<RefCell<HashMap<PathBuf, Option<Rc<Script>>>>>;

/// The imports of the scripts in one folder, read from disk.
pub struct DiskImports {
    dir: PathBuf,
    cache: Cache,
}

/// The extensions tried after a specifier that names no file (`./x.glsl` → `./x.glsl.ts`).
const EXTENSIONS: [&str; 8] = [".ts", ".js", ".mjs", ".tsx", ".jsx", ".mts", ".cjs", ".cts"];

impl DiskImports {
    /// Imports relative to `dir`, the importing script's folder.
    pub fn new(dir: &Path) -> DiskImports {
        DiskImports {
            dir: dir.to_path_buf(),
            cache: Rc::default(),
        }
    }

    /// The imports of a script in `dir` that share this one's cache of scripts read.
    pub(crate) fn at(&self, dir: &Path) -> DiskImports {
        DiskImports {
            dir: dir.to_path_buf(),
            cache: self.cache.clone(),
        }
    }

    /// The file a relative specifier names, as a bundler resolves it.
    pub(crate) fn resolve(&self, from: &str) -> Option<PathBuf> {
        let base = lexical(&self.dir.join(from));
        if base.is_file() {
            return Some(base);
        }
        let name = base.file_name()?.to_string_lossy().into_owned();
        let with = |ext: &str| base.with_file_name(format!("{name}{ext}"));
        EXTENSIONS
            .iter()
            .map(|e| with(e))
            .chain(EXTENSIONS.iter().map(|e| base.join(format!("index{e}"))))
            .find(|p| p.is_file())
    }

    /// Puts a script whose text is already read (a host file) in the cache, so that its
    /// literals are named by the same file wherever they are met.
    pub(crate) fn add(&self, path: &Path, file: Arc<SourceFile>) {
        let consts = js::consts_of(file.text());
        let script = Rc::new(Script {
            path: path.to_path_buf(),
            file,
            consts,
        });
        self.cache.borrow_mut().insert(real(path), Some(script));
    }

    /// The script at `path`, read once.
    pub(crate) fn script(&self, path: &Path) -> Option<Rc<Script>> {
        let key = real(path);
        if let Some(s) = self.cache.borrow().get(&key) {
            return s.clone();
        }
        let script = read_source(path).ok().map(|text| {
            let consts = js::consts_of(&text);
            Rc::new(Script {
                path: path.to_path_buf(),
                file: Arc::new(SourceFile::new(path.display().to_string(), text)),
                consts,
            })
        });
        self.cache.borrow_mut().insert(key, script.clone());
        script
    }
}

impl Imports for DiskImports {
    fn import(
        &self,
        from: &str,
        name: &str,
        member: &str,
        depth: usize,
    ) -> Result<Vec<Piece>, Unknown> {
        let unknown = || Unknown::Name(format!("{name} (from `{from}`)"));
        if !from.starts_with('.') {
            return Err(unknown());
        }
        let path = self.resolve(from).ok_or_else(unknown)?;
        let script = self.script(&path).ok_or_else(unknown)?;
        let there = self.at(path.parent().unwrap_or(Path::new("")));
        let pieces = js::exported(
            script.file.text(),
            &script.consts,
            &there,
            name,
            member,
            depth + 1,
        )?;
        Ok(vec![Piece::From {
            file: script.file.clone(),
            pieces,
        }])
    }
}

/// `path` with its `.` and `dir/..` components taken out, as it reads (`src/pp/../x.js` is
/// `src/x.js`), so that diagnostics name the file as a person would.
fn lexical(path: &Path) -> PathBuf {
    use std::path::Component;
    let mut out: Vec<Component> = Vec::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir if matches!(out.last(), Some(Component::Normal(_))) => {
                out.pop();
            }
            _ => out.push(c),
        }
    }
    out.iter().collect()
}

fn real(p: &Path) -> PathBuf {
    std::fs::canonicalize(p).unwrap_or_else(|_| p.to_path_buf())
}
