//! The server's loop: the open documents, each checked when it opens or changes, with its
//! diagnostics (and its program's link diagnostics, on the file they point into) published;
//! requests answered from the latest check.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use essl::Stage;
use essl_build::Config;
use lsp_server::{Connection, Message, Notification, Request, RequestId, Response};
use lsp_types::notification::{self, Notification as _};
use lsp_types::request::{self, Request as _};
use lsp_types::{PublishDiagnosticsParams, Uri};

use crate::analysis::{self, Analysis};
use crate::{actions, complete, convert, hover, navigate, ServerError};

/// An open document.
struct Doc {
    path: PathBuf,
    analysis: Arc<Analysis>,
}

/// The server's state.
#[derive(Default)]
pub(crate) struct State {
    docs: HashMap<Uri, Doc>,
    configs: HashMap<PathBuf, Config>,
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

    /// Checks a document's new text.
    fn update(&mut self, uri: Uri, text: String) {
        let Some(path) = convert::uri_to_path(&uri).or_else(|| Some(PathBuf::from(uri.as_str())))
        else {
            return;
        };
        let config = self.config(&path);
        let analysis = Arc::new(analysis::analyse(&path, &text, &config));
        self.docs.insert(uri, Doc { path, analysis });
    }

    /// The partner of the document at `uri`: its URI and analysis (open, or read from disk).
    fn partner(&mut self, uri: &Uri) -> Option<(Uri, Arc<Analysis>)> {
        let path = analysis::partner(&self.docs.get(uri)?.path)?;
        let other = convert::path_to_uri(&path)?;
        if let Some(doc) = self.docs.get(&other) {
            return Some((other, doc.analysis.clone()));
        }
        let text = std::fs::read_to_string(&path).ok()?;
        let config = self.config(&path);
        Some((other, Arc::new(analysis::analyse(&path, &text, &config))))
    }

    /// The diagnostics to publish for the document at `uri` and for its partner.
    fn diagnostics(&mut self, uri: &Uri) -> Vec<PublishDiagnosticsParams> {
        let Some(doc) = self.docs.get(uri) else {
            return Vec::new();
        };
        let mine = doc.analysis.clone();
        let mut out = vec![own(uri, &mine)];
        if let Some((other, theirs)) = self.partner(uri) {
            let mut theirs_params = own(&other, &theirs);
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
                    let u = target.uri.clone();
                    let mut converted = convert::diagnostic(&a.shader.file, &u, &d.diagnostic);
                    converted.message = format!("program: {}", converted.message);
                    target.diagnostics.push(converted);
                }
            }
            out.push(theirs_params);
        }
        out
    }
}

/// A document's own diagnostics.
fn own(uri: &Uri, a: &Analysis) -> PublishDiagnosticsParams {
    let diagnostics = a
        .shader
        .diagnostics
        .iter()
        .map(|d| convert::diagnostic(&a.shader.file, uri, d))
        .collect();
    PublishDiagnosticsParams {
        uri: uri.clone(),
        diagnostics,
        version: None,
    }
}

fn send(conn: &Connection, msg: Message) -> Result<(), ServerError> {
    conn.sender.send(msg).map_err(|_| ServerError::Disconnected)
}

fn publish(conn: &Connection, state: &mut State, uri: &Uri) -> Result<(), ServerError> {
    for params in state.diagnostics(uri) {
        let n = Notification::new(notification::PublishDiagnostics::METHOD.into(), params);
        send(conn, Message::Notification(n))?;
    }
    Ok(())
}

/// Handles notifications: open, change, close.
fn notify(conn: &Connection, state: &mut State, n: Notification) -> Result<(), ServerError> {
    match n.method.as_str() {
        notification::DidOpenTextDocument::METHOD => {
            let p: lsp_types::DidOpenTextDocumentParams = parse(n.params)?;
            let uri = p.text_document.uri;
            state.update(uri.clone(), p.text_document.text);
            publish(conn, state, &uri)?;
        }
        notification::DidChangeTextDocument::METHOD => {
            let p: lsp_types::DidChangeTextDocumentParams = parse(n.params)?;
            let uri = p.text_document.uri;
            // Full synchronisation: the last change holds the whole text.
            if let Some(change) = p.content_changes.into_iter().last() {
                state.update(uri.clone(), change.text);
                publish(conn, state, &uri)?;
            }
        }
        notification::DidCloseTextDocument::METHOD => {
            let p: lsp_types::DidCloseTextDocumentParams = parse(n.params)?;
            state.docs.remove(&p.text_document.uri);
            let cleared = PublishDiagnosticsParams {
                uri: p.text_document.uri,
                diagnostics: Vec::new(),
                version: None,
            };
            let n = Notification::new(notification::PublishDiagnostics::METHOD.into(), cleared);
            send(conn, Message::Notification(n))?;
        }
        notification::DidChangeWatchedFiles::METHOD | notification::DidSaveTextDocument::METHOD => {
            // essl.toml may have changed: read it again on the next check.
            state.configs.clear();
        }
        _ => {}
    }
    Ok(())
}

