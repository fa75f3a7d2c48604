//! The checker: resolves names, types every expression, folds constants and enforces the rules
//! GLSL ES 3.00 (and WebGL2) impose, producing a [`hir::Module`].
//!
//! Each rule reports a diagnostic and checking goes on, so that every error is reported in one
//! run; an expression that failed to check becomes [`hir::ExprKind::Error`] (of type
//! [`Type::Void`]) and later rules stay quiet about it (no cascades).

mod appendix_a;
mod decl;
mod es100;
mod expr;
pub mod fold;
mod limits;
mod loops;
mod stmt;
mod types;
mod webgl;

use crate::diagnostic_code::Code;
use crate::Name;
use rustc_hash::FxHashMap as HashMap;

use crate::ast;
use crate::builtins::BuiltinVar;
use crate::diagnostic::Diagnostic;
use crate::hir::{self, FuncId, GlobalId, LocalId};
use crate::source::{SourceFile, Span};
use crate::target::Language;
use crate::types::{Precision, SamplerType, StructDef, Type};
use crate::Stage;

/// Checks a parsed GLSL ES 3.00 shader for WebGL 2 ([`check_as`] for another language).
pub fn check(
    file: &SourceFile,
    unit: &ast::TranslationUnit,
    stage: Stage,
    invariant_all: bool,
) -> (hir::Module, Vec<Diagnostic>) {
    check_as(file, unit, stage, invariant_all, &Language::es300())
}

/// Checks a parsed shader.
pub fn check_as(
    file: &SourceFile,
    unit: &ast::TranslationUnit,
    stage: Stage,
    invariant_all: bool,
    lang: &Language,
) -> (hir::Module, Vec<Diagnostic>) {
    let mut c = Checker::new(file, stage, lang);
    c.invariant_all = invariant_all;
    c.truncated = unit.truncated;
    for item in &unit.items {
        c.external(item);
    }
    c.finish();
    let mut module = hir::Module {
        stage,
        version: if lang.es100 {
            crate::Version::Es100
        } else {
            crate::Version::Es300
        },
        structs: c.structs,
        globals: c.globals,
        functions: c.functions,
        entry: c.entry,
        blocks: c.blocks,
        used_builtins: Vec::new(),
        invariant_all,
        invariant_builtins: c.invariant_builtins,
        frag_data_len: crate::builtins::constant_in("gl_MaxDrawBuffers", lang).unwrap_or(1) as u32,
        frag_color_broadcast: lang.es100
            && lang.has_at(crate::target::Extension::WebglDrawBuffers, u32::MAX),
    };
    crate::usage::mark(&mut module);
    (module, c.diags)
}

/// Whether a type is `bool`, a `bool` vector, or an array of them.
fn is_bool(ty: &Type) -> bool {
    match ty {
        Type::Array(el, _) => is_bool(el),
        _ => ty.scalar_kind() == Some(crate::types::ScalarKind::Bool),
    }
}

/// What a name refers to.
#[derive(Clone, Debug)]
enum Sym {
    Var(Var),
    Funcs(Vec<FuncId>),
    Struct(crate::types::StructId),
    /// A named uniform block instance.
    Block(usize),
}

/// A variable reference.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Var {
    Local(LocalId),
    Param(usize),
    Global(GlobalId),
}

/// What a default precision applies to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum PrecKey {
    Float,
    Int,
    Sampler(SamplerType),
}

#[derive(Default)]
struct Scope {
    names: HashMap<Name, Sym>,
    precisions: Vec<(PrecKey, Precision)>,
}

/// The function being checked.
struct FnCtx {
    func: FuncId,
    locals: Vec<hir::Local>,
    /// GLSL ES 1.00 (Appendix A): the indices of the `for` loops whose bodies enclose the
    /// current statement, which may not be written and may index arrays.
    loop_indices: Vec<LocalId>,
    loops: u32,
    switches: u32,
    calls: Vec<FuncId>,
    ret: Type,
}

