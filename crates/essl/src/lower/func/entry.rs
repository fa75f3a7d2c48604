//! The entry point that wraps the shader's `main`: it copies the inputs and built-ins into
//! private variables, calls `main`, and returns the outputs (with `gl_Position` and
//! `gl_FragDepth`) as one struct.

use naga::proc::Emitter;
use naga::{Expression, Handle, Literal, Span as NSpan, Statement};

use super::FnCx;
use crate::builtins::BuiltinVar;
use crate::hir::{self};
use crate::lower::plan::StagePlan;
use crate::lower::{GlobalLower, LowerError, ModuleCx};
use crate::program::InternalUniform;
use crate::source::Span;
use crate::types::{ScalarKind, Type};
use crate::Stage;

/// IO leaves of a value: (path of struct members / array elements / matrix columns, leaf type).
fn io_leaves(ty: &Type, structs: &[crate::types::StructDef]) -> Vec<(Vec<u32>, Type)> {
    let mut out = Vec::new();
    fn walk(
        ty: &Type,
        structs: &[crate::types::StructDef],
        path: &mut Vec<u32>,
        out: &mut Vec<(Vec<u32>, Type)>,
    ) {
        match ty {
            Type::Matrix { cols, rows } => {
                for c in 0..*cols as u32 {
                    path.push(c);
                    out.push((path.clone(), Type::Vector(ScalarKind::Float, *rows)));
                    path.pop();
                }
            }
            Type::Array(el, n) => {
                for i in 0..*n {
                    path.push(i);
                    walk(el, structs, path, out);
                    path.pop();
                }
            }
            Type::Struct(id) => {
                for (i, m) in structs[id.0 as usize].members.iter().enumerate() {
                    path.push(i as u32);
                    walk(&m.ty, structs, path, out);
                    path.pop();
                }
            }
            t => out.push((path.clone(), t.clone())),
        }
    }
    walk(ty, structs, &mut Vec::new(), &mut out);
    out
}

/// The name and location binding of leaf `i` (of `count`) of an input or output `g` whose first
/// location is `location`. `varying` says whether the value travels between the stages (a
/// vertex output or a fragment input): then it is interpolated — perspective-correct, at the
/// centroid when `centroid` says so — unless it is `flat` or not a float.
fn io_binding(
    g: &hir::Global,
    centroid: bool,
    count: usize,
    i: usize,
    leaf_ty: &Type,
    location: u32,
    varying: bool,
) -> (String, naga::Binding) {
    let flat = g.interpolation == Some(crate::ast::Interpolation::Flat)
        || leaf_ty.scalar_kind() != Some(ScalarKind::Float);
    let (interpolation, sampling) = match (varying, flat) {
        (false, _) => (None, None),
        (true, true) => (Some(naga::Interpolation::Flat), None),
        (true, false) => (
            Some(
                if g.interpolation == Some(crate::ast::Interpolation::NoPerspective) {
                    naga::Interpolation::Linear
                } else {
                    naga::Interpolation::Perspective
                },
            ),
            Some(if centroid {
                naga::Sampling::Centroid
            } else {
                naga::Sampling::Center
            }),
        ),
    };
    let name = if count > 1 {
        format!("{}_{i}", g.name)
    } else {
        g.name.as_str().to_owned()
    };
    (
        name,
        naga::Binding::Location {
            location: location + i as u32,
            interpolation,
            sampling,
            blend_src: None,
            per_primitive: false,
        },
    )
}

/// The binding of one of the two varyings that carry `gl_ClipDistance` to the fragment stage.
fn clip_varying_binding(location: u32) -> naga::Binding {
    naga::Binding::Location {
        location,
        interpolation: Some(naga::Interpolation::Perspective),
        sampling: Some(naga::Sampling::Center),
        blend_src: None,
        per_primitive: false,
    }
}

/// The members and values of the struct the entry point returns.
#[derive(Default)]
struct Outputs {
    members: Vec<naga::StructMember>,
    values: Vec<Handle<Expression>>,
}

impl Outputs {
    /// Adds a member (its offset set when the struct is laid out).
    fn push(
        &mut self,
        name: String,
        ty: Handle<naga::Type>,
        binding: naga::Binding,
        v: Handle<Expression>,
    ) {
        self.members.push(naga::StructMember {
            name: Some(name),
            ty,
            binding: Some(binding),
            offset: 0,
        });
        self.values.push(v);
    }
}

