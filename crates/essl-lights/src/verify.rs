//! Checking a generated program with the `essl` front end: it must compile and link with zero
//! diagnostics, and a specialised program must be minimal — every declared uniform active,
//! every function and varying used.

use essl::hir::GlobalKind;
use essl::source::SourceFile;
use essl::{compile, CompileOptions, Stage};

use crate::program::ShaderPair;

/// What `essl` says about a program.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Verification {
    /// Every compile and link diagnostic, as `stage: severity code: message`.
    pub diagnostics: Vec<String>,
    /// `LINK_STATUS`.
    pub linked: bool,
    /// Active uniform names as WebGL reports them (`name[0]` for arrays).
    pub active_uniforms: Vec<String>,
    /// Declared uniforms that are not active.
    pub inactive_uniforms: Vec<String>,
    /// Functions defined but never called from `main`, as `stage: name`.
    pub unused_functions: Vec<String>,
    /// Inputs, outputs and uniforms declared but not used by `main`, as `stage: name`.
    pub unused_globals: Vec<String>,
}

impl Verification {
    /// Compiles and links with zero diagnostics.
    pub fn is_clean(&self) -> bool {
        self.linked && self.diagnostics.is_empty()
    }

    /// Clean, and nothing declared goes unused.
    pub fn is_minimal(&self) -> bool {
        self.is_clean()
            && self.inactive_uniforms.is_empty()
            && self.unused_functions.is_empty()
            && self.unused_globals.is_empty()
    }
}

/// Compiles both shaders of `program` with `essl`, links them and reports.
pub fn verify(program: &ShaderPair) -> Verification {
    let opts = CompileOptions::default();
    let vs = compile(
        SourceFile::new("essl-lights.vert", program.vertex.clone()),
        Stage::Vertex,
        &opts,
    );
    let fs = compile(
        SourceFile::new("essl-lights.frag", program.fragment.clone()),
        Stage::Fragment,
        &opts,
    );
    let mut diagnostics = Vec::new();
    for sh in [&vs, &fs] {
        for d in &sh.diagnostics {
            diagnostics.push(format!(
                "{}: {} {}: {} (at {:?})",
                sh.stage.as_str(),
                d.severity.as_str(),
                d.code,
                d.message,
                sh.file.slice(d.span)
            ));
        }
    }
    let linked = essl::link::link(&vs, &fs);
    for d in &linked.diagnostics {
        diagnostics.push(format!(
            "link: {} {}: {}",
            d.diagnostic.severity.as_str(),
            d.diagnostic.code,
            d.diagnostic.message
        ));
    }
    let active_uniforms: Vec<String> = linked.uniforms.iter().map(|u| u.name.clone()).collect();
    let inactive_uniforms = program
        .uniforms
        .iter()
        .map(|u| u.active_name())
        .filter(|n| !active_uniforms.contains(n))
        .collect();
    let mut unused_functions = Vec::new();
    let mut unused_globals = Vec::new();
    for sh in [&vs, &fs] {
        for f in &sh.module.functions {
            if !f.used {
                unused_functions.push(format!("{}: {}", sh.stage.as_str(), f.name));
            }
        }
        for g in &sh.module.globals {
            let interface = matches!(
                g.kind,
                GlobalKind::Uniform | GlobalKind::Input | GlobalKind::Output
            );
            if interface && !g.used {
                unused_globals.push(format!("{}: {}", sh.stage.as_str(), g.name));
            }
        }
    }
    Verification {
        diagnostics,
        linked: linked.ok,
        active_uniforms,
        inactive_uniforms,
        unused_functions,
        unused_globals,
    }
}
