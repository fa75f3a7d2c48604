//! Reading a call script: the JSON of `docs/gl-scripts.md`, checked as strictly as
//! `run-chromium.py` checks it — a key not in the format, an enum name WebGL2 does not have, a
//! `ref` to nothing made yet, a name made twice or a `record` key used twice is an error before
//! anything runs.

use std::collections::HashSet;
use std::path::{Path, PathBuf};

use essl_gl::ContextAttributes;
use serde_json::{Map, Value as Json};

use crate::value::TypedArray;
use crate::ScriptError;

/// A call script: a canvas, a context, and the calls of `setup` and `frame`.
#[derive(Clone, Debug)]
pub struct Script {
    /// Free text.
    pub description: String,
    /// Canvas width in pixels.
    pub width: u32,
    /// Canvas height in pixels.
    pub height: u32,
    /// The context's attributes, WebGL's defaults for those the script leaves out
    /// (`antialias` true included).
    pub context: ContextAttributes,
    /// Extensions enabled before `setup`, in order.
    pub extensions: Vec<String>,
    /// Calls run once.
    pub setup: Vec<Call>,
    /// Calls run after `setup` for the picture, and again for timing.
    pub frame: Vec<Call>,
}

impl Script {
    /// Whether a call waits for results (`until`): such a script is not timed.
    pub fn waits(&self) -> bool {
        self.setup
            .iter()
            .chain(&self.frame)
            .any(|c| c.until.is_some())
    }
}

/// One WebGL call and what is expected of it.
#[derive(Clone, Debug)]
pub struct Call {
    /// The method's name as in WebGL2's IDL (`bindFramebuffer`).
    pub f: String,
    /// The arguments.
    pub args: Vec<Arg>,
    /// Keep the return value under this name.
    pub keep_as: Option<String>,
    /// Record the return value (or the `out` array) under this key.
    pub record: Option<String>,
    /// The error `getError` must report right after the call (`NO_ERROR` = 0 by default).
    pub error: u32,
    /// Repeat until the call returns this.
    pub until: Option<Arg>,
    /// The `COMPILE_STATUS` / `LINK_STATUS` expected after `compileShader` / `linkProgram`.
    pub status: bool,
}

/// An argument as the script writes it.
#[derive(Clone, Debug, PartialEq)]
pub enum Arg {
    /// A number (JSON numbers are float64).
    Number(f64),
    /// `true` or `false`.
    Bool(bool),
    /// `null`.
    Null,
    /// A string (also a `{"str": …}` and a `{"file": …}`'s text).
    Str(String),
    /// A named object kept by an earlier call.
    Ref(String),
    /// A new typed array of these values.
    Typed(TypedArray),
    /// A new zero-filled (or `fill`-filled) typed array for the call to write into.
    Out(TypedArray),
    /// A JavaScript array.
    List(Vec<Arg>),
}

/// GL constants of the extensions essl-gl offers, looked up after the context's own.
const EXTENSION_ENUMS: &[(&str, &str, u32)] = &[
    ("EXT_color_buffer_half_float", "RGBA16F_EXT", 0x881A),
    ("EXT_color_buffer_half_float", "RGB16F_EXT", 0x881B),
    (
        "EXT_color_buffer_half_float",
        "FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE_EXT",
        0x8211,
    ),
    (
        "EXT_color_buffer_half_float",
        "UNSIGNED_NORMALIZED_EXT",
        0x8C17,
    ),
];

/// Reads a script from a file; `{"file": …}` arguments are read relative to its folder.
pub fn read_script(path: &Path) -> Result<Script, ScriptError> {
    let text = std::fs::read_to_string(path).map_err(|e| ScriptError::Io {
        path: path.to_path_buf(),
        message: e.to_string(),
    })?;
    let dir = path.parent().unwrap_or(Path::new(".")).to_path_buf();
    parse_script(&text, &dir)
}

