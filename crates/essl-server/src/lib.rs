//! essl-server: a Language Server for WebGL shaders (GLSL ES 3.00 and 1.00), over standard
//! input and output.
//!
//! Each document is checked as `essl lint` checks it — compiled, linted with the levels of
//! its nearest `essl.toml`, and linked with its `NAME.vert` / `NAME.frag` partner (open, or
//! on disk), link diagnostics published on the file they point into — when it opens and on
//! every change. A shader inside an HTML page or a JS/TS file is checked the same way, on its
//! own text, and placed back on the document's lines ([`document`]). Requests are answered
//! from the latest check:
//!
//! - diagnostics: the same codes, spans, notes and helps as the command line, secondary
//!   labels as related information ([`convert`]);
//! - code actions: every fix, and "allow this rule here" for a lint finding ([`actions`]);
//! - hover: a name's declaration (qualifiers, precision, type), a built-in's overloads and
//!   one line about it, an expression's type ([`hover`]);
//! - go to definition, references, document symbols ([`navigate`]) over the checked tree's
//!   uses ([`index`]);
//! - completion ([`complete`]).
//!
//! `essl server` and the `essl-server` binary both call [`run_stdio`].

#![warn(missing_docs)]

mod actions;
mod analysis;
mod builtin_docs;
mod complete;
mod convert;
mod document;
mod hover;
mod index;
mod navigate;
mod server;
mod state;

use lsp_server::Connection;
use lsp_types::{
    CodeActionProviderCapability, CompletionOptions, HoverProviderCapability, OneOf,
    ServerCapabilities, TextDocumentSyncCapability, TextDocumentSyncKind,
};

/// Why the server stopped before the client asked it to.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ServerError {
    /// The client broke the protocol (a malformed message, no `initialize` first).
    #[error("protocol error: {0}")]
    Protocol(String),
    /// The client went away.
    #[error("the client disconnected")]
    Disconnected,
    /// Standard input or output failed.
    #[error("i/o error: {0}")]
    Io(#[from] std::io::Error),
}

/// What the server can do, as `initialize` answers.
fn capabilities() -> ServerCapabilities {
    ServerCapabilities {
        text_document_sync: Some(TextDocumentSyncCapability::Kind(TextDocumentSyncKind::FULL)),
        hover_provider: Some(HoverProviderCapability::Simple(true)),
        definition_provider: Some(OneOf::Left(true)),
        references_provider: Some(OneOf::Left(true)),
        document_symbol_provider: Some(OneOf::Left(true)),
        completion_provider: Some(CompletionOptions::default()),
        code_action_provider: Some(CodeActionProviderCapability::Simple(true)),
        ..ServerCapabilities::default()
    }
}

/// Serves one client over `conn` (after its `initialize`) until it shuts down.
pub fn serve(conn: &Connection) -> Result<(), ServerError> {
    let caps =
        serde_json::to_value(capabilities()).map_err(|e| ServerError::Protocol(e.to_string()))?;
    conn.initialize(caps)
        .map_err(|e| ServerError::Protocol(e.to_string()))?;
    server::main_loop(conn)
}

/// Serves one client over standard input and output until it shuts down and exits.
pub fn run_stdio() -> Result<(), ServerError> {
    let (conn, threads) = Connection::stdio();
    serve(&conn)?;
    drop(conn);
    threads.join()?;
    Ok(())
}
