//! Re-diagnosing a 1,000-line shader after a one-character change, through the server's
//! whole path over an in-memory connection: a `didChange` notification in, then the two
//! `publishDiagnostics` notifications out, the front end's (compile, convert) and the one with
//! the lint findings.
//!
//! `cargo bench -p essl-server --bench rediagnose`; the goal is under 10 ms.

use std::hint::black_box;
use std::time::Instant;

/// The allocator `essl server` ships with (the CLI's default `mimalloc` feature).
#[global_allocator]
static ALLOCATOR: essl_alloc::Allocator = essl_alloc::Allocator;

use criterion::{criterion_group, criterion_main, Criterion};
use lsp_server::{Connection, Message, Notification, Request};
use serde_json::json;

/// A fragment shader of about 1,000 lines: 62 functions of light arithmetic and a main that
/// calls them.
fn shader() -> String {
    let mut s = String::from(
        "#version 300 es\nprecision highp float;\nuniform vec3 u_light;\nuniform float u_time;\nin vec3 v_normal;\nin vec2 v_uv;\nout vec4 color;\n",
    );
    for i in 0..62 {
        s.push_str(&format!(
            "float shade{i}(vec3 n, vec2 uv) {{\n    vec3 l = normalize(u_light + vec3({i}.0));\n    float d = max(dot(n, l), 0.0);\n    float s = pow(max(d, 0.001), 8.0);\n    float w = sin(uv.x * {i}.0 + u_time) * 0.5 + 0.5;\n    float a = mix(d, s, w);\n    float b = clamp(a * 1.5, 0.0, 1.0);\n    vec2 q = fract(uv * float({i} + 1));\n    float c = smoothstep(0.1, 0.9, q.x) * smoothstep(0.1, 0.9, q.y);\n    float e = exp(-length(q - 0.5) * 4.0);\n    float f = b * c + e * 0.25;\n    float g = f * f;\n    return g;\n}}\n\n"
        ));
    }
    s.push_str("void main() {\n    vec3 n = normalize(v_normal);\n    float total = 0.0;\n");
    for i in 0..62 {
        s.push_str(&format!("    total += shade{i}(n, v_uv);\n"));
    }
    s.push_str("    color = vec4(vec3(total / 62.0), 1.0);\n}\n");
    s
}

fn rediagnose(c: &mut Criterion) {
    let text = shader();
    assert!(
        text.lines().count() >= 1000,
        "{} lines",
        text.lines().count()
    );
    let (server, client) = Connection::memory();
    let thread = std::thread::spawn(move || essl_server::serve(&server));
    let init = Request::new(1.into(), "initialize".into(), json!({"capabilities": {}}));
    client.sender.send(Message::Request(init)).unwrap();
    let _ = client.receiver.recv().unwrap();
    let initialized = Notification::new("initialized".into(), json!({}));
    client
        .sender
        .send(Message::Notification(initialized))
        .unwrap();
    let uri = "file:///bench/big.frag";
    let open = Notification::new(
        "textDocument/didOpen".into(),
        json!({"textDocument": {"uri": uri, "languageId": "glsl", "version": 1, "text": text}}),
    );
    client.sender.send(Message::Notification(open)).unwrap();
    let _ = client.receiver.recv().unwrap();
    let mut version = 1;
    // One change: a constant in the last function (one character), then the two
    // `publishDiagnostics` it brings: the front end's, then with the lints. Returns the times to
    // the first and to the second.
    let mut change = || {
        version += 1;
        let changed = text.replace("total / 62.0", &format!("total / {}.0", 62 + version % 2));
        let change = Notification::new(
            "textDocument/didChange".into(),
            json!({"textDocument": {"uri": uri, "version": version}, "contentChanges": [{"text": changed}]}),
        );
        let start = Instant::now();
        client.sender.send(Message::Notification(change)).unwrap();
        black_box(client.receiver.recv().unwrap());
        let first = start.elapsed();
        black_box(client.receiver.recv().unwrap());
        (first, start.elapsed())
    };
    let mut group = c.benchmark_group("rediagnose 1000-line shader after a change");
    group.bench_function("front-end diagnostics published", |b| {
        b.iter_custom(|n| (0..n).map(|_| change().0).sum())
    });
    group.bench_function("lint findings published", |b| {
        b.iter_custom(|n| (0..n).map(|_| change().1).sum())
    });
    group.finish();
    let shutdown = Request::new(2.into(), "shutdown".into(), json!(null));
    client.sender.send(Message::Request(shutdown)).unwrap();
    let _ = client.receiver.recv();
    client
        .sender
        .send(Message::Notification(Notification::new(
            "exit".into(),
            json!(null),
        )))
        .unwrap();
    let _ = thread.join();
}

/// The parts: compiling (front end, lowering, naga's validation) and linting alone.
fn parts(c: &mut Criterion) {
    let text = shader();
    let file = essl::source::SourceFile::new("big.frag", text.as_str());
    let options = essl::CompileOptions::default();
    c.bench_function("compile 1000-line shader", |b| {
        b.iter(|| black_box(essl::compile(file.clone(), essl::Stage::Fragment, &options)))
    });
    c.bench_function("front end only (no lowering) 1000-line shader", |b| {
        use essl::passes::{check, classify, lex, parse, preprocess, PreprocessOptions};
        b.iter(|| {
            let pp = preprocess(&file, lex(&file), &PreprocessOptions::default());
            let mut diagnostics = pp.diagnostics;
            let tokens = classify(pp.tokens, &mut diagnostics);
            let (unit, _) = parse(&file, tokens, essl::Stage::Fragment);
            black_box(check(&file, &unit, essl::Stage::Fragment, pp.invariant_all))
        })
    });
    let shader = essl::compile(file, essl::Stage::Fragment, &options);
    let rules = essl_lint::LintOptions::new();
    c.bench_function("lint 1000-line shader", |b| {
        b.iter(|| black_box(essl_lint::lint(&shader, &rules)))
    });
}

criterion_group!(benches, rediagnose, parts);
criterion_main!(benches);