/// Parses a script's JSON; `dir` is where `{"file": …}` paths start.
pub fn parse_script(text: &str, dir: &Path) -> Result<Script, ScriptError> {
    let json: Json = serde_json::from_str(text).map_err(|e| ScriptError::Json(e.to_string()))?;
    Parser {
        dir: dir.to_path_buf(),
        extensions: Vec::new(),
        made: HashSet::new(),
        recorded: HashSet::new(),
        at: String::new(),
    }
    .script(&json)
}

struct Parser {
    dir: PathBuf,
    extensions: Vec<String>,
    /// Names made with `as` so far.
    made: HashSet<String>,
    /// `record` keys used so far.
    recorded: HashSet<String>,
    /// Where in the script, for messages (`setup[3]`).
    at: String,
}

fn object<'a>(json: &'a Json, what: &str, keys: &[&str]) -> Result<&'a Map<String, Json>, String> {
    let Json::Object(map) = json else {
        return Err(format!("{what} must be an object"));
    };
    if let Some(k) = map.keys().find(|k| !keys.contains(&k.as_str())) {
        return Err(format!("{what} has an unknown key `{k}`"));
    }
    Ok(map)
}

impl Parser {
    fn fail(&self, message: impl Into<String>) -> ScriptError {
        ScriptError::Malformed {
            at: self.at.clone(),
            message: message.into(),
        }
    }

    fn script(mut self, json: &Json) -> Result<Script, ScriptError> {
        const KEYS: &[&str] = &[
            "format",
            "description",
            "width",
            "height",
            "context",
            "extensions",
            "setup",
            "frame",
        ];
        let map = object(json, "the script", KEYS).map_err(|m| self.fail(m))?;
        if map.get("format") != Some(&Json::from(1)) {
            return Err(self.fail("`format` must be 1"));
        }
        let description = match map.get("description") {
            None => String::new(),
            Some(Json::String(s)) => s.clone(),
            Some(_) => return Err(self.fail("`description` must be a string")),
        };
        let size = |key: &str| match map.get(key).and_then(Json::as_u64) {
            Some(v @ 1..=4096) => Ok(v as u32),
            _ => Err(self.fail(format!("`{key}` must be an integer in 1..4096"))),
        };
        let (width, height) = (size("width")?, size("height")?);
        let context = self.context(map.get("context"))?;
        if let Some(list) = map.get("extensions") {
            let Some(list) = list.as_array() else {
                return Err(self.fail("`extensions` must be a list of strings"));
            };
            for e in list {
                let Some(name) = e.as_str() else {
                    return Err(self.fail("`extensions` must be a list of strings"));
                };
                self.extensions.push(name.to_string());
            }
        }
        let setup = self.calls(map.get("setup"), "setup")?;
        let frame = self.calls(map.get("frame"), "frame")?;
        Ok(Script {
            description,
            width,
            height,
            context,
            extensions: self.extensions,
            setup,
            frame,
        })
    }

    fn context(&self, json: Option<&Json>) -> Result<ContextAttributes, ScriptError> {
        // WebGL's defaults, which differ from essl-gl's in `antialias`.
        let mut attrs = ContextAttributes {
            antialias: true,
            ..ContextAttributes::default()
        };
        let Some(json) = json else {
            return Ok(attrs);
        };
        const KEYS: &[&str] = &[
            "alpha",
            "depth",
            "stencil",
            "antialias",
            "premultipliedAlpha",
            "preserveDrawingBuffer",
        ];
        let map = object(json, "`context`", KEYS).map_err(|m| self.fail(m))?;
        for (key, value) in map {
            let Some(b) = value.as_bool() else {
                return Err(self.fail(format!("`context.{key}` must be a boolean")));
            };
            match key.as_str() {
                "alpha" => attrs.alpha = b,
                "depth" => attrs.depth = b,
                "stencil" => attrs.stencil = b,
                "antialias" => attrs.antialias = b,
                "premultipliedAlpha" => attrs.premultiplied_alpha = b,
                _ => attrs.preserve_drawing_buffer = b,
            }
        }
        Ok(attrs)
    }

