//! The module's declarations, grouped as WGSL code keeps them: the shader's structs (in the
//! order the GLSL declared them), the uniform buffer and its bindings, textures and samplers,
//! constants and private variables, the functions (in the source's order), then each entry
//! point with the struct it returns.

use std::collections::HashSet;

use naga::proc::NameKey;
use naga::{AddressSpace, Binding, Handle, Module, TypeInner};

use super::analysis::{self, Shape};
use super::doc::Doc;
use super::func::FnCtx;
use super::names::ModuleNames;
use super::stmt::push_doc;
use super::{bake, Env, Input, Line, Origin};
use crate::layout::Sizes;
use crate::TranslateError;

type Result<T> = std::result::Result<T, TranslateError>;

/// Writes the module; an error for what the writer does not write.
pub(crate) fn write(input: &Input) -> Result<Vec<Line>> {
    let module = input.module;
    let unsupported = module
        .functions
        .iter()
        .map(|(_, f)| f)
        .chain(module.entry_points.iter().map(|e| &e.function))
        .any(|f| !analysis::supported(f));
    if unsupported || !module.overrides.is_empty() {
        return Err(TranslateError::Write {
            target: "wgsl",
            stage: "this",
            message: "a construct essl's WGSL writer does not write".into(),
        });
    }
    let names = ModuleNames::new(module);
    let uniforms = module.global_variables.iter().find_map(|(h, g)| {
        (g.space == AddressSpace::Uniform && g.name.as_deref() == Some("_essl_uniforms"))
            .then_some(h)
    });
    let note_for = |name: &str| input.notes.named(name);
    let env = Env {
        module,
        names,
        writes: bake::function_writes(module),
        uniforms,
        module_scope_uniforms: input.module_scope_uniforms,
        note_for: &note_for,
        texts: input.texts,
    };
    let mut w = ModuleWriter {
        input,
        env: &env,
        sizes: crate::layout::struct_sizes(module),
        out: Vec::new(),
        written: HashSet::new(),
    };
    // WGSL names the extensions a module uses before any declaration.
    let clip_distances = module.types.iter().any(|(_, t)| match &t.inner {
        naga::TypeInner::Struct { members, .. } => members
            .iter()
            .any(|m| m.binding == Some(Binding::BuiltIn(naga::BuiltIn::ClipDistances))),
        _ => false,
    });
    if clip_distances {
        w.out
            .push(Line::new(0, "enable clip_distances;".into(), Origin::None));
        w.out.push(Line::new(0, String::new(), Origin::None));
    }
    w.structs()?;
    w.bindings()?;
    w.privates()?;
    w.functions()?;
    w.entry_points()?;
    while w.out.last().is_some_and(|l| l.text.is_empty()) {
        w.out.pop();
    }
    Ok(w.out)
}

struct ModuleWriter<'a> {
    input: &'a Input<'a>,
    env: &'a Env<'a>,
    sizes: std::collections::HashMap<Handle<naga::Type>, Sizes>,
    out: Vec<Line>,
    written: HashSet<Handle<naga::Type>>,
}

