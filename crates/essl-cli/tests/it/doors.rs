//! One pipeline behind every front door: `essl lint`, the build-script checker (`essl-build`)
//! and the editor server (`essl-server`) report the same errors and warnings, at the same
//! files, lines and columns, for one project folder holding shader files, a linked pair, a
//! program that does not link, `#include`s (with an error inside an included file), an HTML
//! page and a JS module.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;

use lsp_server::{Connection, Message, Notification, Request, RequestId};
use serde_json::{json, Value};

/// `FILE:LINE:COL severity[code]`, the file relative to the project.
type Found = BTreeSet<String>;

fn project() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let files: &[(&str, &str)] = &[
        ("essl.toml", "include = [\"shaders/common\"]\n"),
        (
            "shaders/common/light.glsl",
            "float light(float d) {\n    return clamp(d, 0.0, 1.0);\n}\n",
        ),
        (
            "shaders/common/broken.glsl",
            "float broken(float d) {\n    return d * missing;\n}\n",
        ),
        (
            "shaders/lit.vert",
            "#version 300 es\nin vec4 a_position;\nout float v_d;\nvoid main() {\n    v_d = a_position.x;\n    gl_Position = a_position;\n}\n",
        ),
        (
            "shaders/lit.frag",
            "#version 300 es\nprecision highp float;\n#include \"light.glsl\"\nin float v_d;\nuniform vec3 u_l;\nout vec4 color;\nvoid main() {\n    float d = dot(normalize(vec3(v_d)), u_l);\n    color = vec4(pow(d, 2.5) * light(v_d));\n}\n",
        ),
        (
            "shaders/mismatch.vert",
            "#version 300 es\nout vec2 v_uv;\nvoid main() {\n    v_uv = vec2(0.0);\n    gl_Position = vec4(0.0);\n}\n",
        ),
        (
            "shaders/mismatch.frag",
            "#version 300 es\nprecision highp float;\nin vec3 v_uv;\nout vec4 color;\nvoid main() {\n    color = vec4(v_uv, 1.0);\n}\n",
        ),
        (
            "shaders/broken.frag",
            "#version 300 es\nprecision highp float;\n#include \"broken.glsl\"\nout vec4 color;\nvoid main() {\n    color = vec4(broken(1.0))\n}\n",
        ),
        (
            "page.html",
            "<html><body>\n<script id=\"vs\" type=\"x-shader/x-vertex\">#version 300 es\nin vec4 p;\nvoid main() { gl_Position = p; }\n</script>\n<script id=\"fs\" type=\"x-shader/x-fragment\">#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() { c = vec4(normalise(vec3(1.0)), 1.0); }\n</script>\n</body></html>\n",
        ),
        (
            "app.js",
            "import x from './x.js';\nexport const fs = `#version 300 es\nprecision highp float;\nuniform vec3 u_a;\nuniform vec3 u_b;\nout vec4 c;\nvoid main() {\n  c = vec4(acos(dot(u_a, u_b)) + 1.0) \n}`;\n",
        ),
    ];
    for (path, text) in files {
        let path = dir.path().join(path);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, text).unwrap();
    }
    dir
}

fn relative(root: &Path, file: &str) -> String {
    let p = Path::new(file);
    let real = std::fs::canonicalize(p).unwrap_or_else(|_| p.to_path_buf());
    let root = std::fs::canonicalize(root).unwrap();
    real.strip_prefix(&root)
        .map_or(file.to_string(), |r| r.display().to_string())
}

/// `essl lint --format json DIR`.
fn cli(root: &Path) -> Found {
    let o = Command::new(env!("CARGO_BIN_EXE_essl"))
        .args(["lint", "--format", "json"])
        .arg(root)
        .output()
        .unwrap();
    let mut found = Found::new();
    for line in String::from_utf8(o.stdout).unwrap().lines() {
        let v: Value = serde_json::from_str(line).unwrap();
        let own = v["file"].as_str().unwrap_or_default().to_string();
        for d in v["diagnostics"].as_array().into_iter().flatten() {
            let severity = d["severity"].as_str().unwrap();
            if severity == "note" {
                continue;
            }
            let file = d["file"].as_str().map_or(own.clone(), str::to_string);
            found.insert(format!(
                "{}:{}:{} {severity}[{}]",
                relative(root, &file),
                d["line"],
                d["column"],
                d["code"].as_str().unwrap()
            ));
        }
    }
    found
}

/// `essl_build::check(DIR)`, from its Cargo warning lines.
fn build(root: &Path) -> Found {
    let (mut cargo, mut human) = (Vec::new(), Vec::new());
    let result = essl_build::Check::new(root).run_with(&mut cargo, &mut human);
    assert!(result.is_err(), "the project has errors");
    let mut found = Found::new();
    for line in String::from_utf8(cargo).unwrap().lines() {
        let Some(rest) = line.strip_prefix("cargo:warning=") else {
            continue;
        };
        // FILE:LINE:COL: severity[code]: message
        let Some((at, rest)) = rest.split_once(": ") else {
            continue;
        };
        let Some((severity, _)) = rest.split_once(": ") else {
            continue;
        };
        let mut parts = at.rsplitn(3, ':');
        let (col, line_no, file) = (parts.next(), parts.next(), parts.next());
        let (Some(col), Some(line_no), Some(file)) = (col, line_no, file) else {
            continue;
        };
        found.insert(format!(
            "{}:{line_no}:{col} {severity}",
            relative(root, file)
        ));
    }
    found
}