    fn calls(&mut self, json: Option<&Json>, phase: &str) -> Result<Vec<Call>, ScriptError> {
        let Some(Json::Array(list)) = json else {
            self.at = String::new();
            return Err(self.fail(format!("`{phase}` must be a list of calls")));
        };
        let mut calls = Vec::with_capacity(list.len());
        for (i, call) in list.iter().enumerate() {
            self.at = format!("{phase}[{i}]");
            calls.push(self.call(call)?);
        }
        Ok(calls)
    }

    fn call(&mut self, json: &Json) -> Result<Call, ScriptError> {
        const KEYS: &[&str] = &["f", "a", "as", "record", "error", "until", "status"];
        let map = object(json, "a call", KEYS).map_err(|m| self.fail(m))?;
        let Some(f) = map.get("f").and_then(Json::as_str) else {
            return Err(self.fail("`f` must be a method's name"));
        };
        self.at = format!("{} ({f})", self.at);
        let args = match map.get("a") {
            None => Vec::new(),
            Some(Json::Array(list)) => {
                list.iter().map(|a| self.arg(a)).collect::<Result<_, _>>()?
            }
            Some(_) => return Err(self.fail("`a` must be a list")),
        };
        if args.iter().filter(|a| matches!(a, Arg::Out(_))).count() > 1 {
            return Err(self.fail("at most one `out` array a call"));
        }
        let name = |key: &str| match map.get(key) {
            None => Ok(None),
            Some(Json::String(s)) if !s.is_empty() => Ok(Some(s.clone())),
            Some(_) => Err(self.fail(format!("`{key}` must be a non-empty string"))),
        };
        let keep_as = name("as")?;
        let record = name("record")?;
        let error = match name("error")? {
            None => 0,
            Some(e) => match e.as_str() {
                "NO_ERROR"
                | "INVALID_ENUM"
                | "INVALID_VALUE"
                | "INVALID_OPERATION"
                | "INVALID_FRAMEBUFFER_OPERATION"
                | "OUT_OF_MEMORY" => essl_gl::gl::by_name(&e).unwrap_or(0) as u32,
                _ => return Err(self.fail(format!("`error` {e} is not an error's name"))),
            },
        };
        let until = map.get("until").map(|a| self.arg(a)).transpose()?;
        let status = match map.get("status") {
            None => true,
            Some(Json::Bool(b)) if matches!(f, "compileShader" | "linkProgram") => *b,
            Some(_) => {
                return Err(
                    self.fail("`status` is a boolean, only on compileShader and linkProgram")
                )
            }
        };
        if let Some(key) = &record {
            if !self.recorded.insert(key.clone()) {
                return Err(self.fail(format!("record key `{key}` used twice")));
            }
        }
        if let Some(n) = &keep_as {
            if !self.made.insert(n.clone()) {
                return Err(self.fail(format!("`as` name `{n}` made twice")));
            }
        }
        Ok(Call {
            f: f.to_string(),
            args,
            keep_as,
            record,
            error,
            until,
            status,
        })
    }

    fn arg(&self, json: &Json) -> Result<Arg, ScriptError> {
        Ok(match json {
            Json::Null => Arg::Null,
            Json::Bool(b) => Arg::Bool(*b),
            Json::Number(n) => Arg::Number(n.as_f64().unwrap_or(f64::NAN)),
            Json::String(s) if is_enum_name(s) => Arg::Number(self.enum_value(s)? as f64),
            Json::String(s) => Arg::Str(s.clone()),
            Json::Array(list) => {
                Arg::List(list.iter().map(|a| self.arg(a)).collect::<Result<_, _>>()?)
            }
            Json::Object(map) => self.object_arg(map)?,
        })
    }