pub(crate) struct Checker<'a> {
    file: &'a SourceFile,
    stage: Stage,
    /// The language version, target and usable extensions.
    lang: Language,
    diags: Vec<Diagnostic>,
    structs: Vec<StructDef>,
    globals: Vec<hir::Global>,
    functions: Vec<hir::Function>,
    /// Per function: defined (has a body), and where it was first declared.
    fn_defined: Vec<bool>,
    /// Per function: declared by a prototype (GLSL ES 1.00 allows one).
    fn_prototyped: Vec<bool>,
    blocks: Vec<hir::UniformBlock>,
    scopes: Vec<Scope>,
    fctx: Option<FnCtx>,
    entry: Option<FuncId>,
    invariant_all: bool,
    depth_range_struct: Option<crate::types::StructId>,
    /// Fragment outputs declared: (global, has location).
    frag_outputs: Vec<GlobalId>,
    /// Counter for names of unnamed parameters.
    unnamed_param_counter: u32,
    /// The parser stopped early: do not report what is missing from the end.
    truncated: bool,
    /// Locals of the current function whose block has ended: (name, declaration).
    ended: Vec<(Name, Span)>,
    /// How deeply each struct of `structs` nests structs ([`webgl`]).
    struct_depths: Vec<u32>,
    /// Bytes of private variables declared so far ([`limits`]).
    private_bytes: u64,
    /// Built-in variables declared `invariant` (`invariant gl_Position;`).
    invariant_builtins: Vec<BuiltinVar>,
    /// The first use of `gl_FragColor` and of `gl_FragData` (GLSL ES 1.00).
    frag_color_use: Option<Span>,
    frag_data_use: Option<Span>,
    /// Where diagnostics past the limit are completed and dropped.
    dropped: Diagnostic,
}