/// The server, sent every file of the project as an editor opening it would.
fn server(root: &Path) -> Found {
    let (client, server) = Connection::memory();
    let thread = std::thread::spawn(move || essl_server::serve(&server));
    let send = |m: Message| client.sender.send(m).unwrap();
    send(Message::Request(Request::new(
        RequestId::from(1),
        "initialize".into(),
        json!({"capabilities": {}, "processId": null, "rootUri": null}),
    )));
    let _ = client.receiver.recv().unwrap();
    send(Message::Notification(Notification::new(
        "initialized".into(),
        json!({}),
    )));
    let mut paths: Vec<PathBuf> = Vec::new();
    for entry in walk(root) {
        let ext = entry.extension().and_then(|e| e.to_str()).unwrap_or("");
        if ["vert", "frag", "html", "js", "ts"].contains(&ext) && !p_in_modules(&entry) {
            paths.push(entry);
        }
    }
    for path in &paths {
        let text = std::fs::read_to_string(path).unwrap();
        send(Message::Notification(Notification::new(
            "textDocument/didOpen".into(),
            json!({"textDocument": {"uri": uri(path), "languageId": "glsl", "version": 1, "text": text}}),
        )));
    }
    // A request is answered once every change is checked and linted.
    send(Message::Request(Request::new(
        RequestId::from(2),
        "textDocument/documentSymbol".into(),
        json!({"textDocument": {"uri": uri(&paths[0])}}),
    )));
    let mut latest: std::collections::HashMap<String, Vec<Value>> = Default::default();
    loop {
        match client.receiver.recv().unwrap() {
            Message::Notification(n) if n.method == "textDocument/publishDiagnostics" => {
                let uri = n.params["uri"].as_str().unwrap().to_string();
                latest.insert(uri, n.params["diagnostics"].as_array().unwrap().clone());
            }
            Message::Response(r) if r.id == RequestId::from(2) => break,
            _ => {}
        }
    }
    send(Message::Request(Request::new(
        RequestId::from(3),
        "shutdown".into(),
        json!(null),
    )));
    send(Message::Notification(Notification::new(
        "exit".into(),
        json!(null),
    )));
    drop(client);
    let _ = thread.join();
    let mut found = Found::new();
    for (u, ds) in latest {
        let own = u.strip_prefix("file://").unwrap().to_string();
        for d in ds {
            let severity = match d["severity"].as_i64() {
                Some(1) => "error",
                Some(2) => "warning",
                _ => continue,
            };
            let message = d["message"].as_str().unwrap();
            // A diagnostic in an included file is shown on the shader, naming its place.
            let (file, line, col) = match message.strip_prefix("in ").and_then(|m| {
                let at = m.split(": ").next()?;
                let mut parts = at.rsplitn(3, ':');
                let c = parts.next()?.parse::<u64>().ok()?;
                let l = parts.next()?.parse::<u64>().ok()?;
                Some((parts.next()?.to_string(), l, c))
            }) {
                Some(x) => x,
                None => {
                    let start = &d["range"]["start"];
                    (
                        own.clone(),
                        start["line"].as_u64().unwrap() + 1,
                        start["character"].as_u64().unwrap() + 1,
                    )
                }
            };
            found.insert(format!(
                "{}:{line}:{col} {severity}[{}]",
                relative(root, &file),
                d["code"].as_str().unwrap()
            ));
        }
    }
    found
}

fn uri(path: &Path) -> String {
    format!("file://{}", std::fs::canonicalize(path).unwrap().display())
}

fn p_in_modules(p: &Path) -> bool {
    p.components().any(|c| c.as_os_str() == "node_modules")
}

fn walk(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_symlink() {
            continue;
        }
        if p.is_dir() {
            out.extend(walk(&p));
        } else {
            out.push(p);
        }
    }
    out.sort();
    out
}

#[test]
fn the_cli_the_build_script_and_the_server_agree() {
    let dir = project();
    let root = dir.path();
    let cli = cli(root);
    let expected: Found = [
        "app.js:8:38 error[missing-semicolon]",
        "page.html:9:24 error[undeclared-function]",
        "shaders/broken.frag:6:30 error[missing-semicolon]",
        "shaders/common/broken.glsl:2:16 error[undeclared-identifier]",
        "shaders/lit.frag:9:22 warning[pow-negative-base]",
        "shaders/mismatch.frag:3:9 error[varying-type-mismatch]",
    ]
    .into_iter()
    .map(String::from)
    .collect();
    assert_eq!(cli, expected, "essl lint");
    assert_eq!(build(root), cli, "essl-build");
    assert_eq!(server(root), cli, "essl-server");
}

#[test]
fn they_agree_on_a_deck_gl_layer_with_the_luma_preset() {
    let Some(js) = essl_testdata::js_libraries() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    std::os::unix::fs::symlink(js.join("node_modules"), root.join("node_modules")).unwrap();
    std::fs::write(root.join("essl.toml"), "preset = \"luma\"\n").unwrap();
    let from = js.join("node_modules/@deck.gl/layers/src/scatterplot-layer");
    let to = root.join("scatterplot-layer");
    std::fs::create_dir_all(&to).unwrap();
    for entry in std::fs::read_dir(&from).unwrap() {
        let path = entry.unwrap().path();
        std::fs::copy(&path, to.join(path.file_name().unwrap())).unwrap();
    }
    let fragment = to.join("scatterplot-layer-fragment.glsl.ts");
    let text = std::fs::read_to_string(&fragment).unwrap();
    std::fs::write(
        &fragment,
        text.replacen("void main(void) {", "void main(void) {\n  float x = 1.0", 1),
    )
    .unwrap();
    let cli = cli(root);
    assert_eq!(cli.len(), 1, "{cli:?}");
    assert!(
        cli.iter()
            .next()
            .unwrap()
            .starts_with("scatterplot-layer/scatterplot-layer-fragment.glsl.ts:"),
        "{cli:?}"
    );
    assert_eq!(build(root), cli, "essl-build");
    assert_eq!(server(root), cli, "essl-server");
}