/// Builds the entry point that wraps the shader's `main`.
pub(crate) fn entry_point(
    cx: &mut ModuleCx,
    main: Handle<naga::Function>,
    plan: &StagePlan,
) -> Result<naga::Function, LowerError> {
    let stage = cx.stage;
    let mut fx = FnCx {
        cx,
        f: naga::Function {
            name: Some("main".into()),
            ..Default::default()
        },
        emitter: Emitter::default(),
        blocks: vec![naga::Block::new()],
        locals: Vec::new(),
        params: Vec::new(),
        param_samplers: Default::default(),
        hir_fn: None,
    };
    fx.emitter.start(&fx.f.expressions);
    let sp = Span::default();
    fx.copy_inputs(plan);
    let frag_coord_arg = fx.copy_builtin_inputs();
    fx.copy_clip_distance_input(plan);
    fx.default_frag_depth(frag_coord_arg);
    // Call the shader's main.
    fx.push(
        Statement::Call {
            function: main,
            arguments: Vec::new(),
            result: None,
        },
        sp,
    );
    let mut outputs = Outputs::default();
    if stage == Stage::Vertex {
        fx.vertex_builtin_outputs(&mut outputs);
        fx.clip_distance_outputs(plan, &mut outputs);
    }
    fx.user_outputs(plan, &mut outputs);
    if stage == Stage::Fragment {
        fx.frag_color_outputs(&mut outputs);
        fx.frag_depth_output(&mut outputs);
    }
    if !outputs.members.is_empty() {
        fx.return_outputs(outputs);
    }
    fx.flush();
    let body = fx.blocks.pop().expect("body");
    let mut f = fx.f;
    f.body = body;
    Ok(f)
}

impl FnCx<'_, '_> {
    /// Stores `value` into the private variable `var`.
    fn store_private(&mut self, var: Handle<naga::GlobalVariable>, value: Handle<Expression>) {
        let sp = Span::default();
        let p = self.add(Expression::GlobalVariable(var), sp);
        self.push(Statement::Store { pointer: p, value }, sp);
    }

    /// Appends an argument of the entry point; returns its value.
    fn argument(
        &mut self,
        name: String,
        ty: Handle<naga::Type>,
        binding: naga::Binding,
    ) -> Handle<Expression> {
        let arg = self.f.arguments.len() as u32;
        self.f.arguments.push(naga::FunctionArgument {
            name: Some(name),
            ty,
            binding: Some(binding),
        });
        self.add(Expression::FunctionArgument(arg), Span::default())
    }

    /// A pointer to the leaf at `path` inside the private variable `var`.
    fn leaf_pointer(
        &mut self,
        var: Handle<naga::GlobalVariable>,
        path: &[u32],
    ) -> Handle<Expression> {
        let sp = Span::default();
        let mut p = self.add(Expression::GlobalVariable(var), sp);
        for &k in path {
            p = self.access_index(p, k, sp);
        }
        p
    }

    /// The value of the private variable `var`.
    fn load_private(&mut self, var: Handle<naga::GlobalVariable>) -> Handle<Expression> {
        let sp = Span::default();
        let p = self.add(Expression::GlobalVariable(var), sp);
        self.add(Expression::Load { pointer: p }, sp)
    }

    /// The inputs, one argument per leaf, copied into their private variables.
    fn copy_inputs(&mut self, plan: &StagePlan) {
        let hir = self.cx.hir;
        let varying = self.cx.stage == Stage::Fragment;
        for &(gi, loc) in &plan.inputs {
            let g = &hir.globals[gi];
            let GlobalLower::Private(var) = self.cx.globals[gi] else {
                continue;
            };
            let leaves = io_leaves(&g.ty, &hir.structs);
            for (i, (path, leaf_ty)) in leaves.iter().enumerate() {
                let ty = self.ty(leaf_ty);
                let (name, binding) =
                    io_binding(g, g.centroid, leaves.len(), i, leaf_ty, loc, varying);
                let value = self.argument(name, ty, binding);
                let p = self.leaf_pointer(var, path);
                self.push(Statement::Store { pointer: p, value }, Span::default());
            }
        }
    }

