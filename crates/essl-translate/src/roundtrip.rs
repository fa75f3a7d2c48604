//! WGSL text read back into naga IR, to run what a user would run.
//!
//! A translation is only as good as the text it writes. [`through_wgsl`] writes both stages of
//! a lowered program as WGSL exactly as [`crate::translate_program`] does (names, comments),
//! parses the text with naga's WGSL front end, validates it, and puts the new modules in the
//! program's place. A renderer that takes naga IR (`essl-gl`, through its
//! `set_program_filter`) then draws from the WGSL text instead of from essl's IR; the
//! binding map is the same, since the text keeps every group, binding and location.

use essl::program::ProgramLayout;
use essl::Stage;
use naga::valid::{ModuleInfo, ValidationFlags, Validator};
use naga::Module;

use crate::{write, Code, Options, Target, TranslateError};

/// Parses and validates WGSL text as naga's WGSL front end does for wgpu.
pub fn read_wgsl(text: &str, stage: Stage) -> Result<(Module, ModuleInfo), TranslateError> {
    let fail = |message: String| TranslateError::Reparse {
        stage: stage.as_str(),
        message,
    };
    let module = naga::front::wgsl::parse_str(text).map_err(|e| fail(e.emit_to_string(text)))?;
    let info = Validator::new(ValidationFlags::all(), essl::lower::capabilities())
        .validate(&module)
        .map_err(|e| fail(e.emit_to_string(text)))?;
    Ok((module, info))
}

/// The program with each stage written as WGSL (with `options`' names and comments) and
/// read back. `options.target` is ignored: the text is WGSL.
pub fn through_wgsl(
    mut layout: ProgramLayout,
    options: &Options,
) -> Result<ProgramLayout, TranslateError> {
    let options = Options {
        target: Target::Wgsl,
        ..options.clone()
    };
    for stage in [Stage::Vertex, Stage::Fragment] {
        let (module, info) = match stage {
            Stage::Vertex => (&mut layout.vertex, &mut layout.vertex_info),
            Stage::Fragment => (&mut layout.fragment, &mut layout.fragment_info),
        };
        let Code::Text(text) = write::stage(module, info, stage, "GLSL ES", &options, &[])? else {
            unreachable!("WGSL is text");
        };
        (*module, *info) = read_wgsl(&text, stage)?;
    }
    Ok(layout)
}
