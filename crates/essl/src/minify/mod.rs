//! Minifying a shader: comments and needless white space removed, local names shortened, and
//! the result compiled again and compared with the original before it is returned.
//!
//! What changes:
//! - comments go, and white space is kept only where two tokens would otherwise join
//!   (`float x`, `a - -b`); code runs on one line. Line continuations are joined.
//! - local variables, function parameters, user functions (never `main`) and plain and `const`
//!   globals take the shortest names that nothing in the text, the language, its built-ins or
//!   the `defines` spell (`a`, `b`, … the most used first); see [`names`] for exactly which
//!   names qualify.
//! - decimal float literals lose the zeros that do not change their value (`1.0` → `1.`).
//!
//! What stays: every name WebGL can see or match (uniforms, uniform blocks and their members,
//! struct types and members, attributes, `in`/`out` variables, varyings, fragment outputs),
//! and every preprocessor directive, each on a line of its own with its comments and extra
//! spaces gone: `#version` first, `#extension`, `#pragma`, `#line`, and
//! macros and conditionals as written, so that the text still answers to other `defines` as
//! the original did (three.js and similar libraries choose a shader's variant by prepending
//! `#define`s). `#define` bodies are printed token by token and renamed with the code. A text
//! that reads `__LINE__` keeps its line breaks.
//!
//! A shader with errors is not minified ([`MinifyError::Invalid`]). The minified text is
//! compiled with the same stage and options, and its interface compared with the original's:
//! the active uniforms and block uniforms (names, types, sizes, precisions), the inputs and
//! outputs (names, types, locations, qualifiers, static use), the uniform blocks and the
//! built-in variables used, which is everything linking reads. A text that fails either test
//! is never returned: the call fails with [`MinifyError::Broken`] or [`MinifyError::Differs`].
//!
//! Written here rather than taken from a crate: no Rust crate minifies GLSL ES, and renaming
//! safely needs what only the front end knows (which names are locals, which code the
//! preprocessor skips, what the interface is).

mod emit;
mod names;

use crate::hir::{GlobalKind, Module};
use crate::preprocess::PreprocessOptions;
use crate::source::SourceFile;
use crate::{compile, CompileOptions, Shader, Stage};

/// What to minify and how.
#[derive(Clone, Debug)]
pub struct MinifyOptions {
    /// The options the shader is compiled with (target, macros, extensions); the minified text
    /// is checked with the same.
    pub compile: CompileOptions,
    /// Shorten local names (default true); false removes comments and white space only.
    pub rename: bool,
}

impl Default for MinifyOptions {
    fn default() -> MinifyOptions {
        MinifyOptions {
            compile: CompileOptions::default(),
            rename: true,
        }
    }
}

/// A minified shader.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Minified {
    /// The minified text.
    pub text: String,
    /// Each renamed name and its new name, sorted by the original.
    pub renamed: Vec<(String, String)>,
}

/// Why a shader was not minified.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum MinifyError {
    /// The shader does not compile: it is not minified.
    #[error("the shader has {errors} error(s) and is not minified; the first: {first}")]
    Invalid {
        /// How many errors.
        errors: usize,
        /// The first error's message.
        first: String,
    },
    /// The minified text does not compile (a fault in the minifier; nothing is returned).
    #[error("the minified text does not compile ({0}); the shader is left as it was")]
    Broken(String),
    /// The minified text compiles but its interface differs from the original's.
    #[error("the minified shader's {0} differs from the original's; the shader is left as it was")]
    Differs(String),
}

