//! The float64 reference shader of a library scene.

use glam::{DVec2, DVec3, DVec4};

use super::{mat, sample_texture, FragmentIn, RefShader, VertexIn};
use crate::error::LightsError;

/// The float64 reference of a library scene: [`crate::ideal`]'s model as a [`RefShader`],
/// staged like the generated shaders — Phong shading interpolates the world position and
/// normal and evaluates per pixel; Gouraud evaluates at the vertices (world position
/// `model · p`, normal `normalize(normalMatrix · n)`) and interpolates the colours, screen
/// cookies applied per pixel.
pub struct LitShader {
    scene: crate::LitScene,
    prepared: crate::PreparedScene,
    model: glam::DMat4,
    normal: glam::DMat3,
    eye: DVec3,
    inv_viewport: DVec2,
    shift: f64,
    offset: DVec3,
}

impl LitShader {
    /// The reference shader of `scene` seen from `view`.
    pub fn new(scene: &crate::LitScene, view: &crate::View) -> Result<LitShader, LightsError> {
        let prepared = scene.prepare()?;
        let nm = view.normal_matrix()?;
        let inv_viewport = if prepared.shape.has_screen_cookie() {
            view.inv_viewport()?
        } else {
            view.inv_viewport().unwrap_or([0.0, 0.0])
        };
        Ok(LitShader {
            scene: scene.clone(),
            prepared,
            model: mat(&view.matrices.model),
            normal: glam::DMat3::from_cols_array(&nm),
            eye: DVec3::from_array(view.matrices.eye),
            inv_viewport: DVec2::from_array(inv_viewport),
            shift: 0.0,
            offset: DVec3::ZERO,
        })
    }

    /// The same shader with every world position moved by `offset` before lighting (the
    /// reference band of a float32 GPU's interpolated position near a singular point, such as a
    /// light on the surface).
    pub fn with_offset(mut self, offset: DVec3) -> LitShader {
        self.offset = offset;
        self
    }

    /// The same shader with both cone cosines of every spot light moved by `shift` (the
    /// reference band of a hard edge: see [`band`] and [`crate::stiff::BAND`]).
    pub fn with_shift(mut self, shift: f64) -> LitShader {
        self.shift = shift;
        self
    }

    fn cookie(&self, i: usize, uv: DVec2) -> DVec3 {
        match &self.scene.lights[i] {
            crate::Light::Spot(s) => match &s.cookie {
                Some(c) => {
                    let img = c.image();
                    sample_texture(img.width, img.height, &img.texels, img.filter, img.wrap, uv)
                        .truncate()
                }
                None => DVec3::ONE,
            },
            _ => DVec3::ONE,
        }
    }
}

impl RefShader for LitShader {
    fn vertex(&self, v: &VertexIn) -> Vec<f64> {
        let p = (self.model * v.position.extend(1.0)).truncate() + self.offset;
        let n = self.normal * v.normal;
        match self.scene.shading {
            crate::Shading::Phong => vec![p.x, p.y, p.z, n.x, n.y, n.z],
            crate::Shading::Gouraud => {
                let s = crate::ideal::Surface {
                    position: p,
                    normal: n,
                    eye: self.eye,
                    frag_coord: DVec2::ZERO,
                };
                let t = crate::ideal::terms(
                    &self.scene,
                    &self.prepared,
                    &s,
                    &|i, uv| self.cookie(i, uv),
                    self.inv_viewport,
                    crate::ideal::TermOptions {
                        shift: self.shift,
                        defer_screen: true,
                    },
                );
                let mut out = t.base.to_array().to_vec();
                for (_, c) in t.deferred {
                    out.extend(c.to_array());
                }
                out
            }
        }
    }

    fn fragment(&self, f: &FragmentIn<'_>) -> DVec4 {
        let v = f.varyings;
        let rgb = match self.scene.shading {
            crate::Shading::Phong => {
                let s = crate::ideal::Surface {
                    position: DVec3::new(v[0], v[1], v[2]),
                    normal: DVec3::new(v[3], v[4], v[5]),
                    eye: self.eye,
                    frag_coord: f.frag_coord,
                };
                crate::ideal::terms(
                    &self.scene,
                    &self.prepared,
                    &s,
                    &|i, uv| self.cookie(i, uv),
                    self.inv_viewport,
                    crate::ideal::TermOptions {
                        shift: self.shift,
                        defer_screen: false,
                    },
                )
                .base
            }
            crate::Shading::Gouraud => {
                let mut c = DVec3::new(v[0], v[1], v[2]);
                let screen = self.prepared.lights.iter().enumerate().filter(|(_, l)| {
                    matches!(
                        l.shape,
                        crate::LightShape::Spot {
                            cookie: Some(crate::CookieKind::Screen),
                            ..
                        }
                    )
                });
                for (k, (i, _)) in screen.enumerate() {
                    let o = 3 + 3 * k;
                    let uv = crate::ideal::screen_uv(f.frag_coord, self.inv_viewport);
                    c += self.cookie(i, uv) * DVec3::new(v[o], v[o + 1], v[o + 2]);
                }
                c
            }
        };
        rgb.extend(1.0)
    }
}
