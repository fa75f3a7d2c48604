//! Linking a vertex and a fragment shader as WebGL2 does: varyings matched by name, type and
//! interpolation; uniforms declared in both stages must agree; attributes get locations; the
//! active lists hold exactly what is used, in ANGLE's order (`tests/oracle/PROBES.md`).
//!
//! The `Linker`'s `impl` is spread over the files of this module: varyings, uniforms (and
//! uniform blocks), attributes; this file holds the program's types and the driver.

mod attributes;
mod limits;
pub(crate) mod packing;
mod uniforms;
mod varyings;

use crate::diagnostic::Diagnostic;
use crate::diagnostic_code::Code;
use crate::hir::{GlobalId, GlobalKind, Module};
use crate::reflect::UniformSource;
use crate::source::Span;
use crate::types::{GlType, Precision, StructDef, Type};
use crate::{Shader, Stage};

/// `MAX_VERTEX_ATTRIBS` of the reference implementation, and WebGL 2's minimum.
pub const MAX_VERTEX_ATTRIBS: u32 = 16;

/// A link diagnostic, pointing into one of the two shaders (or none).
#[derive(Clone, Debug)]
pub struct LinkDiagnostic {
    /// The shader the span points into.
    pub stage: Option<Stage>,
    /// The diagnostic.
    pub diagnostic: Diagnostic,
}

/// An active uniform of the program.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ActiveUniform {
    /// WebGL's name.
    pub name: String,
    /// WebGL's type.
    pub ty: GlType,
    /// Array length.
    pub size: u32,
    /// Where it lives in the vertex shader, if declared there.
    pub vertex: Option<UniformSource>,
    /// Where it lives in the fragment shader, if declared there.
    pub fragment: Option<UniformSource>,
}

/// An active attribute of the program.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ActiveAttribute {
    /// Its name.
    pub name: String,
    /// WebGL's type.
    pub ty: GlType,
    /// Always 1 in ES 3.00.
    pub size: u32,
    /// Its location (-1 for `gl_VertexID`/`gl_InstanceID`).
    pub location: i32,
    /// The vertex shader global (`None` for built-ins).
    pub global: Option<GlobalId>,
}

/// A varying that connects the two stages.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Varying {
    /// Its name.
    pub name: String,
    /// The vertex shader's output.
    pub vertex: GlobalId,
    /// The fragment shader's input.
    pub fragment: GlobalId,
    /// First location.
    pub location: u32,
}

/// The result of linking.
#[derive(Clone, Debug)]
pub struct Program {
    /// `LINK_STATUS`.
    pub ok: bool,
    /// `getProgramInfoLog`, in ANGLE's wording.
    pub log: String,
    /// Errors and warnings with spans.
    pub diagnostics: Vec<LinkDiagnostic>,
    /// Active uniforms in WebGL's enumeration order.
    pub uniforms: Vec<ActiveUniform>,
    /// Active attributes in declaration order (built-ins last).
    pub attributes: Vec<ActiveAttribute>,
    /// Locations of every vertex input, active or not.
    pub attribute_locations: Vec<(GlobalId, u32)>,
    /// Matched varyings with locations.
    pub varyings: Vec<Varying>,
    /// Fragment outputs with their locations.
    pub fragment_outputs: Vec<(GlobalId, u32)>,
}

/// Links two compiled shaders with no `bindAttribLocation` bindings.
pub fn link(vs: &Shader, fs: &Shader) -> Program {
    link_with_bindings(vs, fs, &[])
}

/// Whether two types are the same across two modules (structs compared by name and members).
pub fn same_type(a: &Type, sa: &[StructDef], b: &Type, sb: &[StructDef]) -> bool {
    match (a, b) {
        (Type::Struct(x), Type::Struct(y)) => {
            let (x, y) = (&sa[x.0 as usize], &sb[y.0 as usize]);
            x.name == y.name
                && x.members.len() == y.members.len()
                && x.members
                    .iter()
                    .zip(&y.members)
                    .all(|(m, n)| m.name == n.name && same_type(&m.ty, sa, &n.ty, sb))
        }
        (Type::Array(x, n), Type::Array(y, m)) => n == m && same_type(x, sa, y, sb),
        _ => a == b,
    }
}

/// Whether two types agree in precision throughout (for uniforms used in both stages).
pub(super) fn same_precision(
    a: &Type,
    pa: Option<Precision>,
    sa: &[StructDef],
    b: &Type,
    pb: Option<Precision>,
    sb: &[StructDef],
) -> bool {
    match (a, b) {
        (Type::Struct(x), Type::Struct(y)) => {
            let (x, y) = (&sa[x.0 as usize], &sb[y.0 as usize]);
            x.members
                .iter()
                .zip(&y.members)
                .all(|(m, n)| same_precision(&m.ty, m.precision, sa, &n.ty, n.precision, sb))
        }
        (Type::Array(x, _), Type::Array(y, _)) => same_precision(x, pa, sa, y, pb, sb),
        _ => pa == pb,
    }
}

pub(super) fn field_names_differ(a: &Type, sa: &[StructDef], b: &Type, sb: &[StructDef]) -> bool {
    match (a, b) {
        (Type::Struct(x), Type::Struct(y)) => {
            let (x, y) = (&sa[x.0 as usize], &sb[y.0 as usize]);
            x.members.len() != y.members.len()
                || x.members
                    .iter()
                    .zip(&y.members)
                    .any(|(m, n)| m.name != n.name)
        }
        (Type::Array(x, _), Type::Array(y, _)) => field_names_differ(x, sa, y, sb),
        _ => false,
    }
}

