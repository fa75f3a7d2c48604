//! Linking a vertex and a fragment shader as WebGL2 does: varyings matched by name, type and
//! interpolation; uniforms declared in both stages must agree; attributes get locations; the
//! active lists hold exactly what is used, in ANGLE's order (`tests/oracle/PROBES.md`).

use std::collections::HashMap;

use crate::builtins::BuiltinVar;
use crate::diagnostic::{Diagnostic, Label};
use crate::hir::{GlobalId, GlobalKind, Module};
use crate::reflect::{self, UniformSource};
use crate::source::Span;
use crate::types::{GlType, Precision, StructDef, Type};
use crate::{Shader, Stage};

/// WebGL2's `MAX_VERTEX_ATTRIBS` on the reference implementation.
pub const MAX_VERTEX_ATTRIBS: u32 = 16;
/// `MAX_VARYING_VECTORS` (the fragment side's limit, the smaller one).
pub const MAX_VARYING_VECTORS: u32 = 15;

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
fn same_precision(
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

fn field_names_differ(a: &Type, sa: &[StructDef], b: &Type, sb: &[StructDef]) -> bool {
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
fn static_uses(m: &Module) -> Vec<bool> {
    use crate::hir::{Cond, Expr, ExprKind, Stmt, StmtKind};
    fn e(x: &Expr, out: &mut Vec<bool>) {
        match &x.kind {
            ExprKind::Global(g) => out[*g] = true,
            ExprKind::Unary(_, a)
            | ExprKind::IncDec(_, _, a)
            | ExprKind::Member(a, _)
            | ExprKind::Swizzle(a, _) => e(a, out),
            ExprKind::Binary(_, a, b)
            | ExprKind::Assign(_, a, b)
            | ExprKind::Comma(a, b)
            | ExprKind::Index(a, b) => {
                e(a, out);
                e(b, out);
            }
            ExprKind::Select(c, a, b) => {
                e(c, out);
                e(a, out);
                e(b, out);
            }
            ExprKind::Call(_, args) | ExprKind::Builtin(_, args) | ExprKind::Construct(args) => {
                args.iter().for_each(|a| e(a, out))
            }
            ExprKind::BlockMember(_, Some(i), _) => e(i, out),
            _ => {}
        }
    }
    fn s(x: &[Stmt], out: &mut Vec<bool>) {
        for st in x {
            match &st.kind {
                StmtKind::Expr(x) | StmtKind::Local(_, Some(x)) | StmtKind::Return(Some(x)) => {
                    e(x, out)
                }
                StmtKind::Block(b) => s(b, out),
                StmtKind::If(c, a, b) => {
                    e(c, out);
                    s(a, out);
                    s(b, out);
                }
                StmtKind::Loop {
                    init,
                    cond,
                    step,
                    body,
                    ..
                } => {
                    s(init, out);
                    if let Some(c) = cond {
                        match &**c {
                            Cond::Expr(x) | Cond::Decl(_, x) => e(x, out),
                        }
                    }
                    if let Some(x) = step {
                        e(x, out);
                    }
                    s(body, out);
                }
                StmtKind::Switch(sel, cases) => {
                    e(sel, out);
                    cases.iter().for_each(|c| s(&c.body, out));
                }
                _ => {}
            }
        }
    }
    let mut out = vec![false; m.globals.len()];
    for f in &m.functions {
        s(&f.body, &mut out);
    }
    // Dead code folded away by the checker (a constant `if (false)`) is still static use:
    // the checker keeps those statements, so this sees them.
    out
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
        code: &'static str,
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
        code: &'static str,
        message: String,
        log_line: String,
    ) -> &mut Diagnostic {
        self.log.push_str(&log_line);
        self.log.push('\n');
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
    let varyings = l.link_varyings();
    let uniforms = l.link_uniforms();
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

impl Linker<'_> {
    fn link_varyings(&mut self) -> Vec<Varying> {
        let (vm, fm) = (&self.vs.module, &self.fs.module);
        let fuse = static_uses(fm);
        let mut out = Vec::new();
        let mut next_location = 0u32;
        let outputs: HashMap<&str, GlobalId> = vm
            .globals
            .iter()
            .enumerate()
            .filter(|(_, g)| g.kind == GlobalKind::Output)
            .map(|(i, g)| (&*g.name, i))
            .collect();
        for (fi, fg) in fm.globals.iter().enumerate() {
            if fg.kind != GlobalKind::Input {
                continue;
            }
            let used = fuse[fi];
            let Some(&vi) = outputs.get(&*fg.name) else {
                if used {
                    let name = fg.name.clone();
                    let d = self.error(
                        Some(Stage::Fragment),
                        fg.span,
                        "varying-not-written",
                        format!("fragment input `{name}` has no matching vertex shader output"),
                        format!("FRAGMENT varying {name} does not match any VERTEX varying"),
                    );
                    d.label = "read here but never declared `out` in the vertex shader".into();
                    d.help = Some(format!(
                        "declare `out {} {name};` in the vertex shader and write it",
                        fg.ty.display(&fm.structs)
                    ));
                }
                continue;
            };
            let vg = &vm.globals[vi];
            let name = fg.name.clone();
            if !same_type(&vg.ty, &vm.structs, &fg.ty, &fm.structs) {
                let (vt, ft) = (
                    vg.ty.display(&vm.structs).to_string(),
                    fg.ty.display(&fm.structs).to_string(),
                );
                let arrays = vg.ty.is_array() && fg.ty.is_array();
                let what = if arrays { "Array sizes" } else { "Types" };
                let msg = format!("varying `{name}` is `{vt}` in the vertex shader but `{ft}` in the fragment shader");
                let line = format!(
                    "{what} of varying '{name}' differ between VERTEX and FRAGMENT shaders."
                );
                let vspan = vg.span;
                if used {
                    let d = self.error(
                        Some(Stage::Fragment),
                        fg.span,
                        "varying-type-mismatch",
                        msg,
                        line,
                    );
                    d.label = format!("`{ft}` here");
                    d.notes
                        .push(format!("the vertex shader declares it as `{vt}`"));
                    self.log.push_str(&format!(
                        "FRAGMENT varying {name} does not match any VERTEX varying\n"
                    ));
                } else {
                    let d = self.warning(
                        Some(Stage::Fragment),
                        fg.span,
                        "varying-type-mismatch",
                        msg,
                        line,
                    );
                    d.label = format!("`{ft}` here (never read, so the program still links)");
                }
                let _ = vspan;
                continue;
            }
            let vflat = vg.interpolation == Some(crate::ast::Interpolation::Flat);
            let fflat = fg.interpolation == Some(crate::ast::Interpolation::Flat);
            if vflat != fflat {
                let msg = format!("varying `{name}` is `flat` in one shader only");
                let line = format!("Interpolation types of varying '{name}' differ between VERTEX and FRAGMENT shaders.");
                let d = self.error(
                    Some(Stage::Fragment),
                    fg.span,
                    "varying-interpolation-mismatch",
                    msg,
                    line,
                );
                d.label = if fflat {
                    "`flat` here but not in the vertex shader"
                } else {
                    "not `flat` here but `flat` in the vertex shader"
                }
                .into();
                self.log.push_str(&format!(
                    "FRAGMENT varying {name} does not match any VERTEX varying\n"
                ));
                continue;
            }
            let n = location_count(&fg.ty, &fm.structs);
            out.push(Varying {
                name: name.to_string(),
                vertex: vi,
                fragment: fi,
                location: next_location,
            });
            next_location += n;
        }
        if next_location > MAX_VARYING_VECTORS {
            self.error(
                None,
                Span::default(),
                "too-many-varyings",
                format!("the varyings need {next_location} vectors but WebGL2 guarantees {MAX_VARYING_VECTORS}"),
                "Could not pack varying".into(),
            );
        }
        out
    }

    fn link_uniforms(&mut self) -> Vec<ActiveUniform> {
        let (vm, fm) = (&self.vs.module, &self.fs.module);
        let (vuse, fuse) = (static_uses(vm), static_uses(fm));
        // Declared-in-both checks.
        for (fi, fg) in fm.globals.iter().enumerate() {
            if fg.kind != GlobalKind::Uniform {
                continue;
            }
            let Some((vi, vg)) = vm
                .globals
                .iter()
                .enumerate()
                .find(|(_, g)| g.kind == GlobalKind::Uniform && g.name == fg.name)
            else {
                continue;
            };
            let name = fg.name.clone();
            if !same_type(&vg.ty, &vm.structs, &fg.ty, &fm.structs) {
                let names = field_names_differ(&vg.ty, &vm.structs, &fg.ty, &fm.structs);
                let (vt, ft) = (
                    vg.ty.display(&vm.structs).to_string(),
                    fg.ty.display(&fm.structs).to_string(),
                );
                let line = if names {
                    format!("Field names of uniform '{name}' differ between VERTEX and FRAGMENT shaders.")
                } else {
                    format!("Types of uniform '{name}' differ between VERTEX and FRAGMENT shaders.")
                };
                let d = self.error(
                    Some(Stage::Fragment),
                    fg.span,
                    "uniform-type-mismatch",
                    format!("uniform `{name}` is `{vt}` in the vertex shader but `{ft}` here"),
                    line,
                );
                d.label = "declared differently in the two shaders".into();
                d.notes.push(
                    "a uniform declared in both stages is one variable and must have one type"
                        .into(),
                );
                continue;
            }
            if vuse[vi]
                && fuse[fi]
                && !same_precision(
                    &vg.ty,
                    vg.precision,
                    &vm.structs,
                    &fg.ty,
                    fg.precision,
                    &fm.structs,
                )
            {
                let d = self.error(
                    Some(Stage::Fragment),
                    fg.span,
                    "uniform-precision-mismatch",
                    format!("uniform `{name}` has different precisions in the two shaders"),
                    format!("Precisions of uniform '{name}' differ between VERTEX and FRAGMENT shaders."),
                );
                d.label = format!("{} here", fg.precision.map_or("no precision", |p| p.name()));
                d.notes.push(format!(
                    "the vertex shader declares it {}",
                    vg.precision.map_or("without precision", |p| p.name())
                ));
                d.help = Some("give it the same precision qualifier in both shaders".into());
            }
        }
        // Active leaves, in ANGLE's order.
        let vr = reflect::reflect(vm);
        let fr = reflect::reflect(fm);
        struct Entry {
            leaf: reflect::UniformLeaf,
            vertex: Option<UniformSource>,
            fragment: Option<UniformSource>,
            stage_rank: u8,
            decl: usize,
            class: u8,
            shape: (u8, u8),
            part: u8,
            used: bool,
        }
        // ANGLE's classes: 0 non-highp non-aggregates (sorted by shape), 1 non-highp arrays and
        // structs, 2 highp (declaration order).
        let classify = |ty: &Type, precision: Option<Precision>| -> u8 {
            let aggregate = matches!(ty, Type::Array(..) | Type::Struct(_));
            let highp = precision == Some(Precision::High) && !matches!(ty, Type::Struct(_));
            if highp {
                2
            } else if aggregate {
                1
            } else {
                0
            }
        };
        let shape = |t: GlType| -> (u8, u8) {
            match t.to_type() {
                Type::Vector(_, n) => (1, n),
                Type::Matrix { cols, rows } => (cols, rows),
                _ => (1, 1),
            }
        };
        let mut entries: Vec<Entry> = Vec::new();
        let mut index: HashMap<String, usize> = HashMap::new();
        for (stage_rank, (module, refl)) in [(vm, &vr), (fm, &fr)].into_iter().enumerate() {
            let mut decl_order: HashMap<GlobalId, usize> = HashMap::new();
            for (leaf, used) in &refl.uniforms {
                let UniformSource::Default { global, .. } = &leaf.source else {
                    continue;
                };
                let n = decl_order.len();
                let decl = *decl_order.entry(*global).or_insert(n);
                if let Some(&i) = index.get(&leaf.name) {
                    if stage_rank == 1 {
                        entries[i].fragment = Some(leaf.source.clone());
                    }
                    entries[i].used |= *used;
                    continue;
                }
                let g = &module.globals[*global];
                index.insert(leaf.name.clone(), entries.len());
                entries.push(Entry {
                    shape: shape(leaf.ty),
                    leaf: leaf.clone(),
                    vertex: (stage_rank == 0).then(|| leaf.source.clone()),
                    fragment: (stage_rank == 1).then(|| leaf.source.clone()),
                    stage_rank: stage_rank as u8,
                    decl,
                    class: classify(&g.ty, g.precision),
                    part: if leaf.ty.is_sampler() { 1 } else { 0 },
                    used: *used,
                });
            }
        }
        let mut active: Vec<&Entry> = entries.iter().filter(|e| e.used).collect();
        active.sort_by_key(|e| {
            let shape = if e.class == 0 { e.shape } else { (0, 0) };
            (e.part, e.stage_rank, e.class, shape, e.decl)
        });
        let mut out: Vec<ActiveUniform> = active
            .into_iter()
            .map(|e| ActiveUniform {
                name: e.leaf.name.clone(),
                ty: e.leaf.ty,
                size: e.leaf.size,
                vertex: e.vertex.clone(),
                fragment: e.fragment.clone(),
            })
            .collect();
        // Uniform block members: all of them, vertex blocks first, then fragment-only ones.
        let mut seen: HashMap<String, usize> = HashMap::new();
        for (stage_rank, refl) in [&vr, &fr].into_iter().enumerate() {
            for leaf in &refl.block_uniforms {
                if let Some(&i) = seen.get(&leaf.name) {
                    if stage_rank == 1 {
                        out[i].fragment = Some(leaf.source.clone());
                    }
                    continue;
                }
                seen.insert(leaf.name.clone(), out.len());
                out.push(ActiveUniform {
                    name: leaf.name.clone(),
                    ty: leaf.ty,
                    size: leaf.size,
                    vertex: (stage_rank == 0).then(|| leaf.source.clone()),
                    fragment: (stage_rank == 1).then(|| leaf.source.clone()),
                });
            }
        }
        out
    }

    fn link_blocks(&mut self) {
        let (vm, fm) = (&self.vs.module, &self.fs.module);
        for fb in &fm.blocks {
            let Some(vb) = vm.blocks.iter().find(|b| b.name == fb.name) else {
                continue;
            };
            let name = fb.name.clone();
            let names_differ = vb.members.len() != fb.members.len()
                || vb.members.iter().zip(&fb.members).any(|(a, b)| a.0 != b.0);
            let types_differ = !names_differ
                && vb
                    .members
                    .iter()
                    .zip(&fb.members)
                    .any(|(a, b)| !same_type(&a.1, &vm.structs, &b.1, &fm.structs));
            let layout_differs = vb.layout != fb.layout
                || vb.members.iter().zip(&fb.members).any(|(a, b)| a.3 != b.3);
            let precision_differs = vb
                .members
                .iter()
                .zip(&fb.members)
                .any(|(a, b)| !same_precision(&a.1, a.2, &vm.structs, &b.1, b.2, &fm.structs));
            let (what, code) = if names_differ {
                ("Field names", "block-member-mismatch")
            } else if types_differ {
                ("Types", "block-type-mismatch")
            } else if layout_differs {
                ("Layout qualifiers", "block-layout-mismatch")
            } else if precision_differs {
                ("Precisions", "block-precision-mismatch")
            } else {
                continue;
            };
            let d = self.error(
                Some(Stage::Fragment),
                fb.span,
                code,
                format!("uniform block `{name}` is declared differently in the two shaders"),
                format!(
                    "{what} of uniform block '{name}' differ between VERTEX and FRAGMENT shaders."
                ),
            );
            d.label = format!(
                "{} differ from the vertex shader's `{name}`",
                what.to_lowercase()
            );
        }
    }

    /// Puts an attribute at `loc` (taking `n` locations) unless that aliases another one.
    fn place_attribute(
        &mut self,
        taken: &mut [Option<GlobalId>],
        locations: &mut Vec<(GlobalId, u32)>,
        gi: GlobalId,
        loc: u32,
        n: u32,
    ) {
        let vm = &self.vs.module;
        for l in loc..loc + n {
            if let Some(Some(other)) = taken.get(l as usize) {
                let (name, span) = (vm.globals[gi].name.clone(), vm.globals[gi].span);
                let (other_name, other_span) =
                    (vm.globals[*other].name.clone(), vm.globals[*other].span);
                let d = self.error(
                    Some(Stage::Vertex),
                    span,
                    "attribute-location-alias",
                    format!("attribute `{name}` overlaps `{other_name}` at location {l}"),
                    format!("Attribute '{name}' aliases attribute '{other_name}' at location {l}"),
                );
                d.label = "location already taken".into();
                d.secondary.push(Label {
                    span: other_span,
                    message: format!("`{other_name}` is here"),
                });
                return;
            }
        }
        for l in loc..loc + n {
            if let Some(t) = taken.get_mut(l as usize) {
                *t = Some(gi);
            }
        }
        locations.push((gi, loc));
    }

    fn link_attributes(
        &mut self,
        bindings: &[(String, u32)],
    ) -> (Vec<ActiveAttribute>, Vec<(GlobalId, u32)>) {
        let vm = &self.vs.module;
        let inputs: Vec<GlobalId> = vm
            .globals
            .iter()
            .enumerate()
            .filter(|(_, g)| g.kind == GlobalKind::Input)
            .map(|(i, _)| i)
            .collect();
        let mut taken: Vec<Option<GlobalId>> = vec![None; 64];
        let mut locations: Vec<(GlobalId, u32)> = Vec::new();
        // Explicit: `layout(location)` first, then `bindAttribLocation`.
        for &gi in &inputs {
            let g = &self.vs.module.globals[gi];
            let n = location_count(&g.ty, &self.vs.module.structs);
            let bound = bindings
                .iter()
                .find(|(name, _)| **name == *g.name)
                .map(|b| b.1);
            if let Some(loc) = g.location.or(bound) {
                self.place_attribute(&mut taken, &mut locations, gi, loc, n);
            }
        }
        for &gi in &inputs {
            if locations.iter().any(|(x, _)| *x == gi) {
                continue;
            }
            let g = &self.vs.module.globals[gi];
            let n = location_count(&g.ty, &self.vs.module.structs);
            match (0..64u32)
                .find(|&s| (s..s + n).all(|l| taken.get(l as usize).is_some_and(|t| t.is_none())))
            {
                Some(start) => self.place_attribute(&mut taken, &mut locations, gi, start, n),
                None => {
                    let (name, span) = (g.name.clone(), g.span);
                    self.error(
                        Some(Stage::Vertex),
                        span,
                        "too-many-attributes",
                        "no free attribute location".into(),
                        format!("Too many attributes ({name})"),
                    );
                }
            }
        }
        let vm = &self.vs.module;
        if let Some((gi, _)) = locations.iter().find(|(gi, loc)| {
            loc + location_count(&vm.globals[*gi].ty, &vm.structs) > MAX_VERTEX_ATTRIBS
        }) {
            let g = &vm.globals[*gi];
            let (name, span) = (g.name.clone(), g.span);
            let d = self.error(
                Some(Stage::Vertex),
                span,
                "too-many-attributes",
                format!("attribute `{name}` needs a location beyond the {MAX_VERTEX_ATTRIBS} WebGL2 guarantees"),
                format!("Too many attributes ({name})"),
            );
            d.label = "out of attribute locations".into();
        }
        let mut attributes: Vec<ActiveAttribute> = inputs
            .iter()
            .map(|&gi| (gi, &vm.globals[gi]))
            .filter(|(_, g)| g.used)
            .filter_map(|(gi, g)| {
                let loc = locations.iter().find(|(x, _)| *x == gi)?.1;
                Some(ActiveAttribute {
                    name: g.name.to_string(),
                    ty: g.ty.gl_type()?,
                    size: 1,
                    location: loc as i32,
                    global: Some(gi),
                })
            })
            .collect();
        for b in [BuiltinVar::VertexId, BuiltinVar::InstanceId] {
            if vm.used_builtins.contains(&b) {
                attributes.push(ActiveAttribute {
                    name: b.name().into(),
                    ty: GlType::INT,
                    size: 1,
                    location: -1,
                    global: None,
                });
            }
        }
        (attributes, locations)
    }
}