    fn enum_value(&self, name: &str) -> Result<i64, ScriptError> {
        if let Some(v) = essl_gl::gl::by_name(name) {
            return Ok(v);
        }
        self.extensions
            .iter()
            .find_map(|ext| {
                EXTENSION_ENUMS
                    .iter()
                    .find(|(e, n, _)| e == ext && *n == name)
                    .map(|&(_, _, v)| i64::from(v))
            })
            .ok_or_else(|| self.fail(format!("unknown enum `{name}`")))
    }

    fn object_arg(&self, map: &Map<String, Json>) -> Result<Arg, ScriptError> {
        let only = |keys: &[&str]| match map.keys().find(|k| !keys.contains(&k.as_str())) {
            Some(k) => Err(self.fail(format!("an argument has an unknown key `{k}`"))),
            None => Ok(()),
        };
        if let Some(s) = map.get("str") {
            only(&["str"])?;
            return match s {
                Json::String(s) => Ok(Arg::Str(s.clone())),
                _ => Err(self.fail("`str` must be a string")),
            };
        }
        if let Some(list) = map.get("or") {
            only(&["or"])?;
            let mut bits = 0u32;
            for name in list.as_array().into_iter().flatten() {
                match name.as_str() {
                    Some(n) if is_enum_name(n) => bits |= self.enum_value(n)? as u32,
                    _ => return Err(self.fail("`or` must list enum names")),
                }
            }
            return Ok(Arg::Number(f64::from(bits)));
        }
        if let Some(r) = map.get("ref") {
            only(&["ref"])?;
            let Some(name) = r.as_str() else {
                return Err(self.fail("`ref` must be a name"));
            };
            if !self.made.contains(name) {
                return Err(self.fail(format!("`ref` {name} names nothing made before")));
            }
            return Ok(Arg::Ref(name.to_string()));
        }
        if let Some(f) = map.get("file") {
            only(&["file"])?;
            let Some(rel) = f.as_str() else {
                return Err(self.fail("`file` must be a path"));
            };
            let path = self.dir.join(rel);
            let text = std::fs::read_to_string(&path).map_err(|e| ScriptError::Io {
                path: path.clone(),
                message: e.to_string(),
            })?;
            return Ok(Arg::Str(text));
        }
        if let Some(kind) = map.get("out") {
            only(&["out", "length", "fill"])?;
            let kind = kind
                .as_str()
                .ok_or_else(|| self.fail("`out` must name an array kind"))?;
            let length = map
                .get("length")
                .and_then(Json::as_u64)
                .filter(|&n| n <= 1 << 26)
                .ok_or_else(|| self.fail("`out` needs a `length` up to 2^26"))?;
            let fill = match map.get("fill") {
                None => 0.0,
                Some(v) => v
                    .as_f64()
                    .ok_or_else(|| self.fail("`fill` must be a number"))?,
            };
            let values = vec![fill; length as usize];
            let array = TypedArray::from_values(kind, &values).map_err(|m| self.fail(m))?;
            return Ok(Arg::Out(array));
        }
        if map.len() == 1 {
            let (kind, values) = map.iter().next().expect("one entry");
            let Some(values) = values.as_array() else {
                return Err(self.fail(format!("`{kind}` must list numbers")));
            };
            let numbers: Option<Vec<f64>> = values.iter().map(Json::as_f64).collect();
            let numbers =
                numbers.ok_or_else(|| self.fail(format!("`{kind}` must list numbers")))?;
            let array = TypedArray::from_values(kind, &numbers).map_err(|m| self.fail(m))?;
            return Ok(Arg::Typed(array));
        }
        Err(self.fail("an argument object must be one of str, or, ref, file, out or a typed array"))
    }
}

/// Whether a string names an enum: only `A`–`Z`, `0`–`9` and `_`.
fn is_enum_name(s: &str) -> bool {
    !s.is_empty()
        && s.bytes()
            .all(|b| b.is_ascii_uppercase() || b.is_ascii_digit() || b == b'_')
}