impl ModuleWriter<'_> {
    fn module(&self) -> &Module {
        self.input.module
    }

    fn names(&self) -> &ModuleNames {
        &self.env.names
    }

    fn blank(&mut self) {
        if self.out.last().is_some_and(|l| !l.text.is_empty()) {
            self.out.push(Line::blank());
        }
    }

    /// The shader's own structs, in the order its source declared them.
    fn structs(&mut self) -> Result<()> {
        let module = self.module();
        let special: HashSet<Handle<naga::Type>> = module
            .special_types
            .predeclared_types
            .values()
            .copied()
            .collect();
        let mut late: HashSet<Handle<naga::Type>> = module
            .global_variables
            .iter()
            .filter(|(_, g)| g.space == AddressSpace::Uniform)
            .map(|(_, g)| g.ty)
            .collect();
        late.extend(
            module
                .entry_points
                .iter()
                .filter_map(|e| e.function.result.as_ref().map(|r| r.ty)),
        );
        type Keyed = (Option<(usize, u32)>, usize, Handle<naga::Type>);
        let mut structs: Vec<Keyed> = module
            .types
            .iter()
            .filter(|(h, t)| {
                matches!(t.inner, TypeInner::Struct { .. })
                    && !special.contains(h)
                    && !late.contains(h)
            })
            .map(|(h, t)| {
                let at = self.type_anchor(t.name.as_deref()).and_then(sort_key);
                (at, h.index(), h)
            })
            .collect();
        structs.sort_by_key(|(at, i, _)| (at.is_some(), *at, *i));
        for (_, _, h) in structs {
            self.write_struct(h, Vec::new());
        }
        self.written.extend(special);
        Ok(())
    }

    fn type_anchor(&self, name: Option<&str>) -> Option<Origin> {
        let name = name?;
        let name = name.strip_suffix("_std140").unwrap_or(name);
        self.input.anchors.lookup(name)
    }

    fn write_struct(&mut self, h: Handle<naga::Type>, notes: Vec<String>) {
        if self.names().same_as.contains_key(&h) || !self.written.insert(h) {
            return;
        }
        let module = self.input.module;
        let TypeInner::Struct { members, .. } = &module.types[h].inner else {
            return;
        };
        self.blank();
        let name = self.names().get(NameKey::Type(h)).to_owned();
        let original = module.types[h].name.clone().unwrap_or_default();
        let origin = self.type_anchor(Some(&original)).unwrap_or(Origin::None);
        let mut head = Line::new(0, format!("struct {name} {{"), origin);
        head.notes = notes;
        self.out.push(head);
        let sizes = self.sizes.get(&h).cloned().unwrap_or_default();
        if sizes.lead > 0 {
            let mut pad = Line::new(
                1,
                format!("@size({}) _padding: u32,", sizes.lead),
                Origin::None,
            );
            pad.notes.extend(self.input.notes.padding.clone());
            self.out.push(pad);
        }
        let struct_name = original
            .strip_suffix("_std140")
            .unwrap_or(&original)
            .to_owned();
        for (i, m) in members.iter().enumerate() {
            let mut text = String::new();
            if let Some(b) = &m.binding {
                text.push_str(&attributes(b));
            }
            if let Some(size) = sizes.sizes.get(&i) {
                text.push_str(&format!("@size({size}) "));
            }
            let member = self
                .names()
                .get(NameKey::StructMember(h, i as u32))
                .to_owned();
            let ty = self.env.types().name(m.ty);
            text.push_str(&format!("{member}: {ty},"));
            let glsl = m.name.clone().unwrap_or_default();
            let origin = self
                .input
                .anchors
                .member(&struct_name, &glsl)
                .or_else(|| self.input.anchors.lookup(&glsl))
                .unwrap_or(Origin::None);
            let mut line = Line::new(1, text, origin);
            let notes = &self.input.notes;
            match glsl.as_str() {
                "_essl_framebuffer_height" => line.notes.extend(notes.framebuffer_height.clone()),
                "_essl_draw_id" => line.notes.extend(notes.draw_id.clone()),
                _ => {}
            }
            self.out.push(line);
        }
        self.out.push(Line::new(0, "}".into(), Origin::Continued));
    }

    /// The uniform buffers (each after its struct), then textures and samplers.
    fn bindings(&mut self) -> Result<()> {
        let module = self.input.module;
        let mut buffers: Vec<_> = module
            .global_variables
            .iter()
            .filter(|(_, g)| g.space == AddressSpace::Uniform)
            .collect();
        buffers.sort_by_key(|(_, g)| g.binding.as_ref().map(|b| (b.group, b.binding)));
        for (h, g) in buffers {
            let notes = if Some(h) == self.env.uniforms {
                self.input
                    .notes
                    .uniform_buffer
                    .clone()
                    .into_iter()
                    .collect()
            } else {
                Vec::new()
            };
            self.write_struct(g.ty, notes);
            let line = self.global_line(h)?;
            self.out.push(line);
        }
        let mut handles: Vec<_> = module
            .global_variables
            .iter()
            .filter(|(_, g)| g.space == AddressSpace::Handle)
            .collect();
        handles.sort_by_key(|(_, g)| g.binding.as_ref().map(|b| (b.group, b.binding)));
        let mut first = true;
        for (h, _) in handles {
            if first
                && !self
                    .out
                    .last()
                    .is_some_and(|l| l.text.starts_with("@group"))
            {
                self.blank();
            }
            let mut line = self.global_line(h)?;
            if first {
                line.notes.extend(self.input.notes.samplers.clone());
                first = false;
            }
            self.out.push(line);
        }
        Ok(())
    }

    /// Named constants and private variables, in the source's order.
    fn privates(&mut self) -> Result<()> {
        let module = self.input.module;
        let mut lines = Vec::new();
        for (h, c) in module.constants.iter() {
            if c.name.is_none() {
                continue;
            }
            let name = self.names().get(NameKey::Constant(h)).to_owned();
            let ty = self.env.types().name(c.ty);
            let value = self.constant_text(c.init)?;
            let origin = self
                .input
                .anchors
                .lookup(c.name.as_deref().unwrap_or(""))
                .unwrap_or(Origin::None);
            lines.push(Line::new(
                0,
                format!("const {name}: {ty} = {value};"),
                origin,
            ));
        }
        let mut privates: Vec<_> = module
            .global_variables
            .iter()
            .filter(|(_, g)| !matches!(g.space, AddressSpace::Uniform | AddressSpace::Handle))
            .map(|(h, g)| {
                let origin = self
                    .input
                    .anchors
                    .lookup(g.name.as_deref().unwrap_or(""))
                    .unwrap_or(Origin::None);
                (sort_key(origin), h.index(), h, origin)
            })
            .collect();
        privates.sort_by_key(|(k, i, _, _)| (*k, *i));
        for (_, _, h, _) in privates {
            lines.push(self.global_line(h)?);
        }
        if !lines.is_empty() {
            self.blank();
            self.out.extend(lines);
        }
        Ok(())
    }

    /// A constant expression of the module, as text.
    fn constant_text(&self, init: Handle<naga::Expression>) -> Result<String> {
        Ok(super::expr::constant(self.env, init, false)?.doc.flat())
    }

    fn global_line(&self, h: Handle<naga::GlobalVariable>) -> Result<Line> {
        let module = self.input.module;
        let g = &module.global_variables[h];
        let name = self.names().get(NameKey::GlobalVariable(h));
        let ty = self.env.types().name(g.ty);
        let mut text = String::new();
        if let Some(b) = &g.binding {
            text.push_str(&format!("@group({}) @binding({}) ", b.group, b.binding));
        }
        let space = match g.space {
            AddressSpace::Uniform => "<uniform>",
            AddressSpace::Private => "<private>",
            AddressSpace::WorkGroup => "<workgroup>",
            _ => "",
        };
        text.push_str(&format!("var{space} {name}: {ty}"));
        if let Some(init) = g.init {
            text.push_str(&format!(" = {}", self.constant_text(init)?));
        }
        text.push(';');
        let origin = self
            .input
            .anchors
            .lookup(g.name.as_deref().unwrap_or(""))
            .unwrap_or(Origin::None);
        Ok(Line::new(0, text, origin))
    }

    /// The functions, in the order of their source.
    fn functions(&mut self) -> Result<()> {
        let module = self.input.module;
        let mut order: Vec<_> = module
            .functions
            .iter()
            .map(|(h, _)| {
                let file = self.input.function_files.get(h.index()).copied().flatten();
                let span = module.functions.get_span(h);
                let key = (file, span.to_range().map_or(u32::MAX, |r| r.start as u32));
                (key, h.index(), h)
            })
            .collect();
        order.sort_by_key(|(k, i, _)| (*k, *i));
        for (_, _, h) in order {
            let f = &module.functions[h];
            let info = &self.input.info[h];
            let file = self.input.function_files.get(h.index()).copied().flatten();
            let shape = Shape::new(module, f, info);
            let cx = FnCtx::new(self.env, &shape, file);
            let span = module.functions.get_span(h);
            let name = self.names().get(NameKey::Function(h)).to_owned();
            self.blank();
            let helper = !span.is_defined()
                && f.name
                    .as_deref()
                    .is_some_and(|n| crate::ir::inverse::HELPERS.contains(&n));
            let notes = if helper {
                self.input.notes.helper.clone().into_iter().collect()
            } else {
                Vec::new()
            };
            self.function(&cx, &name, span, None, notes)?;
        }
        Ok(())
    }

    fn entry_points(&mut self) -> Result<()> {
        let module = self.input.module;
        for (i, ep) in module.entry_points.iter().enumerate() {
            if let Some(r) = &ep.function.result {
                self.write_struct(r.ty, Vec::new());
            }
            let info = self.input.info.get_entry_point(i);
            let file = self.input.entry_files.get(i).copied().flatten();
            let shape = Shape::new(module, &ep.function, info);
            let cx = FnCtx::new(self.env, &shape, file);
            let name = self.names().get(NameKey::EntryPoint(i as u16)).to_owned();
            let stage = match ep.stage {
                naga::ShaderStage::Vertex => "@vertex",
                naga::ShaderStage::Fragment => "@fragment",
                _ => "@compute",
            };
            self.blank();
            let origin = file
                .and_then(|f| self.input.anchors.main(f))
                .unwrap_or(Origin::None);
            self.out.push(Line::new(0, stage.into(), origin));
            self.function(&cx, &name, naga::Span::UNDEFINED, Some(()), Vec::new())?;
        }
        Ok(())
    }

    /// `fn name(args) -> T {`, the body, `}`.
    fn function(
        &mut self,
        cx: &FnCtx,
        name: &str,
        span: naga::Span,
        entry: Option<()>,
        notes: Vec<String>,
    ) -> Result<()> {
        let f = cx.shape.function;
        let mut args = Vec::new();
        let mut origins = Vec::new();
        for (k, a) in f.arguments.iter().enumerate() {
            let mut text = a.binding.as_ref().map(attributes).unwrap_or_default();
            text.push_str(&format!(
                "{}: {}",
                cx.argument_name(k as u32),
                self.env.types().name(a.ty)
            ));
            args.push(Doc::text(text));
            let origin = a
                .name
                .as_deref()
                .and_then(|n| self.input.anchors.lookup(n))
                .unwrap_or(Origin::None);
            origins.push(origin);
        }
        let ret = match &f.result {
            Some(r) => {
                let attrs = r.binding.as_ref().map(attributes).unwrap_or_default();
                format!(" -> {attrs}{} {{", self.env.types().name(r.ty))
            }
            None => " {".to_owned(),
        };
        let head = Doc::Cat(vec![
            Doc::List {
                head: format!("fn {name}"),
                args: args.clone(),
            },
            Doc::text(ret.clone()),
        ]);
        let origin = match (entry, cx.file, span.to_range()) {
            (None, Some(file), Some(r)) => Origin::Source {
                file,
                start: r.start as u32,
                end: r.end as u32,
            },
            (None, ..) => Origin::None,
            (Some(()), ..) => Origin::Continued,
        };
        if entry.is_some() && origins.iter().any(|o| (self.input.commented)(*o)) {
            // An input the author commented: one argument a line, each under its comment.
            let mut first = Line::new(0, format!("fn {name}("), origin);
            first.notes = notes;
            self.out.push(first);
            for (a, o) in args.iter().zip(origins) {
                self.out.push(Line::new(1, format!("{},", a.flat()), o));
            }
            self.out
                .push(Line::new(0, format!("){}", ret), Origin::Continued));
        } else {
            push_doc(&mut self.out, 0, head, origin, notes);
        }
        cx.body(&mut self.out)?;
        self.out.push(Line::new(0, "}".into(), Origin::Continued));
        Ok(())
    }
}