/// Minifies a shader's text: see the [module](self) documentation.
pub fn minify(text: &str, stage: Stage, options: &MinifyOptions) -> Result<Minified, MinifyError> {
    let file = SourceFile::new("shader", text);
    let original = compile(file.clone(), stage, &options.compile);
    if let Some(first) = original.diagnostics.iter().find(|d| d.is_error()) {
        return Err(MinifyError::Invalid {
            errors: original.error_count(),
            first: first.message.clone(),
        });
    }
    let lexed = crate::lex::lex(&file);
    let lines = emit::lines(&lexed.tokens);
    let rename = if options.rename {
        let active = active_code(&file, stage, &options.compile);
        names::plan(&lines, &active, &original.module, &options.compile.defines)
    } else {
        Default::default()
    };
    let keep_lines = lexed.tokens.iter().any(|t| t.is_ident("__LINE__"));
    let out = emit::print(&lines, &rename, keep_lines);
    let minified = compile(
        SourceFile::new("minified", out.clone()),
        stage,
        &options.compile,
    );
    verify(&original, &minified)?;
    let mut renamed: Vec<(String, String)> = rename
        .into_iter()
        .map(|(a, b)| (a.to_string(), b.to_string()))
        .collect();
    renamed.sort();
    Ok(Minified { text: out, renamed })
}

/// The parts of the text the preprocessor passes on under `options`.
fn active_code(file: &SourceFile, stage: Stage, options: &CompileOptions) -> names::Active {
    let pp = crate::preprocess::preprocess(
        file,
        crate::lex::lex(file),
        &PreprocessOptions {
            defines: options.defines.clone(),
            extensions: PreprocessOptions::extension_macros(options.target, &options.extensions),
            stage: Some(stage),
            target: options.target,
        },
    );
    names::Active::new(
        pp.tokens
            .iter()
            .filter(|t| t.kind != crate::lex::PpKind::Eof)
            .map(|t| (t.span.start, t.span.end))
            .collect(),
    )
}

/// One part of a module's interface, as text to compare.
type Summary = fn(&Module) -> String;

/// Checks that the minified shader compiles and has the original's interface.
fn verify(original: &Shader, minified: &Shader) -> Result<(), MinifyError> {
    if let Some(first) = minified.diagnostics.iter().find(|d| d.is_error()) {
        return Err(MinifyError::Broken(first.message.clone()));
    }
    let (a, b) = (&original.module, &minified.module);
    let checks: [(&str, Summary); 4] = [
        ("interface", interface),
        ("uniform blocks", blocks),
        ("active uniforms and interface variables", |m| {
            format!("{:?}", crate::reflect::reflect(m))
        }),
        ("built-in variables", builtins),
    ];
    for (what, f) in checks {
        if f(a) != f(b) {
            return Err(MinifyError::Differs(what.to_string()));
        }
    }
    Ok(())
}

/// The globals WebGL sees, with everything linking and reflection read of them.
fn interface(m: &Module) -> String {
    let mut out = format!("{:?} {:?}\n", m.version, m.stage);
    for g in &m.globals {
        if matches!(g.kind, GlobalKind::Private | GlobalKind::Const) {
            continue;
        }
        out += &format!(
            "{:?} {} {:?} {:?} {:?} {} {} {:?} {}\n",
            g.kind,
            g.name,
            g.ty,
            g.precision,
            g.interpolation,
            g.centroid,
            g.invariant,
            g.location,
            g.used
        );
    }
    for s in &m.structs {
        out += &format!("{s:?}\n");
    }
    out
}

/// The uniform blocks, all but where they are.
fn blocks(m: &Module) -> String {
    m.blocks
        .iter()
        .map(|b| {
            format!(
                "{} {:?} {:?} {:?} {:?} {}\n",
                b.name, b.instance, b.array, b.members, b.layout, b.used
            )
        })
        .collect()
}

/// The built-in variables used and declared invariant.
fn builtins(m: &Module) -> String {
    let mut used: Vec<String> = m.used_builtins.iter().map(|v| v.name().into()).collect();
    used.sort();
    let mut inv: Vec<String> = m
        .invariant_builtins
        .iter()
        .map(|v| v.name().into())
        .collect();
    inv.sort();
    format!("{used:?} {inv:?} {} {}", m.invariant_all, m.frag_data_len)
}

#[cfg(test)]
mod tests;