    /// The built-in inputs the shader uses, copied into their private variables (converted as
    /// GLSL types them; `gl_FragCoord` flipped when asked). Returns `gl_FragCoord`'s argument
    /// when there is one.
    fn copy_builtin_inputs(&mut self) -> Option<Handle<Expression>> {
        let mut builtins: Vec<(BuiltinVar, Handle<naga::GlobalVariable>)> =
            self.cx.builtins.iter().map(|(k, v)| (*k, *v)).collect();
        builtins.sort_by_key(|(k, _)| *k);
        let mut frag_coord_arg = None;
        for &(b, var) in &builtins {
            if b == BuiltinVar::DrawId {
                let value = self
                    .load_internal(InternalUniform::DrawId)
                    .unwrap_or_else(|| self.lit(Literal::I32(0)));
                self.store_private(var, value);
                continue;
            }
            let (builtin, ty) = match b {
                BuiltinVar::VertexId => (naga::BuiltIn::VertexIndex, Type::UINT),
                BuiltinVar::InstanceId => (naga::BuiltIn::InstanceIndex, Type::UINT),
                BuiltinVar::FragCoord => (
                    naga::BuiltIn::Position { invariant: false },
                    Type::Vector(ScalarKind::Float, 4),
                ),
                BuiltinVar::FrontFacing => (naga::BuiltIn::FrontFacing, Type::BOOL),
                BuiltinVar::PointCoord => (
                    naga::BuiltIn::PointCoord,
                    Type::Vector(ScalarKind::Float, 2),
                ),
                _ => continue,
            };
            let nty = self.ty(&ty);
            let mut value = self.argument(b.name().into(), nty, naga::Binding::BuiltIn(builtin));
            match b {
                BuiltinVar::VertexId | BuiltinVar::InstanceId => {
                    value = self.cast(value, naga::ScalarKind::Sint, Span::default())
                }
                BuiltinVar::FragCoord => {
                    frag_coord_arg = Some(value);
                    value = self.flip_frag_coord(value);
                }
                BuiltinVar::PointCoord if self.cx.options.flip_clip_y => {
                    value = self.flip_point_coord(value);
                }
                _ => {}
            }
            self.store_private(var, value);
        }
        frag_coord_arg
    }

    /// The value the renderer provides as `what`, loaded from the default uniform block, where
    /// the plan gave this stage one.
    fn load_internal(&mut self, what: InternalUniform) -> Option<Handle<Expression>> {
        let (block, member) = *self.cx.internal.get(&what)?;
        let sp = Span::default();
        let bp = self.add(Expression::GlobalVariable(block), sp);
        let mp = self.access_index(bp, member, sp);
        Some(self.add(Expression::Load { pointer: mp }, sp))
    }

    /// A fragment shader's `gl_ClipDistance`: the two `vec4` varyings the vertex stage writes
    /// it to, copied into its private array.
    fn copy_clip_distance_input(&mut self, plan: &StagePlan) {
        let (Stage::Fragment, Some(&var), Some(loc)) = (
            self.cx.stage,
            self.cx.builtins.get(&BuiltinVar::ClipDistance),
            plan.clip_varying,
        ) else {
            return;
        };
        let vec4 = Type::Vector(ScalarKind::Float, 4);
        let nty = self.ty(&vec4);
        for k in 0..2u32 {
            let arg = self.argument(
                format!("gl_ClipDistance_{k}"),
                nty,
                clip_varying_binding(loc + k),
            );
            for c in 0..4u32 {
                let v = self.access_index(arg, c, Span::default());
                let p = self.leaf_pointer(var, &[k * 4 + c]);
                self.push(
                    Statement::Store {
                        pointer: p,
                        value: v,
                    },
                    Span::default(),
                );
            }
        }
    }

