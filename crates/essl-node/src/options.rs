//! The options object of the JavaScript API (`check(source, options)`), read from the JSON the
//! JS side writes: each key checked, a wrong one an error that names it (`TypeError` in JS).

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use essl::{Stage, Target};
use essl_check::{Overrides, Preset};
use essl_lint::Level;
use serde_json::{Map, Value};

/// Why an options object cannot be used: the message a `TypeError` carries.
#[derive(Debug)]
pub struct OptionError(pub String);

/// What `check`, `link` and `translate` take.
#[derive(Clone)]
pub struct Options {
    /// The file the text is checked as (its extension gives the stage or says JS/HTML); its
    /// folder is where `#include`s, `essl.toml` and a preset's package are looked for.
    pub filename: PathBuf,
    /// What is asked beyond `essl.toml`.
    pub overrides: Overrides,
    /// Whether the lints run.
    pub lints: bool,
    /// Whether a host file's pairs are linked.
    pub link: bool,
    /// The JSON text these options were read from (what [`read`] keeps them by).
    pub json: Arc<str>,
    /// The overrides as read, written out: with the stage asked for (which `link` and
    /// `translate` set on top), the key of the settings read for them. It leaves out the
    /// filename, so modules of one build share their settings.
    pub settings_key: Arc<str>,
}

/// What a JSON value is, in words.
fn kind(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

fn bad(key: &str, wanted: &str, got: &Value) -> OptionError {
    OptionError(format!("options.{key} must be {wanted}, not {}", kind(got)))
}

fn string<'a>(o: &'a Map<String, Value>, key: &str) -> Result<Option<&'a str>, OptionError> {
    match o.get(key) {
        None | Some(Value::Null) => Ok(None),
        Some(Value::String(s)) => Ok(Some(s)),
        Some(v) => Err(bad(key, "a string", v)),
    }
}

fn boolean(o: &Map<String, Value>, key: &str, default: bool) -> Result<bool, OptionError> {
    match o.get(key) {
        None | Some(Value::Null) => Ok(default),
        Some(Value::Bool(b)) => Ok(*b),
        Some(v) => Err(bad(key, "a boolean", v)),
    }
}

/// The stage a name (`vertex`, `fragment`, or `vert`/`frag`) names.
pub fn stage(name: &str) -> Option<Stage> {
    match name {
        "vertex" | "vert" => Some(Stage::Vertex),
        "fragment" | "frag" => Some(Stage::Fragment),
        _ => None,
    }
}

/// How many option texts [`read`] keeps.
const KEPT: usize = 8;

