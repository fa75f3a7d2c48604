//! One stage in one target language.
//!
//! Before writing, [`names::prepare`] gives the module names the writers keep, and
//! [`ir::inverse`] replaces `inverse()` where the target has none. WGSL is written by essl's
//! own writer ([`crate::wgsl`]) from the restructured IR ([`ir::restructure`]), with the
//! author's comments put back ([`crate::source`]); the text is read back by naga's WGSL front
//! end, and should it not validate (a bug), naga's writer writes the stage instead, as the
//! header then says. The other targets go through naga's writers, then [`names::restore_in`]
//! gives back the GLSL names their namers changed and [`comments::annotate`] explains what
//! the lowering added.

use essl::{Shader, Stage};
use naga::valid::ModuleInfo;
use naga::Module;

use crate::{comments, ir, names, points, Code, Options, Target, TranslateError};

/// Writes one lowered stage; `sources` are the shaders its spans point into (none when the
/// stage is written without its GLSL, as [`crate::roundtrip`] does).
pub(crate) fn stage(
    module: &Module,
    info: &ModuleInfo,
    stage: Stage,
    language: &str,
    options: &Options,
    sources: &[&Shader],
) -> Result<Code, TranslateError> {
    let fail = |message: String| TranslateError::Write {
        target: options.target.name(),
        stage: stage.as_str(),
        message,
    };
    let original = module;
    let Prepared {
        module,
        info,
        notes,
    } = prepare(module, info, options.target).map_err(fail)?;
    if options.target == Target::Wgsl {
        let what = format!(
            "The {} shader, translated from WebGL's {language} by essl.",
            stage.as_str()
        );
        let (module, info) = ir::restructure::restructure(&module).unwrap_or((module, info));
        let files = crate::wgsl_text::Files::one(&module, sources);
        let text = crate::wgsl_text::text(&module, &info, &what, &notes, options, &files)?;
        return Ok(Code::Text(text));
    }
    let info = &info;
    let naga_stage = match stage {
        Stage::Vertex => naga::ShaderStage::Vertex,
        Stage::Fragment => naga::ShaderStage::Fragment,
    };
    let text = match options.target {
        Target::Wgsl => unreachable!("written above"),
        Target::SpirV => {
            let mut spv = naga::back::spv::Options::default();
            spv.flags.set(naga::back::spv::WriterFlags::DEBUG, false);
            let pipeline = naga::back::spv::PipelineOptions {
                shader_stage: naga_stage,
                entry_point: "main".into(),
            };
            let words = naga::back::spv::write_vec(&module, info, &spv, Some(&pipeline))
                .map_err(|e| fail(e.to_string()))?;
            return Ok(Code::SpirV(words));
        }
        Target::Msl => {
            let msl = naga::back::msl::Options {
                lang_version: (2, 1),
                fake_missing_bindings: true,
                ..Default::default()
            };
            let pipeline = naga::back::msl::PipelineOptions {
                entry_point: Some((naga_stage, "main".into())),
                ..Default::default()
            };
            naga::back::msl::write_string(&module, info, &msl, &pipeline)
                .map_err(|e| fail(e.to_string()))?
                .0
        }
        Target::Hlsl => {
            let hlsl = naga::back::hlsl::Options {
                shader_model: naga::back::hlsl::ShaderModel::V5_1,
                fake_missing_bindings: true,
                ..Default::default()
            };
            let pipeline = naga::back::hlsl::PipelineOptions {
                entry_point: Some((naga_stage, "main".into())),
            };
            let mut text = String::new();
            naga::back::hlsl::Writer::new(&mut text, &hlsl, &pipeline)
                .write(&module, info, None)
                .map_err(|e| fail(e.to_string()))?;
            text
        }
        Target::Glsl => {
            let glsl = naga::back::glsl::Options {
                version: naga::back::glsl::Version::Desktop(450),
                writer_flags: naga::back::glsl::WriterFlags::empty(),
                ..Default::default()
            };
            let pipeline = naga::back::glsl::PipelineOptions {
                shader_stage: naga_stage,
                entry_point: "main".into(),
                multiview: None,
            };
            let mut text = String::new();
            naga::back::glsl::Writer::new(
                &mut text,
                &module,
                info,
                &glsl,
                &pipeline,
                naga::proc::BoundsCheckPolicies::default(),
            )
            .and_then(|mut w| w.write().map(|_| ()))
            .map_err(|e| fail(e.to_string()))?;
            text
        }
    };
    let text = if options.restore_names {
        names::restore_in(&module, options.target, &text)
    } else {
        text
    };
    Ok(Code::Text(if options.comments {
        comments::annotate(&text, original, (stage, language), options, &notes)
    } else {
        text
    }))
}