    /// A vertex shader's `gl_ClipDistance`: the API's clip distances (each 0, which clips
    /// nothing, where the switches say the distance is disabled), and the two `vec4` varyings
    /// that carry the values to a fragment shader that reads them.
    fn clip_distance_outputs(&mut self, plan: &StagePlan, out: &mut Outputs) {
        let sp = Span::default();
        let var = self.cx.builtins.get(&BuiltinVar::ClipDistance).copied();
        if var.is_none() && plan.clip_varying.is_none() {
            return;
        }
        let n = crate::builtins::MAX_CLIP_DISTANCES;
        let zero = self.lit(Literal::F32(0.0));
        let values: Vec<Handle<Expression>> = (0..n)
            .map(|i| match var {
                Some(var) => {
                    let p = self.leaf_pointer(var, &[i]);
                    self.add(Expression::Load { pointer: p }, sp)
                }
                None => zero,
            })
            .collect();
        if var.is_some() {
            let mut clipped = values.clone();
            if let Some(mask) = self.load_internal(InternalUniform::ClipDistancesEnabled) {
                let none = self.lit(Literal::U32(0));
                for (i, d) in clipped.iter_mut().enumerate() {
                    let bit = self.lit(Literal::U32(1 << i));
                    let on = self.binop(naga::BinaryOperator::And, mask, bit, sp);
                    let on = self.binop(naga::BinaryOperator::NotEqual, on, none, sp);
                    *d = self.select(on, *d, zero, sp);
                }
            }
            let ty = Type::Array(Box::new(Type::FLOAT), n);
            let value = self.compose(&ty, clipped, sp);
            let nty = self.ty(&ty);
            out.push(
                "gl_ClipDistance".into(),
                nty,
                naga::Binding::BuiltIn(naga::BuiltIn::ClipDistances),
                value,
            );
        }
        if let Some(loc) = plan.clip_varying {
            let vec4 = Type::Vector(ScalarKind::Float, 4);
            let nty = self.ty(&vec4);
            for k in 0..2u32 {
                let parts = values[k as usize * 4..k as usize * 4 + 4].to_vec();
                let v = self.compose(&vec4, parts, sp);
                out.push(
                    format!("gl_ClipDistance_{k}"),
                    nty,
                    clip_varying_binding(loc + k),
                    v,
                );
            }
        }
    }

    /// `gl_FragCoord` with y counted from the top, when the options ask for it and the
    /// framebuffer height is in the default uniform block; else `value` as it is.
    fn flip_frag_coord(&mut self, value: Handle<Expression>) -> Handle<Expression> {
        if !self.cx.options.flip_frag_coord_y {
            return value;
        }
        let Some(h) = self.load_internal(InternalUniform::FramebufferHeight) else {
            return value;
        };
        let sp = Span::default();
        let x = self.access_index(value, 0, sp);
        let y = self.access_index(value, 1, sp);
        let z = self.access_index(value, 2, sp);
        let w = self.access_index(value, 3, sp);
        let fy = self.binop(naga::BinaryOperator::Subtract, h, y, sp);
        let value = self.compose(&Type::Vector(ScalarKind::Float, 4), vec![x, fy, z, w], sp);
        // Named so that a translation can point at it (essl-translate's comments).
        self.f
            .named_expressions
            .insert(value, "frag_coord_y_up".into());
        value
    }

    /// `gl_PointCoord` with t counted from the other side: (s, 1 − t), for an image drawn
    /// upside down ([`LowerOptions::flip_clip_y`](crate::program::LowerOptions::flip_clip_y)).
    fn flip_point_coord(&mut self, value: Handle<Expression>) -> Handle<Expression> {
        let sp = Span::default();
        let s = self.access_index(value, 0, sp);
        let t = self.access_index(value, 1, sp);
        let one = self.lit(Literal::F32(1.0));
        let ft = self.binop(naga::BinaryOperator::Subtract, one, t, sp);
        self.compose(&Type::Vector(ScalarKind::Float, 2), vec![s, ft], sp)
    }

    /// gl_FragDepth defaults to the fragment's depth (`gl_FragCoord.z`, an argument of its own
    /// when the shader does not read `gl_FragCoord`).
    fn default_frag_depth(&mut self, frag_coord_arg: Option<Handle<Expression>>) {
        let Some(&var) = self.cx.builtins.get(&BuiltinVar::FragDepth) else {
            return;
        };
        let fc = match frag_coord_arg {
            Some(v) => v,
            None => {
                let nty = self.ty(&Type::Vector(ScalarKind::Float, 4));
                self.argument(
                    "gl_FragCoord".into(),
                    nty,
                    naga::Binding::BuiltIn(naga::BuiltIn::Position { invariant: false }),
                )
            }
        };
        let z = self.access_index(fc, 2, Span::default());
        self.store_private(var, z);
    }

