//! `generate_mipmap`: levels computed on the CPU by averaging blocks of the base level (in
//! linear space for sRGB formats).

use super::format::Comp;
use super::is_texture_target;
use super::object::{mip_size, Level};
use crate::context::Context;
use crate::gl;

impl Context {
    /// Computes levels `base + 1..` of the texture bound to `target` from its base level by
    /// averaging 2×2 (2×2×2 in 3D) blocks (`generateMipmap`). The base level must exist and
    /// be colour-renderable and filterable (`INVALID_OPERATION` otherwise): an 8-bit
    /// normalized or unsized format, a 16-bit float one once `EXT_color_buffer_float` (or
    /// `_half_float`) is on, a 32-bit float one once `OES_texture_float_linear` is on too; a
    /// cube map's faces must match.
    pub fn generate_mipmap(&mut self, target: u32) {
        const F: &str = "generateMipmap";
        if self.webgl1_refuses("generateMipmap", &[target]) {
            return;
        }
        if !is_texture_target(target) {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        }
        let Some(id) = self.bound_texture(target, F) else {
            return;
        };
        let t = self
            .objects
            .textures
            .get(id)
            .expect("bound textures are live");
        let (base, _) = t.level_range();
        let faces = if target == gl::TEXTURE_CUBE_MAP { 6 } else { 1 };
        let Some(first) = t.level(0, base).cloned() else {
            return self.error(gl::INVALID_OPERATION, F, "the base level has no image");
        };
        if first.width == 0 || first.height == 0 || first.depth == 0 {
            return self.error(gl::INVALID_OPERATION, F, "the base level is empty");
        }
        let x = &self.extensions;
        if self.webgl1.on && !(first.width.is_power_of_two() && first.height.is_power_of_two()) {
            return self.error(
                gl::INVALID_OPERATION,
                F,
                "WebGL 1: the base level's size is not a power of two",
            );
        }
        let mipmappable = match first.format.comp {
            Comp::Unorm8 => true,
            Comp::F16 => x.color_buffer_float,
            Comp::F32 => x.color_buffer_float && x.texture_float_linear,
            _ => false,
        };
        if !mipmappable
            || first.format.packing != super::format::Packing::None
            || first.format.base == super::compressed::COMPRESSED_BASE
            || (self.webgl1.on && first.format.srgb)
        {
            return self.error(
                gl::INVALID_OPERATION,
                F,
                "format is not colour-renderable and filterable",
            );
        }
        for face in 1..faces {
            let same = t.level(face, base).is_some_and(|l| {
                (l.width, l.height, l.format) == (first.width, first.height, first.format)
            });
            if !same {
                return self.error(gl::INVALID_OPERATION, F, "cube map is not cube complete");
            }
        }
        let three_d = target == gl::TEXTURE_3D;
        let largest = if three_d {
            first.width.max(first.height).max(first.depth)
        } else {
            first.width.max(first.height)
        };
        let mut last = base + (31 - largest.leading_zeros());
        if let Some(n) = t.immutable_levels {
            last = last.min(n - 1);
        }
        // A base level drawn into on the GPU comes back to the CPU first.
        for face in 0..faces {
            let on_gpu = self
                .objects
                .textures
                .get(id)
                .and_then(|t| t.level(face, base))
                .is_some_and(|l| l.data.is_none());
            if on_gpu {
                let data = self.read_texture_level(id, face, base);
                let t = self
                    .objects
                    .textures
                    .get_mut(id)
                    .expect("bound textures are live");
                let l = t.level_mut(face, base).expect("checked");
                l.data = Some(data);
            }
        }
        let t = self
            .objects
            .textures
            .get_mut(id)
            .expect("bound textures are live");
        for face in 0..faces {
            let mut src = t.level(face, base).cloned().expect("checked");
            for level in base + 1..=last {
                let dst = downsample(&src, three_d);
                t.set_level(face, level, dst.clone());
                src = dst;
            }
        }
    }
}

pub(super) fn srgb_to_linear(c: u8) -> f32 {
    let c = c as f32 / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

pub(super) fn linear_to_srgb(l: f32) -> u8 {
    let c = if l <= 0.003_130_8 {
        l * 12.92
    } else {
        1.055 * l.powf(1.0 / 2.4) - 0.055
    };
    (c * 255.0 + 0.5).clamp(0.0, 255.0) as u8
}

/// A component of a texel as a float (8-bit normalized, 16- or 32-bit float storage).
fn read_component(comp: Comp, bytes: &[u8]) -> f32 {
    match comp {
        Comp::F16 => super::f16_to_f32(u16::from_ne_bytes([bytes[0], bytes[1]])),
        Comp::F32 => f32::from_ne_bytes([bytes[0], bytes[1], bytes[2], bytes[3]]),
        _ => bytes[0] as f32 / 255.0,
    }
}

/// Stores a float component as `comp` does (8-bit normalized values rounded).
fn write_component(comp: Comp, v: f32, out: &mut [u8]) {
    match comp {
        Comp::F16 => out.copy_from_slice(&super::format::f32_to_f16(v).to_ne_bytes()),
        Comp::F32 => out.copy_from_slice(&v.to_ne_bytes()),
        _ => out[0] = (v * 255.0 + 0.5) as u8,
    }
}

/// The next level of an image: each texel the mean of its 2×2(×2) block.
pub(super) fn downsample(src: &Level, three_d: bool) -> Level {
    let (w, h) = (mip_size(src.width, 1), mip_size(src.height, 1));
    let d = if three_d {
        mip_size(src.depth, 1)
    } else {
        src.depth
    };
    let n = src.format.texel_size();
    let srgb = src.format.srgb;
    let comp = src.format.comp;
    let size = comp.size();
    let zero = [0u8; 4];
    let empty = Vec::new();
    let src_data = src.data.as_ref().unwrap_or(&empty);
    let mut data = vec![0u8; w as usize * h as usize * d as usize * n];
    let at = |x: u32, y: u32, z: u32| ((z * src.height + y) * src.width + x) as usize * n;
    for z in 0..d {
        let zs: Vec<u32> = if three_d {
            vec![(2 * z).min(src.depth - 1), (2 * z + 1).min(src.depth - 1)]
        } else {
            vec![z]
        };
        for y in 0..h {
            let ys = [(2 * y).min(src.height - 1), (2 * y + 1).min(src.height - 1)];
            for x in 0..w {
                let xs = [(2 * x).min(src.width - 1), (2 * x + 1).min(src.width - 1)];
                for c in 0..n / size {
                    let mut sum = 0.0f32;
                    let mut count = 0.0f32;
                    for &sz in &zs {
                        for sy in ys {
                            for sx in xs {
                                let i = at(sx, sy, sz) + c * size;
                                let v = src_data.get(i..i + size).unwrap_or(&zero[..size]);
                                sum += if srgb && c % 4 != 3 {
                                    srgb_to_linear(v[0])
                                } else {
                                    read_component(comp, v)
                                };
                                count += 1.0;
                            }
                        }
                    }
                    let mean = sum / count;
                    let o = ((z * h + y) * w + x) as usize * n + c * size;
                    if srgb && c % 4 != 3 {
                        data[o] = linear_to_srgb(mean);
                    } else {
                        write_component(comp, mean, &mut data[o..o + size]);
                    }
                }
            }
        }
    }
    Level::new([w, h, d], src.format, data)
}