/// How many locations (vec4 slots) a value of this type occupies.
pub fn location_count(ty: &Type, structs: &[StructDef]) -> u32 {
    match ty {
        Type::Matrix { cols, .. } => *cols as u32,
        Type::Array(el, n) => n * location_count(el, structs),
        Type::Struct(id) => structs[id.0 as usize]
            .members
            .iter()
            .map(|m| location_count(&m.ty, structs))
            .sum(),
        _ => 1,
    }
}

/// Which globals any function of the module references, reachable or not (static use).
pub(super) fn static_uses(m: &Module) -> Vec<bool> {
    use crate::hir::visit::{self, Visitor};
    use crate::hir::{Expr, ExprKind};
    struct Uses(Vec<bool>);
    impl Visitor for Uses {
        fn visit_expr(&mut self, e: &Expr) {
            if let ExprKind::Global(g) = e.kind {
                self.0[g] = true;
            }
            visit::walk_expr(self, e);
        }
    }
    let mut uses = Uses(vec![false; m.globals.len()]);
    for f in &m.functions {
        uses.visit_stmts(&f.body);
    }
    // Dead code folded away by the checker (a constant `if (false)`) is still static use:
    // the checker keeps those statements, so this sees them.
    uses.0
}

struct Linker<'a> {
    vs: &'a Shader,
    fs: &'a Shader,
    log: String,
    diagnostics: Vec<LinkDiagnostic>,
    ok: bool,
}

impl Linker<'_> {
    fn error(
        &mut self,
        stage: Option<Stage>,
        span: Span,
        code: Code,
        message: String,
        log_line: String,
    ) -> &mut Diagnostic {
        self.ok = false;
        self.log.push_str(&log_line);
        self.log.push('\n');
        self.diagnostics.push(LinkDiagnostic {
            stage,
            diagnostic: Diagnostic::error(code, message, span),
        });
        &mut self.diagnostics.last_mut().expect("pushed").diagnostic
    }

    fn warning(
        &mut self,
        stage: Option<Stage>,
        span: Span,
        code: Code,
        message: String,
        log_line: String,
    ) -> &mut Diagnostic {
        if !log_line.is_empty() {
            self.log.push_str(&log_line);
            self.log.push('\n');
        }
        self.diagnostics.push(LinkDiagnostic {
            stage,
            diagnostic: Diagnostic::warning(code, message, span),
        });
        &mut self.diagnostics.last_mut().expect("pushed").diagnostic
    }
}

/// Links two compiled shaders; `bindings` are `bindAttribLocation` calls made before linking.
pub fn link_with_bindings(vs: &Shader, fs: &Shader, bindings: &[(String, u32)]) -> Program {
    let mut l = Linker {
        vs,
        fs,
        log: String::new(),
        diagnostics: Vec::new(),
        ok: true,
    };
    let empty = Program {
        ok: false,
        log: String::new(),
        diagnostics: Vec::new(),
        uniforms: Vec::new(),
        attributes: Vec::new(),
        attribute_locations: Vec::new(),
        varyings: Vec::new(),
        fragment_outputs: Vec::new(),
    };
    if vs.stage != Stage::Vertex || fs.stage != Stage::Fragment {
        return Program {
            log: "Attached shaders must be one vertex and one fragment shader.\n".into(),
            ..empty
        };
    }
    if !vs.ok() || !fs.ok() {
        let mut log = String::new();
        if !vs.ok() {
            log.push_str("Vertex shader is not compiled.\n");
        }
        if !fs.ok() {
            log.push_str("Fragment shader is not compiled.\n");
        }
        return Program { log, ..empty };
    }
    let (vm, fm) = (&vs.module, &fs.module);
    if vm.version != fm.version {
        let name = |v: crate::Version| {
            if v == crate::Version::Es100 {
                "GLSL ES 1.00"
            } else {
                "GLSL ES 3.00"
            }
        };
        let d = l.error(
            Some(Stage::Fragment),
            Span::default(),
            Code::VersionMismatch,
            format!(
                "the vertex shader is {} but the fragment shader is {}",
                name(vm.version),
                name(fm.version)
            ),
            "Fragment shader version does not match other shader versions.".into(),
        );
        d.label = format!("the fragment shader is {}", name(fm.version));
        d.help = Some("write both shaders in the same version: both with `#version 300 es` on their first line, or neither".into());
        return Program {
            log: l.log,
            diagnostics: l.diagnostics,
            ..empty
        };
    }
    let varyings = l.link_varyings();
    let uniforms = l.link_uniforms();
    l.check_uniform_limits();
    l.link_blocks();
    let (attributes, attribute_locations) = l.link_attributes(bindings);
    let fragment_outputs = fm
        .globals
        .iter()
        .enumerate()
        .filter(|(_, g)| g.kind == GlobalKind::Output)
        .map(|(i, g)| (i, g.location.unwrap_or(0)))
        .collect();
    let _ = vm;
    Program {
        ok: l.ok,
        log: l.log,
        diagnostics: l.diagnostics,
        uniforms,
        attributes,
        attribute_locations,
        varyings,
        fragment_outputs,
    }
}
