//! The server end to end: the `essl-server` binary spoken to in JSON-RPC over its standard
//! input and output, as an editor speaks to it — initialize, open and change documents, the
//! diagnostics it publishes, and each request it answers.

use std::io::{BufRead, BufReader, Read, Write};
use std::path::Path;
use std::process::{Child, ChildStdin, ChildStdout, Command, Stdio};

use serde_json::{json, Value};

struct Client {
    child: Child,
    stdin: ChildStdin,
    stdout: BufReader<ChildStdout>,
    next_id: i64,
    /// Notifications read while waiting for something else.
    pending: Vec<Value>,
}

impl Client {
    fn start() -> Client {
        let mut child = Command::new(env!("CARGO_BIN_EXE_essl-server"))
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .expect("the server starts");
        let stdin = child.stdin.take().unwrap();
        let stdout = BufReader::new(child.stdout.take().unwrap());
        let mut c = Client {
            child,
            stdin,
            stdout,
            next_id: 1,
            pending: Vec::new(),
        };
        let caps = c.request(
            "initialize",
            json!({"capabilities": {}, "processId": null, "rootUri": null}),
        );
        assert_eq!(caps["capabilities"]["hoverProvider"], true, "{caps}");
        c.notify("initialized", json!({}));
        c
    }

    fn send(&mut self, msg: Value) {
        let body = msg.to_string();
        write!(self.stdin, "Content-Length: {}\r\n\r\n{body}", body.len()).unwrap();
        self.stdin.flush().unwrap();
    }

    fn read(&mut self) -> Value {
        let mut length = 0;
        loop {
            let mut line = String::new();
            assert!(
                self.stdout.read_line(&mut line).unwrap() > 0,
                "the server closed its output"
            );
            let line = line.trim_end();
            if line.is_empty() {
                break;
            }
            if let Some(n) = line.strip_prefix("Content-Length: ") {
                length = n.parse().unwrap();
            }
        }
        let mut body = vec![0; length];
        self.stdout.read_exact(&mut body).unwrap();
        serde_json::from_slice(&body).unwrap()
    }

    fn request(&mut self, method: &str, params: Value) -> Value {
        let id = self.next_id;
        self.next_id += 1;
        self.send(json!({"jsonrpc": "2.0", "id": id, "method": method, "params": params}));
        loop {
            let msg = self.read();
            if msg["id"] == id {
                assert!(msg.get("error").is_none(), "{msg}");
                return msg["result"].clone();
            }
            self.pending.push(msg);
        }
    }

    fn notify(&mut self, method: &str, params: Value) {
        self.send(json!({"jsonrpc": "2.0", "method": method, "params": params}));
    }

    /// The diagnostics last published for `uri` once the server has finished every check it
    /// has pending: a request is answered only after them (the server publishes a change's
    /// front-end diagnostics first and again with its lint findings).
    fn diagnostics(&mut self, uri: &str) -> Vec<Value> {
        self.request(
            "textDocument/documentSymbol",
            json!({"textDocument": {"uri": uri}}),
        );
        let is_mine = |m: &Value| {
            m["method"] == "textDocument/publishDiagnostics" && m["params"]["uri"] == uri
        };
        let mine: Vec<Value> = self
            .pending
            .iter()
            .filter(|m| is_mine(m))
            .cloned()
            .collect();
        self.pending.retain(|m| !is_mine(m));
        let last = mine
            .last()
            .unwrap_or_else(|| panic!("nothing published for {uri}"));
        last["params"]["diagnostics"].as_array().unwrap().clone()
    }

    /// The next diagnostics published for `uri`, without waiting for pending checks.
    fn next_diagnostics(&mut self, uri: &str) -> Vec<Value> {
        loop {
            let at = self.pending.iter().position(|m| {
                m["method"] == "textDocument/publishDiagnostics" && m["params"]["uri"] == uri
            });
            if let Some(i) = at {
                let msg = self.pending.remove(i);
                return msg["params"]["diagnostics"].as_array().unwrap().clone();
            }
            let msg = self.read();
            self.pending.push(msg);
        }
    }

    fn open(&mut self, uri: &str, text: &str) {
        self.notify(
            "textDocument/didOpen",
            json!({"textDocument": {"uri": uri, "languageId": "glsl", "version": 1, "text": text}}),
        );
    }