/// The position an origin sorts at (none: last).
fn sort_key(o: Origin) -> Option<(usize, u32)> {
    match o {
        Origin::Source { file, start, .. } => Some((file, start)),
        _ => None,
    }
}

/// `@location(0) `, `@builtin(position) `, with interpolation as naga's writer writes it.
fn attributes(b: &Binding) -> String {
    use naga::common::wgsl::{ToWgsl, TryToWgsl};
    match *b {
        Binding::BuiltIn(builtin) => {
            let name = builtin.try_to_wgsl().unwrap_or("unknown");
            match builtin {
                naga::BuiltIn::Position { invariant: true } => {
                    format!("@builtin({name}) @invariant ")
                }
                _ => format!("@builtin({name}) "),
            }
        }
        Binding::Location {
            location,
            interpolation,
            sampling,
            blend_src,
            ..
        } => {
            let mut s = format!("@location({location}) ");
            if let Some(b) = blend_src {
                s.push_str(&format!("@blend_src({b}) "));
            }
            if sampling.is_some() && sampling != Some(naga::Sampling::Center) {
                let i = interpolation
                    .unwrap_or(naga::Interpolation::Perspective)
                    .to_wgsl();
                let smp = sampling.unwrap_or(naga::Sampling::Center).to_wgsl();
                s.push_str(&format!("@interpolate({i}, {smp}) "));
            } else if interpolation.is_some()
                && interpolation != Some(naga::Interpolation::Perspective)
            {
                let i = interpolation
                    .unwrap_or(naga::Interpolation::Perspective)
                    .to_wgsl();
                s.push_str(&format!("@interpolate({i}) "));
            }
            s
        }
    }
}
