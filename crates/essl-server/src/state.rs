//! What the server holds between messages: the open documents with their latest checks, the
//! pipeline's settings and files (open documents in front of the disk, so that an included
//! file being edited is checked as the editor shows it), the work a change left pending, and
//! the partner shaders read from disk to link open ones with.

use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::Arc;

use essl::Stage;
use essl_check::{CheckOptions, Configs, Files, Overrides};
use lsp_types::{PublishDiagnosticsParams, Uri};

use crate::analysis::Analysis;
use crate::convert;
use crate::document::{self, Doc};

/// A file read from disk to be linked with an open document, checked once per version.
struct OnDisk {
    modified: Option<std::time::SystemTime>,
    len: u64,
    analysis: Arc<Analysis>,
}

/// The server's state.
pub(crate) struct State {
    /// The open documents.
    pub docs: HashMap<Uri, Doc>,
    configs: Configs,
    files: Files,
    /// New texts not checked yet, in the order they came.
    pub unchecked: Vec<(Uri, String)>,
    /// Documents checked but not linted yet.
    pub unlinted: Vec<Uri>,
    /// Partners read from disk.
    on_disk: HashMap<PathBuf, OnDisk>,
    /// Replaced checks, freed after the diagnostics of their successors are out.
    pub retired: Vec<Doc>,
}

impl Default for State {
    fn default() -> State {
        State {
            docs: HashMap::new(),
            configs: Configs::new(Overrides::default()),
            files: Files::disk(),
            unchecked: Vec::new(),
            unlinted: Vec::new(),
            on_disk: HashMap::new(),
            retired: Vec::new(),
        }
    }
}

impl State {
    /// Forgets the settings and the files read from disk (essl.toml or a partner may have
    /// changed).
    pub fn forget_files(&mut self) {
        self.configs.forget();
        self.files.forget_disk();
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
        self.files.give(path.clone(), text.clone());
        let doc = Doc::check(path, text, &self.configs, &self.files, self.docs.get(&uri));
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
        self.docs.get_mut(uri).is_some_and(|doc| doc.lint())
    }

    /// The partner of the shader file at `uri`: its URI and analysis (open, or read from disk).
    fn partner(&mut self, uri: &Uri) -> Option<(Uri, Arc<Analysis>)> {
        let doc = self.docs.get(uri).filter(|d| !d.host)?;
        let open_path = |p: &std::path::Path| -> Option<Uri> {
            let u = convert::path_to_uri(p)?;
            self.docs.get(&u).filter(|d| !d.host).map(|_| u)
        };
        let path = essl_check::partner(&doc.path, |p| open_path(p).is_some() || p.is_file())?;
        let other = convert::path_to_uri(&path)?;
        if let Some(doc) = self.docs.get(&other).filter(|d| !d.host) {
            return Some((other, doc.parts.first()?.clone()));
        }
        let meta = std::fs::metadata(&path).ok()?;
        let (modified, len) = (meta.modified().ok(), meta.len());
        if let Some(d) = self.on_disk.get(&path) {
            if d.modified.is_some() && d.modified == modified && d.len == len {
                return Some((other, d.analysis.clone()));
            }
        }
        let text = essl_check::read_source(&path).ok()?;
        let (unit, _) = essl_check::check_text(
            &path,
            text,
            &self.configs,
            &self.files,
            CheckOptions::default(),
        )
        .ok()?;
        let analysis = Arc::new(Analysis::new(unit.shaders.into_iter().next()?));
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
        let Some(mine) = doc.parts.first().filter(|_| !doc.host).cloned() else {
            return out;
        };
        let Some((other, theirs)) = self.partner(uri) else {
            return out;
        };
        let their_doc = theirs.document().clone();
        let mut theirs_params = params(
            &other,
            theirs
                .diagnostics()
                .into_iter()
                .map(|d| convert::diagnostic(&their_doc, &other, d))
                .collect(),
        );
        let (vs, fs) = match mine.checked.stage {
            Stage::Vertex => (&mine, &theirs),
            Stage::Fragment => (&theirs, &mine),
        };
        let program = essl_check::link(&vs.checked, &fs.checked);
        for d in &program.diagnostics {
            let Some(file) = &d.file else { continue };
            let (target, doc) = if Arc::ptr_eq(file, &their_doc) {
                (&mut theirs_params, &their_doc)
            } else if Arc::ptr_eq(file, mine.document()) {
                (&mut out[0], mine.document())
            } else {
                continue;
            };
            let u = target.uri.clone();
            target
                .diagnostics
                .push(convert::link_diagnostic(doc, &u, &d.diagnostic));
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
