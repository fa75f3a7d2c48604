//! The server's loop: the open documents, each checked when it opens or changes, with its
//! diagnostics (and its program's link diagnostics, on the file they point into) published;
//! requests answered from the latest check.
//!
//! A change is checked in two steps, so that an error appears as soon as the front end has
//! found it: once no message is waiting, changed documents go through the front end and their
//! diagnostics are published (with the previous text's lint findings that lie outside the
//! edit); then, if still no message is waiting, each is lowered to naga IR and linted, and its
//! diagnostics are published again. Changes that arrive together are checked once (the last
//! text wins), and a request first finishes every pending check, so that it is answered from
//! the text it was sent for.

use lsp_server::{Connection, Message, Notification, Request, RequestId, Response};
use lsp_types::notification::{self, Notification as _};
use lsp_types::request::{self, Request as _};
use lsp_types::{PublishDiagnosticsParams, Uri};

use crate::document::Doc;
use crate::state::State;
use crate::{actions, complete, hover, navigate, ServerError};

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
            state.change(p.text_document.uri, p.text_document.text);
        }
        notification::DidChangeTextDocument::METHOD => {
            let p: lsp_types::DidChangeTextDocumentParams = parse(n.params)?;
            let uri = p.text_document.uri;
            // Full synchronisation: the last change holds the whole text.
            if let Some(change) = p.content_changes.into_iter().last() {
                state.change(uri, change.text);
            }
        }
        notification::DidCloseTextDocument::METHOD => {
            let p: lsp_types::DidCloseTextDocumentParams = parse(n.params)?;
            state.close(&p.text_document.uri);
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
            state.forget_files();
        }
        _ => {}
    }
    Ok(())
}

fn parse<T: serde::de::DeserializeOwned>(v: serde_json::Value) -> Result<T, ServerError> {
    serde_json::from_value(v).map_err(|e| ServerError::Protocol(e.to_string()))
}

/// The latest check of the document a request names.
fn doc<'a>(state: &'a State, uri: &Uri) -> Option<&'a Doc> {
    state.docs.get(uri)
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
            let at = doc(state, &pos.text_document.uri).and_then(|d| d.at(pos.position));
            json(at.and_then(|(a, place)| hover::hover(a, place, pos.position)))
        }
        request::GotoDefinition::METHOD => {
            let params: lsp_types::GotoDefinitionParams = from(req.params)?;
            let pos = params.text_document_position_params;
            let uri = pos.text_document.uri;
            let at = doc(state, &uri).and_then(|d| d.at(pos.position));
            let found =
                at.and_then(|(a, place)| navigate::definition(a, place, &uri, pos.position));
            json(found.map(lsp_types::GotoDefinitionResponse::Scalar))
        }
        request::References::METHOD => {
            let params: lsp_types::ReferenceParams = from(req.params)?;
            let pos = params.text_document_position;
            let uri = pos.text_document.uri;
            let include = params.context.include_declaration;
            let at = doc(state, &uri).and_then(|d| d.at(pos.position));
            let found =
                at.map(|(a, place)| navigate::references(a, place, &uri, pos.position, include));
            json(found)
        }
        request::DocumentSymbolRequest::METHOD => {
            let params: lsp_types::DocumentSymbolParams = from(req.params)?;
            let found = doc(state, &params.text_document.uri).map(|d| {
                d.all()
                    .flat_map(|(a, place)| navigate::symbols(a, place))
                    .collect()
            });
            json(found.map(lsp_types::DocumentSymbolResponse::Nested))
        }
        request::Completion::METHOD => {
            let params: lsp_types::CompletionParams = from(req.params)?;
            let pos = params.text_document_position;
            let at = doc(state, &pos.text_document.uri).and_then(|d| d.at(pos.position));
            let found = at.map(|(a, place)| complete::complete(a, place, pos.position));
            json(found.map(lsp_types::CompletionResponse::Array))
        }
        request::CodeActionRequest::METHOD => {
            let params: lsp_types::CodeActionParams = from(req.params)?;
            let uri = params.text_document.uri.clone();
            let found = doc(state, &uri).map(|d| {
                d.all()
                    .flat_map(|(a, place)| actions::actions(a, place, &uri, params.range))
                    .collect::<Vec<_>>()
            });
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

/// Checks every changed document and publishes its diagnostics.
fn check_changed(conn: &Connection, state: &mut State) -> Result<(), ServerError> {
    for (uri, text) in std::mem::take(&mut state.unchecked) {
        state.update(uri.clone(), text);
        publish(conn, state, &uri)?;
    }
    Ok(())
}

/// Lints one checked document and publishes its diagnostics again.
fn lint_one(conn: &Connection, state: &mut State) -> Result<(), ServerError> {
    if let Some(uri) = state.unlinted.first().cloned() {
        if state.lint(&uri) {
            publish(conn, state, &uri)?;
        }
    }
    Ok(())
}

/// Serves one client until it asks to shut down.
pub(crate) fn main_loop(conn: &Connection) -> Result<(), ServerError> {
    let mut state = State::default();
    loop {
        let msg = if state.unchecked.is_empty() && state.unlinted.is_empty() {
            state.retired.clear();
            match conn.receiver.recv() {
                Ok(msg) => msg,
                Err(_) => return Ok(()),
            }
        } else {
            match conn.receiver.try_recv() {
                Ok(msg) => msg,
                Err(crossbeam_channel::TryRecvError::Empty) => {
                    // Idle: the next step of pending work, then look for messages again.
                    if state.unchecked.is_empty() {
                        lint_one(conn, &mut state)?;
                    } else {
                        check_changed(conn, &mut state)?;
                    }
                    continue;
                }
                Err(crossbeam_channel::TryRecvError::Disconnected) => return Ok(()),
            }
        };
        match msg {
            Message::Request(req) => {
                if conn
                    .handle_shutdown(&req)
                    .map_err(|e| ServerError::Protocol(e.to_string()))?
                {
                    return Ok(());
                }
                // Answer from the text the request was sent for, with its lint findings.
                check_changed(conn, &mut state)?;
                while !state.unlinted.is_empty() {
                    lint_one(conn, &mut state)?;
                }
                let response = answer(&state, req);
                send(conn, Message::Response(response))?;
            }
            Message::Notification(n) => notify(conn, &mut state, n)?,
            Message::Response(_) => {}
        }
    }
}
