//! What a linked program's transform feedback captures: each varying's words, in one
//! interleaved buffer or one buffer each, checked against ES 3.0's limits.

use essl::program::{CaptureSource as Source, ProgramLayout};
use essl::types::GlType;

use super::interface::ActiveInfo;
use super::linker::LinkError;
use crate::gl;
use crate::shader_patch::{CaptureSource, CaptureSpec, CaptureValue};

/// `MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS`, `MAX_TRANSFORM_FEEDBACK_SEPARATE_COMPONENTS`
/// and `MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS`: ES 3.0's minimums.
pub(crate) const MAX_SEPARATE_ATTRIBS: u32 = 4;
pub(crate) const MAX_SEPARATE_COMPONENTS: u32 = 4;
pub(crate) const MAX_INTERLEAVED_COMPONENTS: u32 = 64;

/// What a linked program's transform feedback captures.
#[derive(Clone, Debug)]
pub(crate) struct Feedback {
    /// `INTERLEAVED_ATTRIBS` or `SEPARATE_ATTRIBS`.
    pub(crate) mode: u32,
    /// The varyings, as `get_transform_feedback_varying` reports them.
    pub(crate) varyings: Vec<ActiveInfo>,
    /// The words each draw writes per vertex, and where.
    pub(crate) spec: CaptureSpec,
}

impl Feedback {
    /// Words per vertex record of buffer `b`.
    pub(crate) fn stride(&self, b: u32) -> u32 {
        self.spec
            .values
            .iter()
            .filter(|v| v.buffer == b)
            .map(|v| v.stride)
            .next()
            .unwrap_or(0)
    }
}

/// Components of one location of a type (a matrix column, a vector, a scalar).
fn location_words(ty: GlType) -> u32 {
    use essl::types::Type;
    match ty.to_type() {
        Type::Matrix { rows, .. } => rows as u32,
        Type::Vector(_, n) => n as u32,
        _ => 1,
    }
}

/// The capture layout of the varyings `names` in `layout`, or why the link fails.
pub(crate) fn feedback_layout(
    layout: &ProgramLayout,
    names: &[String],
    mode: u32,
) -> Result<Option<Feedback>, LinkError> {
    if names.is_empty() {
        return Ok(None);
    }
    let separate = mode == gl::SEPARATE_ATTRIBS;
    let mut values = Vec::new();
    let mut varyings = Vec::new();
    let mut offset = 0;
    for (i, name) in names.iter().enumerate() {
        if names[..i].contains(name) {
            return Err(LinkError::Feedback(format!(
                "transform feedback varying {name} is named twice"
            )));
        }
        let Some(c) = layout.captured.iter().find(|c| c.name == *name) else {
            return Err(LinkError::Feedback(format!(
                "transform feedback varying {name} is not an output of the vertex shader"
            )));
        };
        let per = location_words(c.ty);
        let locations: Vec<CaptureSource> = match c.source {
            Source::Location { first, count } => (first..first + count)
                .map(CaptureSource::Location)
                .collect(),
            Source::Position => vec![CaptureSource::Position],
            Source::PointSize => vec![CaptureSource::PointSize],
        };
        let words = per * locations.len() as u32;
        if separate && words > MAX_SEPARATE_COMPONENTS {
            return Err(LinkError::Feedback(format!(
                "transform feedback varying {name} has {words} components: more than MAX_TRANSFORM_FEEDBACK_SEPARATE_COMPONENTS"
            )));
        }
        let buffer = if separate { i as u32 } else { 0 };
        if separate {
            offset = 0;
        }
        for source in locations {
            values.push(CaptureValue {
                source,
                words: per,
                buffer,
                offset,
                stride: 0,
            });
            offset += per;
        }
        varyings.push(ActiveInfo {
            name: name.clone(),
            size: c.size,
            ty: c.ty as u32,
        });
    }
    let buffers = if separate { names.len() as u32 } else { 1 };
    if separate && buffers > MAX_SEPARATE_ATTRIBS {
        return Err(LinkError::Feedback(
            "more transform feedback varyings than MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS".into(),
        ));
    }
    if !separate && offset > MAX_INTERLEAVED_COMPONENTS {
        return Err(LinkError::Feedback(format!(
            "{offset} interleaved transform feedback components: more than MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS"
        )));
    }
    for b in 0..buffers {
        let stride: u32 = values
            .iter()
            .filter(|v| v.buffer == b)
            .map(|v| v.words)
            .sum();
        for v in values.iter_mut().filter(|v| v.buffer == b) {
            v.stride = stride;
        }
    }
    Ok(Some(Feedback {
        mode,
        varyings,
        spec: CaptureSpec { values, buffers },
    }))
}
