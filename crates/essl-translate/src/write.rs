//! One stage in one target language, through naga's backend for it.
//!
//! Before writing, [`names::prepare`] gives the module names the backends keep, and for WGSL
//! [`points::drop_point_builtins`] removes what WGSL cannot say; after, for WGSL,
//! [`layout::sized_members`] spells out the std140 offsets and [`names::restore`] gives back
//! the GLSL names the namer changed. [`comments::annotate`] then explains what the lowering
//! added, in every text target; the other targets keep their namers' choices (each has its
//! own reserved words and rules).

use essl::Stage;
use naga::valid::ModuleInfo;
use naga::Module;

use crate::{comments, layout, names, points, Code, Options, Target, TranslateError};

/// Writes one lowered stage.
pub(crate) fn stage(
    module: &Module,
    info: &ModuleInfo,
    stage: Stage,
    language: &str,
    options: &Options,
) -> Result<Code, TranslateError> {
    let fail = |message: String| TranslateError::Write {
        target: options.target.name(),
        stage: stage.as_str(),
        message,
    };
    let original = module;
    let mut module = names::prepare(module);
    let mut notes = Vec::new();
    let revalidated;
    let mut info = info;
    if options.target == Target::Wgsl {
        let dropped = points::drop_point_builtins(&mut module);
        if dropped.point_size {
            notes.push(
                "gl_PointSize is left out: WebGPU draws every point one pixel wide (draw \
                 larger points as quads)."
                    .to_owned(),
            );
        }
        if dropped.point_coord {
            notes.push(
                "gl_PointCoord is (0.5, 0.5), the centre of WebGPU's one-pixel points.".to_owned(),
            );
        }
        if dropped != points::Dropped::default() {
            revalidated = naga::valid::Validator::new(
                naga::valid::ValidationFlags::all(),
                naga::valid::Capabilities::default(),
            )
            .validate(&module)
            .map_err(|e| fail(e.into_inner().to_string()))?;
            info = &revalidated;
        }
    }
    let naga_stage = match stage {
        Stage::Vertex => naga::ShaderStage::Vertex,
        Stage::Fragment => naga::ShaderStage::Fragment,
    };
    let text = match options.target {
        Target::Wgsl => {
            let flags = naga::back::wgsl::WriterFlags::empty();
            let text = naga::back::wgsl::write_string(&module, info, flags)
                .map_err(|e| fail(e.to_string()))?;
            let written = names::wgsl_names(&module);
            let text = layout::sized_members(&module, &written, &text);
            if options.restore_names {
                names::restore(&module, &written, &text)
            } else {
                text
            }
        }
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
    Ok(Code::Text(if options.comments {
        comments::annotate(&text, original, (stage, language), options, &notes)
    } else {
        text
    }))
}
