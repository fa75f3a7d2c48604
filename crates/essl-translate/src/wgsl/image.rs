//! Texture reads: `textureSample…`, `textureLoad`, `textureDimensions`…, as naga's WGSL
//! writer spells them.

use naga::{Expression, SampleLevel};

use super::doc::Doc;
use super::expr::{call, W};
use super::func::FnCtx;
use crate::TranslateError;

impl FnCtx<'_> {
    /// A texture read or query.
    pub(crate) fn image(&self, e: &Expression) -> Result<W, TranslateError> {
        let v = |h| -> Result<Doc, TranslateError> { Ok(self.value(h, false)?.doc) };
        Ok(match *e {
            Expression::ImageSample {
                image,
                sampler,
                gather,
                coordinate,
                array_index,
                offset,
                level,
                depth_ref,
                clamp_to_edge,
            } => {
                let compare = if depth_ref.is_some() { "Compare" } else { "" };
                let mut args = Vec::new();
                let name = match gather {
                    Some(component) => {
                        let depth = matches!(
                            self.shape.ty(image),
                            naga::TypeInner::Image {
                                class: naga::ImageClass::Depth { .. },
                                ..
                            }
                        );
                        if !depth {
                            args.push(Doc::text((component as u8).to_string()));
                        }
                        format!("textureGather{compare}")
                    }
                    None => {
                        let suffix = match level {
                            SampleLevel::Auto => "",
                            SampleLevel::Zero if clamp_to_edge => "BaseClampToEdge",
                            SampleLevel::Zero | SampleLevel::Exact(_) => "Level",
                            SampleLevel::Bias(_) => "Bias",
                            SampleLevel::Gradient { .. } => "Grad",
                        };
                        format!("textureSample{compare}{suffix}")
                    }
                };
                args.extend([v(image)?, v(sampler)?, v(coordinate)?]);
                if let Some(a) = array_index {
                    args.push(v(a)?);
                }
                if let Some(d) = depth_ref {
                    args.push(v(d)?);
                }
                if gather.is_none() {
                    match level {
                        SampleLevel::Auto => {}
                        SampleLevel::Zero => {
                            if depth_ref.is_none() && !clamp_to_edge {
                                args.push(Doc::text("0.0"));
                            }
                        }
                        SampleLevel::Exact(x) | SampleLevel::Bias(x) => args.push(v(x)?),
                        SampleLevel::Gradient { x, y } => {
                            args.push(v(x)?);
                            args.push(v(y)?);
                        }
                    }
                }
                if let Some(o) = offset {
                    args.push(v(o)?);
                }
                call(&name, args)
            }
            Expression::ImageLoad {
                image,
                coordinate,
                array_index,
                sample,
                level,
            } => {
                let mut args = vec![v(image)?, v(coordinate)?];
                if let Some(a) = array_index {
                    args.push(v(a)?);
                }
                if let Some(i) = sample.or(level) {
                    args.push(v(i)?);
                }
                call("textureLoad", args)
            }
            Expression::ImageQuery { image, query } => {
                let (name, level) = match query {
                    naga::ImageQuery::Size { level } => ("textureDimensions", level),
                    naga::ImageQuery::NumLevels => ("textureNumLevels", None),
                    naga::ImageQuery::NumLayers => ("textureNumLayers", None),
                    naga::ImageQuery::NumSamples => ("textureNumSamples", None),
                };
                let mut args = vec![v(image)?];
                if let Some(l) = level {
                    args.push(v(l)?);
                }
                call(name, args)
            }
            _ => return Err(self.unsupported("a texture expression".into())),
        })
    }
}