    /// Replaces the whole text of `uri`, as version `version`.
    fn change(&mut self, uri: &str, version: i32, text: &str) {
        self.notify(
            "textDocument/didChange",
            json!({"textDocument": {"uri": uri, "version": version}, "contentChanges": [{"text": text}]}),
        );
    }

    fn at(&mut self, method: &str, uri: &str, line: u32, character: u32) -> Value {
        let mut params = json!({
            "textDocument": {"uri": uri},
            "position": {"line": line, "character": character},
        });
        if method == "textDocument/references" {
            params["context"] = json!({"includeDeclaration": true});
        }
        self.request(method, params)
    }

    fn shutdown(mut self) {
        self.request("shutdown", Value::Null);
        self.notify("exit", Value::Null);
        let status = self.child.wait().unwrap();
        assert!(status.success(), "{status}");
    }
}

fn uri(path: &Path) -> String {
    format!("file://{}", path.display())
}

const BROKEN: &str = "#version 300 es
precision highp float;
uniform vec3 u_light
in vec3 v_normal;
out vec4 color;
void main() {
    vec3 n = normalize(v_normal);
    float d = dot(n, u_light);
    color = vec4(pow(d, 2.5));
}
";

#[test]
fn diagnostics_and_fixes() {
    let dir = tempfile::tempdir().unwrap();
    let a = uri(&dir.path().join("a.frag"));
    let mut c = Client::start();
    c.open(&a, BROKEN);
    let ds = c.diagnostics(&a);
    assert_eq!(ds.len(), 1, "{ds:#?}");
    assert_eq!(ds[0]["code"], "missing-semicolon");
    assert_eq!(ds[0]["source"], "essl");
    assert_eq!(ds[0]["range"]["start"], json!({"line": 2, "character": 20}));
    assert!(
        ds[0]["message"].as_str().unwrap().contains("\nhelp: "),
        "{}",
        ds[0]
    );
    let actions = c.request(
        "textDocument/codeAction",
        json!({"textDocument": {"uri": a}, "range": ds[0]["range"], "context": {"diagnostics": []}}),
    );
    let fix = &actions[0];
    assert_eq!(fix["kind"], "quickfix");
    assert_eq!(fix["isPreferred"], true);
    let edit = &fix["edit"]["changes"][&a][0];
    assert_eq!(edit["newText"], ";");
    assert_eq!(edit["range"]["start"], json!({"line": 2, "character": 20}));

    // Fixed: the lint finding (`pow` of a base that may be negative) remains, with an
    // "allow this rule here" action that comments the line before.
    let fixed = BROKEN.replace("u_light\n", "u_light;\n");
    c.change(&a, 2, &fixed);
    let ds = c.diagnostics(&a);
    let pow = ds
        .iter()
        .find(|d| d["code"] == "pow-negative-base")
        .expect("a pow finding");
    let actions = c.request(
        "textDocument/codeAction",
        json!({"textDocument": {"uri": a}, "range": pow["range"], "context": {"diagnostics": []}}),
    );
    let allow = actions
        .as_array()
        .unwrap()
        .iter()
        .find(|x| {
            x["title"]
                .as_str()
                .unwrap()
                .starts_with("allow `pow-negative-base`")
        })
        .expect("an allow action");
    let edit = &allow["edit"]["changes"][&a][0];
    assert_eq!(edit["newText"], "    // essl-allow: pow-negative-base\n");
    assert_eq!(edit["range"]["start"], json!({"line": 8, "character": 0}));
    c.shutdown();
}

