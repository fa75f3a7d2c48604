//! WGSL text from a prepared module: essl's writer ([`crate::wgsl`]) with the author's
//! comments ([`crate::source`]) and a header, read back by naga's WGSL front end and
//! validated; should that fail (a bug), naga's writer writes the module instead, and the
//! header says so.

use essl::{Shader, Stage};
use naga::valid::ModuleInfo;
use naga::Module;

use crate::{comments, layout, names, source, wgsl, Options, TranslateError};

/// What the header says when naga's writer wrote the WGSL.
pub const FALLBACK: &str = "Written by naga's WGSL writer: essl's own could not write this shader.";

/// The GLSL sources of a module and which one each function's spans point into.
pub(crate) struct Files<'a> {
    pub sources: &'a [&'a Shader],
    pub functions: Vec<Option<usize>>,
    pub entry_points: Vec<Option<usize>>,
}

impl<'a> Files<'a> {
    /// A module lowered from the one shader in `sources` (or from none).
    pub(crate) fn one(module: &Module, sources: &'a [&'a Shader]) -> Files<'a> {
        let file = (!sources.is_empty()).then_some(0);
        Files {
            sources,
            functions: module
                .functions
                .iter()
                .map(|(h, _)| file.filter(|_| module.functions.get_span(h).is_defined()))
                .collect(),
            entry_points: vec![file; module.entry_points.len()],
        }
    }
}

/// The module as WGSL: `what` and `notes` open the header.
pub(crate) fn text(
    module: &Module,
    info: &ModuleInfo,
    what: &str,
    notes: &[String],
    options: &Options,
    files: &Files,
) -> Result<String, TranslateError> {
    let mut anchors = source::Anchors::default();
    for (file, s) in files.sources.iter().enumerate() {
        anchors.add(file, s);
    }
    let texts: Vec<source::SourceText> = files
        .sources
        .iter()
        .map(|s| source::SourceText::new(s.file.text()))
        .collect();
    let raw: Vec<&str> = files.sources.iter().map(|s| s.file.text()).collect();
    let comment_notes = comments::Notes::new(options);
    let commented = |o: wgsl::Origin| match o {
        wgsl::Origin::Source { file, start, .. } => {
            options.comments && texts.get(file).is_some_and(|t| t.commented(start))
        }
        _ => false,
    };
    let input = wgsl::Input {
        module,
        info,
        function_files: files.functions.clone(),
        entry_files: files.entry_points.clone(),
        anchors: &anchors,
        module_scope_uniforms: options.uniforms == crate::Uniforms::ModuleScope,
        notes: &comment_notes,
        commented: &commented,
        texts: &raw,
    };
    let author: Vec<Vec<String>> = texts.iter().map(|t| t.header()).collect();
    if let Ok(lines) = wgsl::write(&input) {
        let header = if options.comments {
            comments::header(what, notes, &author) + "\n"
        } else {
            String::new()
        };
        let text = header + &source::assemble(&lines, &texts, options.comments);
        if crate::roundtrip::read_wgsl(&text, Stage::Vertex).is_ok() {
            return Ok(text);
        }
    }
    // naga's writer, with essl's names and offsets.
    let flags = naga::back::wgsl::WriterFlags::empty();
    let text =
        naga::back::wgsl::write_string(module, info, flags).map_err(|e| TranslateError::Write {
            target: "wgsl",
            stage: "this",
            message: e.to_string(),
        })?;
    let written = names::wgsl_names(module);
    let text = layout::sized_members(module, &written, &text);
    let text = if options.restore_names {
        names::restore(module, &written, &text)
    } else {
        text
    };
    let mut notes = notes.to_vec();
    notes.push(FALLBACK.into());
    Ok(format!("{}{text}", comments::header(what, &notes, &[])))
}