    /// A vertex shader's `gl_Position` (its depth mapped to 0..w and its y negated when
    /// asked) and `gl_PointSize`.
    fn vertex_builtin_outputs(&mut self, out: &mut Outputs) {
        let sp = Span::default();
        let var = self.cx.builtins[&BuiltinVar::Position];
        let mut pos = self.load_private(var);
        let control = self
            .cx
            .options
            .clip_control
            .then(|| self.clip_control_overrides());
        if self.cx.options.zero_to_one_depth {
            let x = self.access_index(pos, 0, sp);
            let y = self.access_index(pos, 1, sp);
            let z = self.access_index(pos, 2, sp);
            let w = self.access_index(pos, 3, sp);
            let zw = self.binop(naga::BinaryOperator::Add, z, w, sp);
            let half = self.lit(Literal::F32(0.5));
            let mut nz = self.binop(naga::BinaryOperator::Multiply, zw, half, sp);
            if let Some((_, zero_to_one)) = control {
                nz = self.select(zero_to_one, z, nz, sp);
            }
            pos = self.compose(&Type::Vector(ScalarKind::Float, 4), vec![x, y, nz, w], sp);
            // Named so that a translation can point at it (essl-translate's comments).
            self.f
                .named_expressions
                .insert(pos, "clip_position_depth_0_to_w".into());
        }
        if self.cx.options.flip_clip_y || control.is_some() {
            let x = self.access_index(pos, 0, sp);
            let y = self.access_index(pos, 1, sp);
            let z = self.access_index(pos, 2, sp);
            let w = self.access_index(pos, 3, sp);
            let neg = self.add(
                Expression::Unary {
                    op: naga::UnaryOperator::Negate,
                    expr: y,
                },
                sp,
            );
            let ny = match (control, self.cx.options.flip_clip_y) {
                (Some((upper_left, _)), true) => self.select(upper_left, y, neg, sp),
                (Some((upper_left, _)), false) => self.select(upper_left, neg, y, sp),
                (None, _) => neg,
            };
            pos = self.compose(&Type::Vector(ScalarKind::Float, 4), vec![x, ny, z, w], sp);
            self.f
                .named_expressions
                .insert(pos, "clip_position_y_flipped".into());
        }
        let invariant = self.cx.hir.invariant_all;
        let vec4 = self.ty(&Type::Vector(ScalarKind::Float, 4));
        out.push(
            "gl_Position".into(),
            vec4,
            naga::Binding::BuiltIn(naga::BuiltIn::Position { invariant }),
            pos,
        );
        if let Some(&var) = self.cx.builtins.get(&BuiltinVar::PointSize) {
            let v = self.load_private(var);
            let f32_ty = self.ty(&Type::FLOAT);
            out.push(
                "gl_PointSize".into(),
                f32_ty,
                naga::Binding::BuiltIn(naga::BuiltIn::PointSize),
                v,
            );
        }
    }

    /// `EXT_clip_control`'s two pipeline-overridable `bool`s, declared in the module, as
    /// values: (origin `UPPER_LEFT_EXT`, depth `ZERO_TO_ONE_EXT`).
    fn clip_control_overrides(&mut self) -> (Handle<Expression>, Handle<Expression>) {
        let bool_ty = self.ty(&Type::BOOL);
        let value = |fx: &mut Self, name: &str| {
            let module = &mut fx.cx.module;
            let init = module
                .global_expressions
                .append(Expression::Literal(Literal::Bool(false)), NSpan::UNDEFINED);
            let o = module.overrides.append(
                naga::Override {
                    name: Some(name.to_owned()),
                    id: None,
                    ty: bool_ty,
                    init: Some(init),
                },
                NSpan::UNDEFINED,
            );
            fx.add(Expression::Override(o), Span::default())
        };
        let upper_left = value(self, crate::program::CLIP_UPPER_LEFT);
        let zero_to_one = value(self, crate::program::CLIP_ZERO_TO_ONE);
        (upper_left, zero_to_one)
    }