fn parse<T: serde::de::DeserializeOwned>(v: serde_json::Value) -> Result<T, ServerError> {
    serde_json::from_value(v).map_err(|e| ServerError::Protocol(e.to_string()))
}

/// The latest check of the document a request names.
fn doc<'a>(state: &'a State, uri: &Uri) -> Option<&'a Analysis> {
    state.docs.get(uri).map(|d| &*d.analysis)
}

/// The start of the error message for a request the server does not answer.
const UNKNOWN: &str = "essl-server does not answer ";

/// Answers one request.
fn answer(state: &State, req: Request) -> Response {
    let id: RequestId = req.id.clone();
    let result: Result<serde_json::Value, String> = (|| match req.method.as_str() {
        request::HoverRequest::METHOD => {
            let params: lsp_types::HoverParams = from(req.params)?;
            let pos = params.text_document_position_params;
            json(doc(state, &pos.text_document.uri).and_then(|a| hover::hover(a, pos.position)))
        }
        request::GotoDefinition::METHOD => {
            let params: lsp_types::GotoDefinitionParams = from(req.params)?;
            let pos = params.text_document_position_params;
            let uri = pos.text_document.uri;
            let found = doc(state, &uri).and_then(|a| navigate::definition(a, &uri, pos.position));
            json(found.map(lsp_types::GotoDefinitionResponse::Scalar))
        }
        request::References::METHOD => {
            let params: lsp_types::ReferenceParams = from(req.params)?;
            let pos = params.text_document_position;
            let uri = pos.text_document.uri;
            let include = params.context.include_declaration;
            let found =
                doc(state, &uri).map(|a| navigate::references(a, &uri, pos.position, include));
            json(found)
        }
        request::DocumentSymbolRequest::METHOD => {
            let params: lsp_types::DocumentSymbolParams = from(req.params)?;
            let found = doc(state, &params.text_document.uri).map(navigate::symbols);
            json(found.map(lsp_types::DocumentSymbolResponse::Nested))
        }
        request::Completion::METHOD => {
            let params: lsp_types::CompletionParams = from(req.params)?;
            let pos = params.text_document_position;
            let found =
                doc(state, &pos.text_document.uri).map(|a| complete::complete(a, pos.position));
            json(found.map(lsp_types::CompletionResponse::Array))
        }
        request::CodeActionRequest::METHOD => {
            let params: lsp_types::CodeActionParams = from(req.params)?;
            let uri = params.text_document.uri.clone();
            let found = doc(state, &uri).map(|a| actions::actions(a, &uri, params.range));
            json(found)
        }
        other => Err(format!("{UNKNOWN}`{other}`")),
    })();
    match result {
        Ok(v) => Response::new_ok(id, v),
        Err(message) => {
            let code = if message.starts_with(UNKNOWN) {
                lsp_server::ErrorCode::MethodNotFound
            } else {
                lsp_server::ErrorCode::InvalidParams
            };
            Response::new_err(id, code as i32, message)
        }
    }
}

fn json<T: serde::Serialize>(v: T) -> Result<serde_json::Value, String> {
    serde_json::to_value(v).map_err(|e| e.to_string())
}

fn from<T: serde::de::DeserializeOwned>(v: serde_json::Value) -> Result<T, String> {
    serde_json::from_value(v).map_err(|e| e.to_string())
}

/// Serves one client until it asks to shut down.
pub(crate) fn main_loop(conn: &Connection) -> Result<(), ServerError> {
    let mut state = State::default();
    for msg in &conn.receiver {
        match msg {
            Message::Request(req) => {
                if conn
                    .handle_shutdown(&req)
                    .map_err(|e| ServerError::Protocol(e.to_string()))?
                {
                    return Ok(());
                }
                let response = answer(&state, req);
                send(conn, Message::Response(response))?;
            }
            Message::Notification(n) => notify(conn, &mut state, n)?,
            Message::Response(_) => {}
        }
    }
    Ok(())
}