#[test]
fn hover_definition_references_symbols_completion() {
    let dir = tempfile::tempdir().unwrap();
    let a = uri(&dir.path().join("a.frag"));
    let text = BROKEN.replace("u_light\n", "u_light;\n");
    let mut c = Client::start();
    c.open(&a, &text);
    c.diagnostics(&a);
    // `u_light` used on line 7 (0-based), column 21.
    let h = c.at("textDocument/hover", &a, 7, 22);
    assert_eq!(
        h["contents"]["value"], "```glsl\nuniform highp vec3 u_light\n```",
        "{h}"
    );
    let h = c.at("textDocument/hover", &a, 6, 14);
    let value = h["contents"]["value"].as_str().unwrap();
    assert!(value.contains("vec3 normalize(vec3)"), "{value}");
    assert!(value.contains("length 1"), "{value}");
    // `n` used on line 7 → declared on line 6.
    let def = c.at("textDocument/definition", &a, 7, 18);
    assert_eq!(
        def["range"]["start"],
        json!({"line": 6, "character": 9}),
        "{def}"
    );
    let refs = c.at("textDocument/references", &a, 6, 9);
    assert_eq!(refs.as_array().unwrap().len(), 2, "{refs}");
    let symbols = c.request(
        "textDocument/documentSymbol",
        json!({"textDocument": {"uri": a}}),
    );
    let names: Vec<&str> = symbols
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["name"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["u_light", "v_normal", "color", "main"]);
    let items = c.at("textDocument/completion", &a, 8, 4);
    let labels: Vec<&str> = items
        .as_array()
        .unwrap()
        .iter()
        .map(|i| i["label"].as_str().unwrap())
        .collect();
    for expected in [
        "n",
        "d",
        "u_light",
        "normalize",
        "smoothstep",
        "gl_FragCoord",
        "vec3",
    ] {
        assert!(labels.contains(&expected), "{expected} missing: {labels:?}");
    }
    c.shutdown();
}

#[test]
fn programs_put_link_errors_on_the_right_file() {
    let dir = tempfile::tempdir().unwrap();
    let vert = dir.path().join("light.vert");
    std::fs::write(
        &vert,
        "#version 300 es\nin vec4 p;\nout vec3 v_normal;\nvoid main() { v_normal = p.xyz; gl_Position = p; }\n",
    )
    .unwrap();
    let frag = uri(&dir.path().join("light.frag"));
    let text = "#version 300 es\nprecision highp float;\nin vec3 v_normal;\nin vec2 v_uv;\nout vec4 c;\nvoid main() { c = vec4(v_normal, v_uv.x); }\n";
    let mut c = Client::start();
    c.open(&frag, text);
    let ds = c.diagnostics(&frag);
    let link = ds
        .iter()
        .find(|d| d["code"] == "varying-not-written")
        .expect("a link error");
    assert_eq!(link["range"]["start"]["line"], 3, "{link}");
    assert!(
        link["message"].as_str().unwrap().starts_with("program: "),
        "{link}"
    );
    // The vertex shader, not open, is published too: clean.
    assert!(c.diagnostics(&uri(&vert)).is_empty());
    c.shutdown();
}

/// A change is published twice: first the front end's diagnostics with the previous lint
/// findings that lie outside the edit (moved with it), then with the lints of the new text.
#[test]
fn a_change_publishes_the_front_end_first_and_keeps_lints_outside_the_edit() {
    let dir = tempfile::tempdir().unwrap();
    let a = uri(&dir.path().join("a.frag"));
    let text = BROKEN.replace("u_light\n", "u_light;\n");
    let mut c = Client::start();
    c.open(&a, &text);
    let pow_line = |ds: &[Value]| -> Vec<Value> {
        ds.iter()
            .filter(|d| d["code"] == "pow-negative-base")
            .map(|d| d["range"]["start"]["line"].clone())
            .collect()
    };
    assert_eq!(pow_line(&c.diagnostics(&a)), [json!(8)]);
    // A line added above: the finding moves down with its text before the lints run again.
    let moved = text.replace(
        "out vec4 color;\n",
        "out vec4 color;\nconst float k = 2.0;\n",
    );
    c.change(&a, 2, &moved);
    assert_eq!(pow_line(&c.next_diagnostics(&a)), [json!(9)]);
    assert_eq!(pow_line(&c.diagnostics(&a)), [json!(9)]);
    // An edit of the finding's own line drops it until the lints have run on the new text.
    let edited = moved.replace("pow(d, 2.5)", "pow(0.5 - d * 2.0, 2.5)");
    c.change(&a, 3, &edited);
    assert!(pow_line(&c.next_diagnostics(&a)).is_empty());
    assert_eq!(pow_line(&c.diagnostics(&a)), [json!(9)]);
    // A syntax error: the front end's error alone, no lint findings carried.
    let broken = edited.replace(
        "vec3 n = normalize(v_normal);",
        "vec3 n = normalize(v_normal)",
    );
    c.change(&a, 4, &broken);
    let ds = c.diagnostics(&a);
    assert_eq!(ds.len(), 1, "{ds:#?}");
    assert_eq!(ds[0]["code"], "missing-semicolon");
    c.shutdown();
}

