//! The `luma` preset's preparation: the program objects of every JS/TS host a `luma` setting
//! covers, assembled in one run of luma.gl per project (`luma.mjs`), and wrapped around the
//! author's literals.

use std::path::{Path, PathBuf};

use serde_json::{json, Value};

use super::programs::{self, Literal, LocalModule, ModuleRef, Program};
use super::{key, node, Assembled, Prepared, Preset, PresetError, Wrap};
use crate::find::Found;
use crate::imports::DiskImports;
use crate::settings::Configs;

/// The script that assembles in Node.js.
const SCRIPT: &str = include_str!("luma.mjs");

/// The package the preset reads.
const PACKAGE: &str = "@luma.gl/shadertools";

/// A fragment shader to pair with a lone vertex shader (and the other way round): luma.gl
/// assembles pairs.
const LONE_FS: &str = "#version 300 es\nout vec4 essl_c;\nvoid main() { essl_c = vec4(0.0); }";
const LONE_VS: &str = "#version 300 es\nvoid main() { gl_Position = vec4(0.0); }";

/// What one request asks: a program, or a lone shader of a host.
enum Asked {
    Program(PathBuf, Program),
    Lone(PathBuf, Literal, essl::Stage),
}

/// Prepares the `luma` preset for every host of `found` whose settings name it.
pub fn prepare(found: &Found, configs: &Configs) -> Prepared {
    let mut prepared = Prepared::default();
    let projects = node::projects(found, configs, Preset::Luma, PACKAGE, &mut prepared);
    for (root, hosts) in projects {
        project(found, &root, &hosts, &mut prepared);
    }
    prepared
}

/// Prepares the hosts `hosts` of the project at `root`.
fn project(found: &Found, root: &Path, hosts: &[usize], prepared: &mut Prepared) {
    let imports = DiskImports::new(root);
    for &h in hosts {
        let host = &found.hosts[h];
        imports.add(&host.path, host.file.clone());
    }
    let mut asked: Vec<Asked> = Vec::new();
    for &h in hosts {
        let host = &found.hosts[h];
        let Some(script) = imports.script(&host.path) else {
            continue;
        };
        for p in programs::programs(&script, &imports) {
            for lit in [&p.vs, &p.fs].into_iter().flatten() {
                prepared
                    .claimed
                    .insert((key(std::path::Path::new(lit.file.name())), lit.at));
            }
            asked.push(Asked::Program(key(&host.path), p));
        }
    }
    for &h in hosts {
        let host = &found.hosts[h];
        let k = key(&host.path);
        for e in &host.embedded {
            let (Some(stage), None, false) = (e.stage, e.skip, e.chunk) else {
                continue;
            };
            if prepared.claimed.contains(&(k.clone(), e.literal)) {
                continue;
            }
            let text = crate::extract::text_of(host.file.text(), &e.pieces);
            let literal = Literal {
                file: host.file.clone(),
                at: e.literal,
                pieces: e.pieces.clone(),
                text,
            };
            asked.push(Asked::Lone(k.clone(), literal, stage));
        }
    }
    if asked.is_empty() {
        return;
    }
    let request = json!({ "programs": asked.iter().enumerate().map(|(id, a)| request(id, a)).collect::<Vec<_>>() });
    let answer = match node::run(SCRIPT, root, &request) {
        Ok(a) => a,
        Err(e) => {
            for &h in hosts {
                prepared.failed.insert(key(&found.hosts[h].path), e.clone());
            }
            return;
        }
    };
    if let Some(e) = answer.get("error").and_then(Value::as_str) {
        for &h in hosts {
            let err = PresetError::Script(e.to_string());
            prepared.failed.insert(key(&found.hosts[h].path), err);
        }
        return;
    }
    let results = answer["programs"].as_array().cloned().unwrap_or_default();
    for (a, r) in asked.into_iter().zip(results) {
        take(a, &r, prepared);
    }
}