    /// The shader's outputs, one member per leaf, read from their private variables.
    fn user_outputs(&mut self, plan: &StagePlan, out: &mut Outputs) {
        let hir = self.cx.hir;
        let varying = self.cx.stage == Stage::Vertex;
        for &(gi, loc) in &plan.outputs {
            let g = &hir.globals[gi];
            let GlobalLower::Private(var) = self.cx.globals[gi] else {
                continue;
            };
            let leaves = io_leaves(&g.ty, &hir.structs);
            for (i, (path, leaf_ty)) in leaves.iter().enumerate() {
                let ty = self.ty(leaf_ty);
                let p = self.leaf_pointer(var, path);
                let v = self.add(Expression::Load { pointer: p }, Span::default());
                let centroid = plan.output_centroid.get(&gi).copied().unwrap_or(g.centroid);
                let (name, binding) =
                    io_binding(g, centroid, leaves.len(), i, leaf_ty, loc, varying);
                out.push(name, ty, binding, v);
            }
        }
    }

    /// A GLSL ES 1.00 fragment shader's `gl_FragColor` (location 0, or every draw buffer's
    /// with `GL_EXT_draw_buffers` enabled, as `WEBGL_draw_buffers` says) or `gl_FragData[i]`
    /// (location `i`), when it writes them.
    fn frag_color_outputs(&mut self, out: &mut Outputs) {
        let vec4 = Type::Vector(ScalarKind::Float, 4);
        let interp = |location| naga::Binding::Location {
            location,
            interpolation: None,
            sampling: None,
            blend_src: None,
            per_primitive: false,
        };
        if let Some(&var) = self.cx.builtins.get(&BuiltinVar::FragColor) {
            let v = self.load_private(var);
            let ty = self.ty(&vec4);
            out.push("gl_FragColor".into(), ty, interp(0), v);
            let hir = self.cx.hir;
            if hir.frag_color_broadcast {
                for i in 1..hir.frag_data_len {
                    out.push(format!("gl_FragColor_{i}"), ty, interp(i), v);
                }
            }
        }
        if let Some(&var) = self.cx.builtins.get(&BuiltinVar::FragData) {
            for i in 0..self.cx.hir.frag_data_len.max(1) {
                let p = self.leaf_pointer(var, &[i]);
                let v = self.add(Expression::Load { pointer: p }, Span::default());
                let ty = self.ty(&vec4);
                out.push(format!("gl_FragData_{i}"), ty, interp(i), v);
            }
        }
    }

    /// A fragment shader's `gl_FragDepth`, when it has one.
    fn frag_depth_output(&mut self, out: &mut Outputs) {
        if let Some(&var) = self.cx.builtins.get(&BuiltinVar::FragDepth) {
            let v = self.load_private(var);
            let f32_ty = self.ty(&Type::FLOAT);
            out.push(
                "gl_FragDepth".into(),
                f32_ty,
                naga::Binding::BuiltIn(naga::BuiltIn::FragDepth),
                v,
            );
        }
    }

    /// Lays out the output struct, returns it, and makes it the entry point's result.
    fn return_outputs(&mut self, out: Outputs) {
        let Outputs {
            mut members,
            values,
        } = out;
        // Offsets: naga wants them laid out even for IO structs.
        let mut off = 0u32;
        for m in &mut members {
            let size = self.cx.module.types[m.ty]
                .inner
                .size(self.cx.module.to_ctx());
            let align = crate::lower::layout::naga_align(&self.cx.module, m.ty);
            off = off.div_ceil(align) * align;
            m.offset = off;
            off += size;
        }
        let span = off.div_ceil(16) * 16;
        let out_ty = self.cx.module.types.insert(
            naga::Type {
                name: Some(
                    if self.cx.stage == Stage::Vertex {
                        "_essl_VertexOutput"
                    } else {
                        "_essl_FragmentOutput"
                    }
                    .to_owned(),
                ),
                inner: naga::TypeInner::Struct { members, span },
            },
            NSpan::UNDEFINED,
        );
        let sp = Span::default();
        let r = self.add(
            Expression::Compose {
                ty: out_ty,
                components: values,
            },
            sp,
        );
        self.push(Statement::Return { value: Some(r) }, sp);
        self.f.result = Some(naga::FunctionResult {
            ty: out_ty,
            binding: None,
        });
    }
}