/// Shaders inside an HTML page: each checked on its own text, diagnostics and fixes on the
/// page's lines, hover at page positions, the two shaders linked, and a template literal
/// with `${…}` reported as not checked.
#[test]
fn shaders_inside_html_and_js() {
    let dir = tempfile::tempdir().unwrap();
    let page = uri(&dir.path().join("page.html"));
    let html = "<!doctype html>\n<canvas></canvas>\n\
<script id=\"vertex-shader-3d\" type=\"x-shader/x-vertex\">#version 300 es\n\
in vec4 a_position;\n\
out vec3 v_normal;\n\
void main() { v_normal = a_position.xyz; gl_Position = a_position; }\n\
</script>\n\
<script id=\"fragment-shader-3d\" type=\"x-shader/x-fragment\">#version 300 es\n\
precision highp float;\n\
in vec3 v_normal;\n\
in vec2 v_uv;\n\
out vec4 outColor;\n\
void main() {\n\
  float k = 1.0\n\
  outColor = vec4(v_normal * k, v_uv.x);\n\
}\n\
</script>\n";
    let mut c = Client::start();
    c.open(&page, html);
    let ds = c.diagnostics(&page);
    let semi = ds
        .iter()
        .find(|d| d["code"] == "missing-semicolon")
        .unwrap_or_else(|| panic!("{ds:#?}"));
    // `float k = 1.0` is on the page's line 13 (0-based), the `;` goes after its 13 columns.
    assert_eq!(semi["range"]["start"], json!({"line": 13, "character": 13}));
    let actions = c.request(
        "textDocument/codeAction",
        json!({"textDocument": {"uri": page}, "range": semi["range"], "context": {"diagnostics": []}}),
    );
    let edit = &actions[0]["edit"]["changes"][&page][0];
    assert_eq!(edit["newText"], ";");
    assert_eq!(edit["range"]["start"], json!({"line": 13, "character": 13}));
    // Fixed: the fragment shader reads `v_uv`, which the vertex shader does not write.
    let fixed = html.replace("float k = 1.0\n", "float k = 1.0;\n");
    c.change(&page, 2, &fixed);
    let ds = c.diagnostics(&page);
    let link = ds
        .iter()
        .find(|d| d["code"] == "varying-not-written")
        .unwrap_or_else(|| panic!("{ds:#?}"));
    assert_eq!(link["range"]["start"]["line"], 10, "{link}");
    assert!(link["message"].as_str().unwrap().starts_with("program: "));
    // Hover on `a_position` in the vertex shader's `main` (page line 5, column 27).
    let h = c.at("textDocument/hover", &page, 5, 27);
    assert_eq!(
        h["contents"]["value"], "```glsl\nin highp vec4 a_position\n```",
        "{h}"
    );
    // Outside every shader, nothing.
    assert_eq!(c.at("textDocument/hover", &page, 1, 3), Value::Null);

    // A constant's value is put in: the error after `${n}` is on the script's own column.
    let script = uri(&dir.path().join("app.js"));
    let js = "const n = 4;\nconst fs = `#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() { c = vec4(${n}) }\n`;\n";
    c.open(&script, js);
    let ds = c.diagnostics(&script);
    assert_eq!(ds.len(), 1, "{ds:#?}");
    assert_eq!(ds[0]["code"], "missing-semicolon");
    assert_eq!(ds[0]["range"]["start"], json!({"line": 4, "character": 28}));
    // A value known only at run time leaves the shader unchecked, and says so.
    let other = uri(&dir.path().join("run.js"));
    let js = "const fs = `#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() { c = vec4(${count()}); }\n`;\n";
    c.open(&other, js);
    let ds = c.diagnostics(&other);
    assert_eq!(ds.len(), 1, "{ds:#?}");
    assert_eq!(ds[0]["code"], "not-checked");
    assert_eq!(ds[0]["range"]["start"]["line"], 0);
    assert!(ds[0]["message"].as_str().unwrap().contains("run"));
    c.shutdown();
}