/// A request's JSON.
fn request(id: usize, a: &Asked) -> Value {
    match a {
        Asked::Program(_, p) => json!({
            "id": id,
            "deck": p.deck,
            "vs": p.vs.as_ref().map_or(LONE_VS, |l| l.text.as_str()),
            "fs": p.fs.as_ref().map_or(LONE_FS, |l| l.text.as_str()),
            "defines": defines(&p.defines),
            "modules": p.modules.iter().map(module).collect::<Vec<_>>(),
        }),
        Asked::Lone(_, l, stage) => {
            let (vs, fs) = match stage {
                essl::Stage::Vertex => (l.text.as_str(), LONE_FS),
                essl::Stage::Fragment => (LONE_VS, l.text.as_str()),
            };
            json!({ "id": id, "deck": false, "vs": vs, "fs": fs, "defines": {}, "modules": [] })
        }
    }
}

fn defines(list: &[(String, String)]) -> Value {
    Value::Object(
        list.iter()
            .map(|(k, v)| {
                let value = match v.as_str() {
                    "true" => Value::Bool(true),
                    "false" => Value::Bool(false),
                    other => Value::String(other.to_string()),
                };
                (k.clone(), value)
            })
            .collect(),
    )
}

fn module(m: &ModuleRef) -> Value {
    match m {
        ModuleRef::Package { package, export } => json!({ "package": package, "export": export }),
        ModuleRef::Local(l) => json!({ "local": local(l) }),
    }
}

fn local(l: &LocalModule) -> Value {
    json!({
        "name": l.name,
        "vs": l.vs.as_ref().map(|x| x.text.clone()),
        "fs": l.fs.as_ref().map(|x| x.text.clone()),
        "defines": defines(&l.defines),
        "dependencies": l.dependencies.iter().map(module).collect::<Vec<_>>(),
    })
}

/// The project's own module texts a program's stage holds (its modules' and their
/// dependencies').
fn locals(modules: &[ModuleRef], vertex: bool, out: &mut Vec<Literal>) {
    for m in modules {
        if let ModuleRef::Local(l) = m {
            locals(&l.dependencies, vertex, out);
            let text = if vertex { &l.vs } else { &l.fs };
            out.extend(text.iter().cloned());
        }
    }
}

/// Records what Node.js answered for one request.
fn take(a: Asked, r: &Value, prepared: &mut Prepared) {
    let error = r.get("error").and_then(Value::as_str).map(str::to_string);
    let text = |stage: &str| {
        r.get(stage)
            .and_then(Value::as_str)
            .unwrap_or("")
            .to_string()
    };
    match a {
        Asked::Program(host, p) => {
            let wrap = |lit: &Option<Literal>, stage: &str, vertex: bool| {
                let lit = lit.clone()?;
                let mut l = Vec::new();
                locals(&p.modules, vertex, &mut l);
                Wrap::new(lit, &text(stage), true, l)
            };
            let mut error = error;
            if error.is_none() && !p.unknown.is_empty() {
                error = Some(format!(
                    "essl cannot follow the module{} `{}` (not a package's export or a module \
                     object of literals in the project)",
                    if p.unknown.len() == 1 { "" } else { "s" },
                    p.unknown.join("`, `")
                ));
            }
            let assembled = Assembled {
                object: p.object,
                vs: error.is_none().then(|| wrap(&p.vs, "vs", true)).flatten(),
                fs: error.is_none().then(|| wrap(&p.fs, "fs", false)).flatten(),
                error: error.map(|e| format!("luma.gl cannot assemble this program: {e}")),
                unchecked: None,
                problems: Vec::new(),
            };
            prepared.programs.entry(host).or_default().push(assembled);
        }
        Asked::Lone(host, l, stage) => {
            let which = match stage {
                essl::Stage::Vertex => "vs",
                essl::Stage::Fragment => "fs",
            };
            let at = l.at;
            if let Some(w) = error
                .is_none()
                .then(|| Wrap::new(l, &text(which), true, Vec::new()))
                .flatten()
            {
                prepared.lone.insert((host, at), w);
            }
        }
    }
}