/// Reads an options object; `default_name` is the file name used when `filename` is absent
/// (its extension says what the text is). The options last read from the same text are reused
/// (a bundler, or a loop over many shaders, passes one options object every time): only a
/// relative `filename` is resolved again, against the current folder of this call.
pub fn read(json: &str, default_name: &'static str) -> Result<Options, OptionError> {
    type Kept = Vec<(&'static str, Options)>;
    static READ: Mutex<Kept> = Mutex::new(Vec::new());
    let found = {
        let kept = READ.lock().unwrap_or_else(|e| e.into_inner());
        kept.iter()
            .find(|(name, o)| *name == default_name && *o.json == *json)
            .map(|(_, o)| o.clone())
    };
    let mut options = match found {
        Some(o) => o,
        None => {
            let o = parse(json, default_name)?;
            let mut kept = READ.lock().unwrap_or_else(|e| e.into_inner());
            if kept.len() == KEPT {
                kept.remove(0);
            }
            kept.push((default_name, o.clone()));
            o
        }
    };
    options.filename = absolute(&options.filename);
    Ok(options)
}

/// Reads an options object, its `filename` as written.
fn parse(json: &str, default_name: &str) -> Result<Options, OptionError> {
    let value: Value = serde_json::from_str(json)
        .map_err(|e| OptionError(format!("options are not JSON: {e}")))?;
    let empty = Map::new();
    let o = match &value {
        Value::Object(o) => o,
        Value::Null => &empty,
        v => {
            return Err(OptionError(format!(
                "options must be an object, not {}",
                kind(v)
            )))
        }
    };
    const KEYS: [&str; 13] = [
        "filename",
        "stage",
        "target",
        "defines",
        "includeDirs",
        "includes",
        "preset",
        "config",
        "rules",
        "lints",
        "link",
        "denyWarnings",
        "variants",
    ];
    if let Some(k) = o.keys().find(|k| !KEYS.contains(&k.as_str())) {
        return Err(OptionError(format!(
            "options.{k} is not an option (options: {})",
            KEYS.join(", ")
        )));
    }
    let mut overrides = Overrides::default();
    if let Some(s) = string(o, "stage")? {
        overrides.stage = Some(stage(s).ok_or_else(|| {
            OptionError(format!(
                "options.stage must be 'vertex' or 'fragment', not '{s}'"
            ))
        })?);
    }
    if let Some(t) = string(o, "target")? {
        overrides.target = Some(Target::from_name(t).ok_or_else(|| {
            OptionError(format!(
                "options.target must be 'webgl1' or 'webgl2', not '{t}'"
            ))
        })?);
    }
    if let Some(p) = string(o, "preset")? {
        overrides.preset = Some(Preset::from_name(p).ok_or_else(|| {
            OptionError(format!(
                "options.preset must be 'three' or 'luma', not '{p}'"
            ))
        })?);
    }
    if let Some(c) = string(o, "config")? {
        overrides.config = Some(PathBuf::from(c));
    }
    match o.get("defines") {
        None | Some(Value::Null) => {}
        Some(Value::Object(d)) => {
            for (k, v) in d {
                let value = match v {
                    Value::String(s) => s.clone(),
                    Value::Number(n) => n.to_string(),
                    Value::Bool(true) => "1".to_string(),
                    Value::Bool(false) => continue,
                    v => return Err(bad(&format!("defines.{k}"), "a string or a number", v)),
                };
                overrides.defines.push((k.clone(), value));
            }
        }
        Some(v) => return Err(bad("defines", "an object ({NAME: value})", v)),
    }
    match o.get("includeDirs") {
        None | Some(Value::Null) => {}
        Some(Value::Array(dirs)) => {
            for d in dirs {
                match d {
                    Value::String(s) => overrides.include_dirs.push(PathBuf::from(s)),
                    v => return Err(bad("includeDirs[]", "a string", v)),
                }
            }
        }
        Some(v) => return Err(bad("includeDirs", "an array of folders", v)),
    }
    overrides.variants = match o.get("variants") {
        None | Some(Value::Null) => None,
        Some(Value::Bool(on)) => Some(if *on { essl_lint::variants::DEFAULT } else { 0 }),
        Some(Value::Number(n)) if n.as_u64().is_some() => {
            Some(n.as_u64().map_or(0, |n| n.min(u32::MAX as u64) as usize))
        }
        Some(v) => return Err(bad("variants", "a boolean or a whole number", v)),
    };
    overrides.includes = boolean(o, "includes", true)?;
    overrides.deny_warnings = boolean(o, "denyWarnings", false)?;
    match o.get("rules") {
        None | Some(Value::Null) => {}
        Some(Value::Object(rules)) => {
            for (rule, level) in rules {
                let level = match level.as_str() {
                    Some("allow" | "off") => Level::Allow,
                    Some("note") => Level::Note,
                    Some("warn") => Level::Warn,
                    Some("deny" | "error") => Level::Deny,
                    _ => {
                        return Err(bad(
                            &format!("rules.{rule}"),
                            "'allow', 'note', 'warn' or 'deny'",
                            level,
                        ))
                    }
                };
                overrides
                    .rule(rule, level)
                    .map_err(|e| OptionError(format!("options.rules: {e}")))?;
            }
        }
        Some(v) => return Err(bad("rules", "an object ({rule: level})", v)),
    }
    let filename = PathBuf::from(string(o, "filename")?.unwrap_or(default_name));
    // A shader file's name decides its stage, as everywhere in essl; a `stage` that says
    // otherwise is a mistake (it would be dropped silently).
    if let (Some(asked), Some(named)) = (overrides.stage, essl_check::stage_from_name(&filename)) {
        if asked != named {
            return Err(OptionError(format!(
                "options.stage is '{}', but options.filename '{}' names a {} shader",
                asked.as_str(),
                filename.display(),
                named.as_str()
            )));
        }
    }
    Ok(Options {
        filename,
        lints: boolean(o, "lints", true)?,
        link: boolean(o, "link", true)?,
        json: Arc::from(json),
        settings_key: Arc::from(format!("{overrides:?}")),
        overrides,
    })
}

/// `path` against the current folder.
fn absolute(path: &Path) -> PathBuf {
    if path.is_absolute() {
        return path.to_path_buf();
    }
    std::env::current_dir()
        .map(|d| d.join(path))
        .unwrap_or_else(|_| path.to_path_buf())
}