impl<'a> Checker<'a> {
    fn new(file: &'a SourceFile, stage: Stage, lang: &Language) -> Checker<'a> {
        let mut global = Scope::default();
        // Predeclared default precisions (ES 3.00 §4.5.4).
        match stage {
            Stage::Vertex => {
                global.precisions.push((PrecKey::Float, Precision::High));
                global.precisions.push((PrecKey::Int, Precision::High));
            }
            Stage::Fragment => global.precisions.push((PrecKey::Int, Precision::Medium)),
        }
        for name in ["sampler2D", "samplerCube"] {
            let s = SamplerType::from_name(name).expect("sampler");
            global
                .precisions
                .push((PrecKey::Sampler(s), Precision::Low));
        }
        Checker {
            file,
            stage,
            lang: lang.clone(),
            diags: Vec::new(),
            structs: Vec::new(),
            globals: Vec::new(),
            functions: Vec::new(),
            fn_defined: Vec::new(),
            fn_prototyped: Vec::new(),
            blocks: Vec::new(),
            scopes: vec![global],
            fctx: None,
            entry: None,
            invariant_all: false,
            depth_range_struct: None,
            frag_outputs: Vec::new(),
            unnamed_param_counter: 0,
            truncated: false,
            ended: Vec::new(),
            struct_depths: Vec::new(),
            private_bytes: 0,
            invariant_builtins: Vec::new(),
            frag_color_use: None,
            frag_data_use: None,
            dropped: Diagnostic::new(
                crate::diagnostic::Severity::Warning,
                "dropped",
                "",
                Span::default(),
            ),
        }
    }

    // ----- diagnostics -----

    fn error(&mut self, code: Code, span: Span, message: impl Into<String>) -> &mut Diagnostic {
        let token = self.file.slice(span).to_string();
        self.keep(Diagnostic::error(code, message, span).with_token(token))
    }

    fn warning(&mut self, code: Code, span: Span, message: impl Into<String>) -> &mut Diagnostic {
        let token = self.file.slice(span).to_string();
        self.keep(Diagnostic::warning(code, message, span).with_token(token))
    }

    /// Adds a diagnostic (for the caller to complete), or, past
    /// [`crate::diagnostic::MAX_DIAGNOSTICS`], lets the caller complete one that is dropped.
    fn keep(&mut self, d: Diagnostic) -> &mut Diagnostic {
        if crate::diagnostic::accepts(&self.diags, &d) {
            self.diags.push(d);
            self.diags.last_mut().expect("just pushed")
        } else {
            self.dropped = d;
            &mut self.dropped
        }
    }

    fn type_name(&self, ty: &Type) -> String {
        format!("`{}`", ty.display(&self.structs))
    }

    // ----- scopes -----

    fn push_scope(&mut self) {
        self.scopes.push(Scope::default());
    }

    fn pop_scope(&mut self) {
        if let Some(scope) = self.scopes.pop() {
            // Remember variables whose block ended, to explain a later "undeclared" use.
            if let Some(f) = &self.fctx {
                for (name, sym) in scope.names {
                    if let Sym::Var(Var::Local(l)) = sym {
                        self.ended.push((name, f.locals[l].span));
                    }
                }
            }
        }
    }

    fn at_global_scope(&self) -> bool {
        self.scopes.len() == 1
    }

    fn lookup(&self, name: &str) -> Option<&Sym> {
        self.scopes.iter().rev().find_map(|s| s.names.get(name))
    }

    /// Declares a name in the innermost scope; reports a redefinition.
    fn declare(&mut self, name: &ast::Ident, sym: Sym) -> bool {
        if let Some(prev) = self.scopes.last().expect("scope").names.get(&name.name) {
            let what = match prev {
                Sym::Funcs(_) => "a function",
                Sym::Struct(_) => "a struct",
                Sym::Block(_) => "a uniform block instance",
                Sym::Var(_) => "a variable",
            };
            let d = self.error(
                Code::Redefinition,
                name.span,
                format!("`{}` is already declared in this scope", name.name),
            );
            d.label = format!("redefines {what}");
            d.help = Some("rename one of them".into());
            return false;
        }
        self.scopes
            .last_mut()
            .expect("scope")
            .names
            .insert(name.name.clone(), sym);
        true
    }

    /// Checks a name the user declares: reserved prefixes and double underscores.
    fn check_name(&mut self, name: &ast::Ident) {
        let n = &*name.name;
        if n.starts_with("gl_") || n.starts_with("webgl_") || n.starts_with("_webgl_") {
            let prefix = if n.starts_with("gl_") {
                "gl_"
            } else if n.starts_with("webgl_") {
                "webgl_"
            } else {
                "_webgl_"
            };
            let d = self.error(
                Code::ReservedName,
                name.span,
                format!("`{n}` starts with `{prefix}`, which is reserved for built-in names"),
            );
            d.label = "reserved prefix".into();
            d.help = Some(format!("rename it without the `{prefix}` prefix"));
        } else if n.as_bytes().windows(2).any(|w| w == b"__") {
            let d = self.error(
                Code::ReservedName,
                name.span,
                format!("`{n}` contains `__`, which is reserved in GLSL ES 3.00"),
            );
            d.label = "two consecutive underscores".into();
            d.help = Some(format!("rename it, e.g. `{}`", n.replace("__", "_")));
        }
    }

    // ----- precision -----

    fn default_precision(&self, key: PrecKey) -> Option<Precision> {
        self.scopes.iter().rev().find_map(|s| {
            s.precisions
                .iter()
                .rev()
                .find(|(k, _)| *k == key)
                .map(|(_, p)| *p)
        })
    }

    fn prec_key(ty: &Type) -> Option<PrecKey> {
        match ty {
            Type::Scalar(k) | Type::Vector(k, _) => match k {
                crate::types::ScalarKind::Float => Some(PrecKey::Float),
                crate::types::ScalarKind::Int | crate::types::ScalarKind::Uint => {
                    Some(PrecKey::Int)
                }
                crate::types::ScalarKind::Bool => None,
            },
            Type::Matrix { .. } => Some(PrecKey::Float),
            Type::Sampler(s) => Some(PrecKey::Sampler(*s)),
            Type::Array(t, _) => Self::prec_key(t),
            _ => None,
        }
    }

    /// The precision of a declaration: its qualifier, else the default in scope. Reports a
    /// missing default (a `float` in a fragment shader, a `sampler3D` anywhere).
    fn precision_for(
        &mut self,
        ty: &Type,
        declared: Option<Precision>,
        span: Span,
    ) -> Option<Precision> {
        if declared.is_some() && is_bool(ty) {
            let d = self.error(
                Code::InvalidPrecision,
                span,
                "`bool` takes no precision qualifier",
            );
            d.label = "a precision on a `bool`".into();
            d.token = "bool".into();
            d.notes
                .push("precision qualifiers apply to float, integer and sampler types only".into());
            d.help = Some("remove the precision qualifier".into());
            return None;
        }
        let key = Self::prec_key(ty)?;
        if declared.is_some() {
            return declared;
        }
        if let Some(p) = self.default_precision(key) {
            return Some(p);
        }
        let what = match key {
            PrecKey::Float => "float".to_string(),
            PrecKey::Int => "int".to_string(),
            PrecKey::Sampler(s) => s.name().to_string(),
        };
        let insert_at = self.precision_insert_point();
        let d = self.error(
            Code::MissingPrecision,
            span,
            format!("no precision specified for `{what}`"),
        );
        d.label = "this declaration needs a precision".into();
        d.token = String::new();
        d.notes.push(match key {
            PrecKey::Float => "fragment shaders have no default precision for `float`".into(),
            _ => format!("`{what}` has no default precision in GLSL ES 3.00"),
        });
        d.help = Some(format!("declare a default precision, e.g. `precision highp {what};`, or qualify the declaration"));
        if let Some(at) = insert_at {
            d.fix = Some(crate::diagnostic::Fix::suggested(
                format!("add `precision highp {what};` after `#version`"),
                Span::empty(at),
                format!("precision highp {what};\n"),
            ));
        }
        // Report once per kind: pretend a default exists from here on.
        self.scopes[0].precisions.push((key, Precision::High));
        None
    }

    /// Where a `precision` statement can be inserted: the start of line 2 (after `#version`).
    fn precision_insert_point(&self) -> Option<u32> {
        if self.file.line_text(0).trim_start().starts_with("#version") && self.file.line_count() > 1
        {
            Some(self.file.line_start(1))
        } else {
            None
        }
    }

    // ----- top level -----

    fn external(&mut self, item: &ast::ExternalDecl) {
        match item {
            ast::ExternalDecl::Function(f) => self.function_def(f),
            ast::ExternalDecl::Prototype(p) => {
                self.function_decl(p, false);
            }
            ast::ExternalDecl::Declaration(d) => {
                self.declaration(d, true);
            }
        }
    }

    /// Checks after the last declaration: `main`, recursion, outputs, uses.
    fn finish(&mut self) {
        match self.entry {
            None if self.truncated => {}
            None => {
                let at = Span::empty(self.file.text().len() as u32);
                let d = self.error(Code::MissingMain, at, "the shader has no `main` function");
                d.label = "`void main() { … }` expected".into();
                d.token = String::new();
                d.help = Some("add `void main() { … }`".into());
            }
            Some(f) if !self.fn_defined[f] => {
                let span = self.functions[f].span;
                let d = self.error(
                    Code::MissingMain,
                    span,
                    "`main` is declared but never defined",
                );
                d.label = "declared here without a body".into();
            }
            _ => {}
        }
        self.check_recursion();
        self.check_call_depth();
        self.check_fragment_outputs();
        self.check_frag_color_and_data();
        self.check_infinite_loops();
    }

    fn check_recursion(&mut self) {
        // Depth-first search for a cycle in the call graph.
        let n = self.functions.len();
        let mut state = vec![0u8; n]; // 0 new, 1 on stack, 2 done
        let mut reported = vec![false; n];
        for start in 0..n {
            if state[start] != 0 {
                continue;
            }
            let mut stack: Vec<(usize, usize)> = vec![(start, 0)];
            state[start] = 1;
            while let Some(&mut (f, ref mut next)) = stack.last_mut() {
                if let Some(&callee) = self.functions[f].calls.get(*next) {
                    *next += 1;
                    match state[callee] {
                        0 => {
                            state[callee] = 1;
                            stack.push((callee, 0));
                        }
                        1 if !reported[callee] => {
                            reported[callee] = true;
                            let pos = stack.iter().position(|(g, _)| *g == callee).unwrap_or(0);
                            let chain: Vec<String> = stack[pos..]
                                .iter()
                                .map(|(g, _)| self.functions[*g].name.to_string())
                                .chain(std::iter::once(self.functions[callee].name.to_string()))
                                .collect();
                            let span = self.functions[callee].span;
                            let msg = if chain.len() == 2 {
                                format!("function `{}` calls itself", chain[0])
                            } else {
                                format!("recursive call chain: {}", chain.join(" → "))
                            };
                            let d = self.error(Code::Recursion, span, msg);
                            d.label = "part of a recursive call chain".into();
                            d.notes.push("GLSL ES 3.00 forbids recursion, even in functions that are never called".into());
                        }
                        _ => {}
                    }
                } else {
                    state[f] = 2;
                    stack.pop();
                }
            }
        }
    }

    fn check_fragment_outputs(&mut self) {
        if self.stage != Stage::Fragment || self.frag_outputs.len() < 2 {
            return;
        }
        for &g in &self.frag_outputs.clone() {
            if self.globals[g].location.is_none() {
                let span = self.globals[g].span;
                let name = self.globals[g].name.clone();
                let d = self.error(
                    Code::OutputLocationRequired,
                    span,
                    format!("fragment output `{name}` needs a `layout(location = N)`"),
                );
                d.label = "no location".into();
                d.notes.push("when a fragment shader has several outputs, every one needs an explicit location".into());
            }
        }
        // Overlapping locations.
        let mut used: Vec<(u32, GlobalId)> = Vec::new();
        for &g in &self.frag_outputs.clone() {
            let Some(loc) = self.globals[g].location else {
                continue;
            };
            let n = match &self.globals[g].ty {
                Type::Array(_, n) => *n,
                _ => 1,
            };
            for l in loc..loc + n {
                if let Some((_, other)) = used.iter().find(|(u, _)| *u == l) {
                    let other_name = self.globals[*other].name.clone();
                    let span = self.globals[g].span;
                    let d = self.error(
                        Code::OutputLocationOverlap,
                        span,
                        format!("fragment output location {l} is already used by `{other_name}`"),
                    );
                    d.label = "overlapping location".into();
                    break;
                }
                used.push((l, g));
            }
        }
    }

    fn new_local(&mut self, local: hir::Local) -> LocalId {
        let f = self.fctx.as_mut().expect("in a function");
        f.locals.push(local);
        f.locals.len() - 1
    }

    fn unnamed_param(&mut self) -> Name {
        self.unnamed_param_counter += 1;
        Name::from(format!("_essl_unnamed{}", self.unnamed_param_counter))
    }
}
