//! The `three` preset: a three.js material's shaders — an object with `vertexShader` and
//! `fragmentShader` keys, given to `new ShaderMaterial(…)` or kept for one (`CopyShader`), or to
//! `new RawShaderMaterial(…)` — checked as three.js's `WebGLProgram` builds them in a WebGL2
//! context: its prelude before the author's text (the `#version`, precision, the built-in
//! uniforms and attributes, the material's `defines`; for a `RawShaderMaterial` only the
//! defines), and each `#include <chunk>` line replaced by the chunk as three.js expands it.
//! Both come from the three.js the project has installed (`three.mjs`, run once per project in
//! Node.js); the prelude is that of a mesh with normals, opaque, no tone mapping, sRGB output.

use std::collections::HashSet;
use std::path::{Path, PathBuf};
use std::rc::Rc;

use essl::diagnostic::{Diagnostic, Fix, Severity};
use essl::source::Span;
use serde_json::{json, Value};

use super::programs::{self, Literal};
use super::{key, node, Assembled, Prepared, Preset, Wrap};
use crate::check::from_pieces;
use crate::codes::CheckCode;
use crate::extract::js::objects;
use crate::find::Found;
use crate::imports::{DiskImports, Script};
use crate::settings::Configs;

const SCRIPT: &str = include_str!("three.mjs");
const PACKAGE: &str = "three";

/// A material the project's code makes, or an object kept for one (`CopyShader`).
struct Material {
    host: PathBuf,
    object: usize,
    /// Whether the object is given to a material's constructor.
    usage: bool,
    raw: bool,
    glsl3: bool,
    /// Whether its script draws instances (`InstancedMesh`): three.js then adds
    /// `instanceMatrix`.
    instanced: bool,
    defines: Vec<(String, String)>,
    /// Why the program is not checked: a value it needs is known only when the script runs.
    unknown: Option<String>,
    /// Whether a shader value is written in the object itself (a string, a join of strings,
    /// a `ShaderChunk` entry) rather than passed through a name, so that an object kept for
    /// a material is a shader even when its value is made when the script runs.
    written: bool,
    vertex: Option<Literal>,
    fragment: Option<Literal>,
}

impl Material {
    /// Its literals, as (file, start).
    fn literals(&self) -> impl Iterator<Item = (String, usize)> + '_ {
        [&self.vertex, &self.fragment]
            .into_iter()
            .flatten()
            .map(|l| (l.file.name().to_string(), l.at))
    }

    /// What makes two materials the same program.
    fn signature(&self) -> String {
        let at = |l: &Option<Literal>| l.as_ref().map(|l| (l.file.name().to_string(), l.at));
        let alone = self
            .literals()
            .next()
            .is_none()
            .then_some((&self.host, self.object));
        format!(
            "{alone:?} {:?} {:?} {} {} {} {:?}",
            at(&self.vertex),
            at(&self.fragment),
            self.raw,
            self.glsl3,
            self.instanced,
            self.defines
        )
    }
}

/// Whether a vertex shader kept for a material (no constructor in sight) declares what
/// three.js's `ShaderMaterial` prelude declares: it is then written for a `RawShaderMaterial`
/// (a `ShaderMaterial` would fail to compile with the name declared twice).
fn declares_prelude(vertex: &str) -> bool {
    static DECLARES: std::sync::OnceLock<regex::Regex> = std::sync::OnceLock::new();
    DECLARES
        .get_or_init(|| {
            regex::Regex::new(
                r"(?m)^\s*(?:attribute|in)\s+vec3\s+position\s*;|^\s*uniform\s+mat4\s+(?:modelViewMatrix|projectionMatrix)\s*;",
            )
            .expect("a valid pattern")
        })
        .is_match(vertex)
}

