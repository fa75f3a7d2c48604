//! What the server holds between messages: the open documents with their latest checks, the
//! settings of each folder, the work a change left pending, and the partner shaders read
//! from disk to link open ones with.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use essl::Stage;
use essl_build::Config;
use lsp_types::{PublishDiagnosticsParams, Uri};

use crate::analysis::{self, Analysis};
use crate::convert::{self, Place};
use crate::document::{self, Doc};

/// A file read from disk to be linked with an open document, checked once per version.
struct OnDisk {
    modified: Option<std::time::SystemTime>,
    len: u64,
    analysis: Arc<Analysis>,
}

/// The server's state.
#[derive(Default)]
pub(crate) struct State {
    /// The open documents.
    pub docs: HashMap<Uri, Doc>,
    configs: HashMap<PathBuf, Config>,
    /// New texts not checked yet, in the order they came.
    pub unchecked: Vec<(Uri, String)>,
    /// Documents checked but not linted yet.
    pub unlinted: Vec<Uri>,
    /// Partners read from disk.
    on_disk: HashMap<PathBuf, OnDisk>,
    /// Replaced checks, freed after the diagnostics of their successors are out.
    pub retired: Vec<Doc>,
}

impl State {
    /// The settings of the nearest essl.toml above `path` (the defaults when there is none or
    /// it cannot be read: the error is logged to stderr).
    fn config(&mut self, path: &Path) -> Config {
        let dir = path.parent().unwrap_or(Path::new("/")).to_path_buf();
        self.configs
            .entry(dir.clone())
            .or_insert_with(|| match Config::discover(&dir) {
                Ok(c) => c.unwrap_or_default(),
                Err(e) => {
                    eprintln!("essl-server: {e}");
                    Config::default()
                }
            })
            .clone()
    }

    /// Forgets the settings and the files read from disk (essl.toml or a partner may have
    /// changed).
    pub fn forget_files(&mut self) {
        self.configs.clear();
        self.on_disk.clear();
    }

    /// Records a document's new text, to be checked once no message is waiting.
    pub fn change(&mut self, uri: Uri, text: String) {
        self.unchecked.retain(|(u, _)| *u != uri);
        self.unchecked.push((uri, text));
    }

    /// Forgets a closed document.
    pub fn close(&mut self, uri: &Uri) {
        self.unchecked.retain(|(u, _)| u != uri);
        self.unlinted.retain(|u| u != uri);
        if let Some(doc) = self.docs.remove(uri) {
            self.retired.push(doc);
        }
    }

    /// Runs the front end on a document's new text (lowering and the lints are left for
    /// [`State::lint`]).
    pub fn update(&mut self, uri: Uri, text: String) {
        let path = document::path_of(&uri);
        let config = self.config(&path);
        let doc = Doc::check(path, text, &config, self.docs.get(&uri));
        if doc.unlinted() && !self.unlinted.contains(&uri) {
            self.unlinted.push(uri.clone());
        }
        if let Some(old) = self.docs.insert(uri, doc) {
            self.retired.push(old);
        }
    }

    /// Lowers and lints a checked document; whether anything changed.
    pub fn lint(&mut self, uri: &Uri) -> bool {
        self.unlinted.retain(|u| u != uri);
        let Some(path) = self.docs.get(uri).map(|d| d.path.clone()) else {
            return false;
        };
        let config = self.config(&path);
        self.docs
            .get_mut(uri)
            .is_some_and(|doc| doc.lint(&config.rules))
    }

    /// The partner of the shader file at `uri`: its URI and analysis (open, or read from disk).
    fn partner(&mut self, uri: &Uri) -> Option<(Uri, Arc<Analysis>)> {
        let doc = self.docs.get(uri).filter(|d| !d.host)?;
        let path = analysis::partner(&doc.path)?;
        let other = convert::path_to_uri(&path)?;
        if let Some(doc) = self.docs.get(&other).filter(|d| !d.host) {
            return Some((other, doc.parts.first()?.analysis.clone()));
        }
        let meta = std::fs::metadata(&path).ok()?;
        let (modified, len) = (meta.modified().ok(), meta.len());
        if let Some(d) = self.on_disk.get(&path) {
            if d.modified.is_some() && d.modified == modified && d.len == len {
                return Some((other, d.analysis.clone()));
            }
        }
        let text = std::fs::read_to_string(&path).ok()?;
        let config = self.config(&path);
        let analysis = Arc::new(Analysis::analyse(&path, &text, &config));
        let entry = OnDisk {
            modified,
            len,
            analysis: analysis.clone(),
        };
        self.on_disk.insert(path, entry);
        Some((other, analysis))
    }

    /// The diagnostics to publish for the document at `uri`, and for its partner when it is a
    /// shader file linked with one.
    pub fn diagnostics(&mut self, uri: &Uri) -> Vec<PublishDiagnosticsParams> {
        let Some(doc) = self.docs.get(uri) else {
            return Vec::new();
        };
        let mut out = vec![params(uri, doc.diagnostics(uri))];
        let Some(mine) = doc
            .parts
            .first()
            .filter(|_| !doc.host)
            .map(|p| p.analysis.clone())
        else {
            return out;
        };
        let Some((other, theirs)) = self.partner(uri) else {
            return out;
        };
        let their_place = Place::whole(&theirs.shader.file);
        let mut theirs_params = params(
            &other,
            theirs
                .diagnostics()
                .into_iter()
                .map(|d| convert::diagnostic(their_place, &theirs.shader.file, &other, d))
                .collect(),
        );
        let (vs, fs) = match mine.shader.stage {
            Stage::Vertex => (&mine, &theirs),
            Stage::Fragment => (&theirs, &mine),
        };
        if let Some(program) = analysis::link(&vs.shader, &fs.shader) {
            for d in &program.diagnostics {
                let (target, a) = if d.stage == Some(theirs.shader.stage) {
                    (&mut theirs_params, &theirs)
                } else {
                    (&mut out[0], &mine)
                };
                let (u, file) = (target.uri.clone(), &a.shader.file);
                let converted =
                    convert::link_diagnostic(Place::whole(file), file, &u, &d.diagnostic);
                target.diagnostics.push(converted);
            }
        }
        out.push(theirs_params);
        out
    }
}

fn params(uri: &Uri, diagnostics: Vec<lsp_types::Diagnostic>) -> PublishDiagnosticsParams {
    PublishDiagnosticsParams {
        uri: uri.clone(),
        diagnostics,
        version: None,
    }
}