/// A linked program as one WGSL module ([`ir::merge`]), both stages written in it.
pub(crate) fn program_module(
    layout: &essl::program::ProgramLayout,
    shaders: [&Shader; 2],
    language: &str,
    options: &Options,
) -> Result<Code, TranslateError> {
    let fail = |message: String| TranslateError::Write {
        target: "wgsl",
        stage: "program",
        message,
    };
    let vertex = prepare(&layout.vertex, &layout.vertex_info, Target::Wgsl).map_err(fail)?;
    let fragment = prepare(&layout.fragment, &layout.fragment_info, Target::Wgsl).map_err(fail)?;
    let restructured =
        |p: Prepared| ir::restructure::restructure(&p.module).map_or(p.module, |(m, _)| m);
    let mut notes = vertex.notes.clone();
    notes.extend(
        fragment
            .notes
            .iter()
            .filter(|n| !vertex.notes.contains(n))
            .cloned(),
    );
    let merged = ir::merge::merge(&restructured(vertex), &restructured(fragment))
        .ok_or_else(|| fail("the two stages do not make one module".into()))?;
    let files = crate::wgsl_text::Files {
        sources: &shaders,
        functions: merged
            .function_files
            .iter()
            .zip(merged.module.functions.iter())
            .map(|(file, (h, _))| {
                merged
                    .module
                    .functions
                    .get_span(h)
                    .is_defined()
                    .then_some(*file)
            })
            .collect(),
        entry_points: vec![Some(0), Some(1)],
    };
    let [vs_main, fs_main] = ir::merge::ENTRY_POINTS;
    let what = format!(
        "The vertex and fragment shaders of a program, translated from WebGL's {language} by \
         essl: entry points `{vs_main}` and `{fs_main}`."
    );
    let text =
        crate::wgsl_text::text(&merged.module, &merged.info, &what, &notes, options, &files)?;
    Ok(Code::Text(text))
}

/// A lowered module ready for a target's writer, with the notes its header gives.
pub(crate) struct Prepared {
    pub module: Module,
    pub info: ModuleInfo,
    pub notes: Vec<String>,
}

/// The module with names the writers keep ([`names::prepare`]), `inverse()` as a function
/// where the target has none, and (WGSL) the point built-ins WGSL lacks left out.
pub(crate) fn prepare(
    module: &Module,
    info: &ModuleInfo,
    target: Target,
) -> Result<Prepared, String> {
    let mut module = names::prepare(module);
    let mut notes = Vec::new();
    let mut changed = false;
    if matches!(target, Target::Wgsl | Target::Msl | Target::Hlsl) {
        changed |= ir::inverse::lower_inverse(&mut module).unwrap_or(false);
    }
    if target == Target::Wgsl {
        let dropped = points::drop_point_builtins(&mut module);
        if dropped.point_size {
            notes.push(
                "gl_PointSize is left out: WebGPU's points are one pixel (draw larger ones as \
                 quads)."
                    .to_owned(),
            );
        }
        if dropped.point_coord {
            notes.push(
                "gl_PointCoord is (0.5, 0.5), the centre of WebGPU's one-pixel points.".to_owned(),
            );
        }
        changed |= dropped != points::Dropped::default();
    }
    let info = if changed {
        naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            essl::lower::capabilities(),
        )
        .validate(&module)
        .map_err(|e| e.into_inner().to_string())?
    } else {
        info.clone()
    };
    Ok(Prepared {
        module,
        info,
        notes,
    })
}