/// The names a script replaces in strings (`.replace( /DEPTH_TO_VIEW_Z/g, … )`,
/// `.replaceAll('NAME', …)`): a shader that holds one is rewritten before it is compiled.
fn replaced_names(text: &str) -> Vec<String> {
    static REPLACE: std::sync::OnceLock<regex::Regex> = std::sync::OnceLock::new();
    let re = REPLACE.get_or_init(|| {
        regex::Regex::new(r#"\.replace(?:All)?\(\s*(?:/(\w+)/g?|'(\w+)'|"(\w+)")"#)
            .expect("a valid pattern")
    });
    re.captures_iter(text)
        .filter_map(|c| {
            c.iter()
                .skip(1)
                .flatten()
                .next()
                .map(|m| m.as_str().to_string())
        })
        .collect()
}

/// The materials of a script.
fn materials(script: &Rc<Script>, imports: &DiskImports) -> Vec<Material> {
    let text = script.file.text();
    let replaced = replaced_names(text);
    let instanced = text.contains("InstancedMesh");
    objects::objects_with(text, &["vertexShader", "fragmentShader"])
        .into_iter()
        .map(|o| {
            let shader = |k: &str| programs::shader_value(script, o.get(k)?, imports);
            let (vertex, fragment) = (shader("vertexShader"), shader("fragmentShader"));
            let usage = o.callee.ends_with("ShaderMaterial");
            let raw = match usage {
                true => o.callee.ends_with("RawShaderMaterial"),
                false => vertex.as_ref().is_some_and(|v| declares_prelude(&v.text)),
            };
            let glsl3 = o.get("glslVersion").is_some_and(|r| {
                let v = &text[r];
                v.contains("GLSL3") || v.contains("300 es")
            });
            let written = ["vertexShader", "fragmentShader"].iter().any(|k| {
                o.get(k).is_some_and(|r| {
                    let v = &text[r];
                    v.contains(['\'', '"', '`']) || v.contains("ShaderChunk")
                })
            });
            let mut unknown = None;
            let mut defines = Vec::new();
            if let Some(r) = o.get("defines") {
                match programs::define_values(script, r.clone(), imports) {
                    Some(values) => {
                        for (k, v) in values {
                            match v {
                                Some(v) => defines.push((k, v)),
                                None => {
                                    unknown.get_or_insert(format!(
                                        "`defines.{k}` is set when the script runs"
                                    ));
                                }
                            }
                        }
                    }
                    None => {
                        unknown = Some(format!(
                            "its `defines` (`{}`) are made when the script runs",
                            short(&text[r])
                        ));
                    }
                }
            }
            for (k, lit) in [("vertexShader", &vertex), ("fragmentShader", &fragment)] {
                if let (None, Some(r)) = (lit, o.get(k)) {
                    unknown.get_or_insert(format!(
                        "its `{k}` (`{}`) is made when the script runs",
                        short(&text[r])
                    ));
                }
            }
            for lit in [&vertex, &fragment].into_iter().flatten() {
                if let Some(n) = replaced.iter().find(|n| word_in(&lit.text, n)) {
                    unknown.get_or_insert(format!(
                        "the script replaces `{n}` in its text before it is compiled"
                    ));
                }
            }
            Material {
                host: key(&script.path),
                object: o.open,
                usage,
                raw,
                glsl3,
                instanced,
                defines,
                unknown,
                written,
                vertex,
                fragment,
            }
        })
        .collect()
}

/// `code` on one line (runs of white space made one space), at most 40 characters.
fn short(code: &str) -> String {
    let line = code.split_whitespace().collect::<Vec<_>>().join(" ");
    match line.char_indices().nth(40) {
        Some((i, _)) => format!("{}…", &line[..i]),
        None => line.to_string(),
    }
}

/// Whether `name` occurs in `text` as a whole word.
fn word_in(text: &str, name: &str) -> bool {
    let ident = |c: Option<char>| c.is_some_and(|c| c.is_alphanumeric() || c == '_');
    text.match_indices(name).any(|(i, _)| {
        !ident(text[..i].chars().next_back()) && !ident(text[i + name.len()..].chars().next())
    })
}

/// The names three.js replaces in a program's whole text (`replaceLightNums`,
/// `replaceClippingPlaneNums`), longest first where one begins another; each is 0 in the scene
/// the preset builds (no lights, no clipping planes).
const PLACEHOLDERS: &str = "NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS|NUM_SPOT_LIGHT_SHADOWS|\
NUM_SPOT_LIGHT_COORDS|NUM_SPOT_LIGHT_MAPS|NUM_SPOT_LIGHTS|NUM_SUN_LIGHT_SHADOWS|NUM_SUN_LIGHTS|\
NUM_DIR_LIGHT_SHADOWS|NUM_DIR_LIGHTS|NUM_RECT_AREA_LIGHTS|NUM_POINT_LIGHT_SHADOWS|\
NUM_POINT_LIGHTS|NUM_HEMI_LIGHTS|NUM_LIGHT_PROBE_GRIDS|NUM_CLIPPING_PLANES|UNION_CLIPPING_PLANES";

/// three.js's `unrollLoopPattern`, its bounds also taking a placeholder (replaced before the
/// loops are unrolled).
const UNROLL: &str = r"#pragma unroll_loop_start\s+for\s*\(\s*int\s+i\s*=\s*(\w+)\s*;\s*i\s*<\s*(\w+)\s*;\s*i\s*\+\+\s*\)\s*\{([\s\S]+?)\}\s+#pragma unroll_loop_end";

/// The runs of an author's text that three.js rewrites after its includes are resolved: each
/// light or clipping-plane count (0), and each `#pragma unroll_loop_start` loop, by its
/// unrolled copies (`[ i ]` and `UNROLLED_LOOP_INDEX` numbered).
pub(crate) fn rewrites(text: &str) -> Vec<(std::ops::Range<usize>, String)> {
    static PATTERNS: std::sync::OnceLock<(regex::Regex, regex::Regex, regex::Regex)> =
        std::sync::OnceLock::new();
    let (names, unroll, index) = PATTERNS.get_or_init(|| {
        let re = |p: &str| regex::Regex::new(p).expect("a valid pattern");
        (re(PLACEHOLDERS), re(UNROLL), re(r"\[\s*i\s*\]"))
    });
    let number = |s: &str| -> Option<u32> { names.replace_all(s, "0").parse().ok() };
    let mut out: Vec<(std::ops::Range<usize>, String)> = Vec::new();
    let mut loops = Vec::new();
    for c in unroll.captures_iter(text) {
        let (Some(from), Some(to)) = (number(&c[1]), number(&c[2])) else {
            continue;
        };
        let body = names.replace_all(&c[3], "0");
        let mut copies = String::new();
        for i in from..to.min(from.saturating_add(1024)) {
            let numbered = index.replace_all(&body, format!("[ {i} ]").as_str());
            copies.push_str(&numbered.replace("UNROLLED_LOOP_INDEX", &i.to_string()));
        }
        let whole = c.get(0).map_or(0..0, |m| m.range());
        loops.push(whole.clone());
        out.push((whole, copies));
    }
    for m in names.find_iter(text) {
        if !loops.iter().any(|l| l.contains(&m.start())) {
            out.push((m.range(), "0".to_string()));
        }
    }
    out.sort_by_key(|(r, _)| r.start);
    out
}

/// The `#include <chunk>` lines of a text, as three.js matches them
/// (`^[ \t]*#include +<([\w\d./]+)>`): each line's run to replace, and the chunk's name.
fn includes(text: &str) -> Vec<(std::ops::Range<usize>, String)> {
    let mut out = Vec::new();
    let mut pos = 0;
    for line in text.split_inclusive('\n') {
        let start = pos;
        pos += line.len();
        let body = line.trim_start_matches([' ', '\t']);
        let Some(rest) = body.strip_prefix("#include") else {
            continue;
        };
        let after = rest.trim_start_matches(' ');
        if after.len() == rest.len() || !after.starts_with('<') {
            continue;
        }
        let name: String = after[1..]
            .chars()
            .take_while(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '.' | '/'))
            .collect();
        if name.is_empty() || !after[1 + name.len()..].starts_with('>') {
            continue;
        }
        let end = start + (line.len() - after.len()) + 1 + name.len() + 1;
        out.push((start..end, name));
    }
    out
}

/// Prepares the `three` preset for every host of `found` whose settings name it.
pub fn prepare(found: &Found, configs: &Configs, prepared: &mut Prepared) {
    let projects = node::projects(found, configs, Preset::Three, PACKAGE, prepared);
    for (root, hosts) in projects {
        project(found, &root, &hosts, prepared);
    }
}

fn project(found: &Found, root: &Path, hosts: &[usize], prepared: &mut Prepared) {
    let imports = DiskImports::new(root);
    for &h in hosts {
        imports.add(&found.hosts[h].path, found.hosts[h].file.clone());
    }
    let mut all: Vec<Material> = Vec::new();
    for &h in hosts {
        if let Some(script) = imports.script(&found.hosts[h].path) {
            all.extend(materials(&script, &imports));
        }
    }
    // An object kept for a material (`OutputShader`) is checked as the material made of it
    // is (`new RawShaderMaterial({vertexShader: OutputShader.vertexShader, …})`), and each
    // program once.
    let used: HashSet<(String, usize)> = all
        .iter()
        .filter(|m| m.usage)
        .flat_map(Material::literals)
        .collect();
    all.retain(|m| m.usage || !m.literals().any(|l| used.contains(&l)));
    let mut seen = HashSet::new();
    all.retain(|m| {
        let known = m.literals().next().is_some() || (m.usage || m.written) && m.unknown.is_some();
        known && seen.insert(m.signature())
    });
    if all.is_empty() {
        return;
    }
    for m in &all {
        for lit in [&m.vertex, &m.fragment].into_iter().flatten() {
            prepared
                .claimed
                .insert((key(Path::new(lit.file.name())), lit.at));
        }
    }
    let checked: Vec<usize> = (0..all.len())
        .filter(|&i| all[i].unknown.is_none())
        .collect();
    let request = json!({ "materials": checked.iter().map(|&id| {
        let m = &all[id];
        let mut chunks: Vec<String> = [&m.vertex, &m.fragment]
            .into_iter()
            .flatten()
            .flat_map(|l| includes(&l.text).into_iter().map(|(_, n)| n))
            .collect();
        chunks.sort();
        chunks.dedup();
        let define = |v: &str| match v {
            "true" => Value::Bool(true),
            "false" => Value::Bool(false),
            _ => Value::String(v.to_string()),
        };
        json!({
            "id": id,
            "raw": m.raw,
            "glsl3": m.glsl3,
            "instanced": m.instanced,
            "defines": m.defines.iter().map(|(k, v)| (k.clone(), define(v))).collect::<serde_json::Map<_, _>>(),
            "includes": chunks,
        })
    }).collect::<Vec<_>>() });
    let answer = if checked.is_empty() {
        json!({})
    } else {
        match node::run(SCRIPT, root, &request) {
            Ok(a) => a,
            Err(e) => {
                for &h in hosts {
                    prepared.failed.insert(key(&found.hosts[h].path), e.clone());
                }
                return;
            }
        }
    };
    let chunks: Vec<String> = answer["chunks"]
        .as_array()
        .map(|a| {
            a.iter()
                .filter_map(|c| c.as_str().map(String::from))
                .collect()
        })
        .unwrap_or_default();
    let results = answer["materials"].as_array().cloned().unwrap_or_default();
    for (id, m) in all.into_iter().enumerate() {
        let host = m.host.clone();
        let r = results
            .iter()
            .find(|r| r["id"].as_u64() == Some(id as u64))
            .cloned()
            .unwrap_or(Value::Null);
        let assembled = assemble(m, &r, &chunks);
        prepared.programs.entry(host).or_default().push(assembled);
    }
}

/// A material's shaders as three.js builds them, or what three.js refuses in them.
fn assemble(m: Material, r: &Value, chunks: &[String]) -> Assembled {
    if let Some(why) = m.unknown {
        return Assembled {
            object: m.object,
            vs: None,
            fs: None,
            error: None,
            unchecked: Some(format!("this material's program is not checked: {why}")),
            problems: Vec::new(),
        };
    }
    let error = r
        .get("error")
        .and_then(Value::as_str)
        .map(|e| format!("three.js cannot build this material's program: {e}"));
    let mut problems = Vec::new();
    let mut wrap = |lit: &Option<Literal>, stage: &str| -> Option<Wrap> {
        let lit = lit.clone()?;
        let prefix = r[stage].as_str()?.to_string();
        let mut runs = rewrites(&lit.text);
        for (run, name) in includes(&lit.text) {
            match r["expanded"][&name][stage].as_str() {
                Some(text) => runs.push((run, text.to_string())),
                None => problems.push(unknown_chunk(&lit, run, &name, chunks)),
            }
        }
        runs.sort_by_key(|(run, _)| run.start);
        let mut end = 0;
        runs.retain(|(run, _)| {
            let apart = run.start >= end;
            end = end.max(run.end);
            apart
        });
        Some(Wrap::around(lit, prefix, runs))
    };
    let vs = wrap(&m.vertex, "vertex");
    let fs = wrap(&m.fragment, "fragment");
    Assembled {
        object: m.object,
        vs,
        fs,
        error,
        unchecked: None,
        problems,
    }
}

/// The error of an `#include <name>` that three.js has no chunk for, at its line.
fn unknown_chunk(
    lit: &Literal,
    run: std::ops::Range<usize>,
    name: &str,
    chunks: &[String],
) -> (std::sync::Arc<essl::source::SourceFile>, Diagnostic) {
    let author = from_pieces(&lit.file, &lit.pieces);
    let at = author
        .map_span(Span::new(run.start as u32, run.end as u32))
        .map_or(Span::default(), |(_, s)| s);
    let mut d = Diagnostic::new(
        Severity::Error,
        CheckCode::PresetAssembly.as_str(),
        format!("three.js has no shader chunk `{name}`: `#include <{name}>` throws when the material is compiled"),
        at,
    );
    if let Some(near) = essl::suggest::nearest(name, chunks.iter().map(String::as_str)) {
        d = d.with_help(format!("a chunk with a similar name exists, `{near}`"));
        if let Some(i) = lit.text[run.clone()].find(name) {
            let start = at.start + i as u32;
            d = d.with_fix(Fix::suggested(
                format!("include `{near}`"),
                Span::new(start, start + name.len() as u32),
                near,
            ));
        }
    }
    (lit.file.clone(), d)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn include_lines_as_three_js_matches_them() {
        let text =
            "a\n  #include <common>\n#include\t<x>\n#include \"y\"\n\t#include  <a/b.c> // c\n";
        let found = includes(text);
        assert_eq!(found.len(), 2);
        assert_eq!(&text[found[0].0.clone()], "  #include <common>");
        assert_eq!(found[0].1, "common");
        assert_eq!(&text[found[1].0.clone()], "\t#include  <a/b.c>");
    }
}
