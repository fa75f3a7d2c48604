//! Textures: the RGBA8 texels of `checker` and `pixels` textures, their sampling state, and the
//! texture-unit assignment (units follow the sorted order of the sampler names).

use crate::format::{Filter, OrderedMap, TextureSpec, Wrap};

/// A built texture, as `texImage2D(TEXTURE_2D, 0, RGBA8, width, height, 0, RGBA, UNSIGNED_BYTE,
/// texels)` receives it: data row 0 first (texture row `y` is sampled at `t ∈ [y/h, (y+1)/h]`).
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    /// The `sampler2D` uniform's name.
    pub name: String,
    /// The texture unit (`TEXTURE0 + unit`, and the value `uniform1i` sets).
    pub unit: u32,
    /// Width in texels.
    pub width: u32,
    /// Height in texels.
    pub height: u32,
    /// `width * height * 4` bytes, RGBA, row 0 first, no padding (`UNPACK_ALIGNMENT = 1`).
    pub texels: Vec<u8>,
    /// MIN and MAG filter (no mipmaps).
    pub filter: Filter,
    /// S and T wrap mode.
    pub wrap: Wrap,
}

impl Texture {
    /// Builds a (validated) texture spec's texels.
    pub fn build(name: &str, unit: u32, spec: &TextureSpec) -> Texture {
        let (width, height, texels) = match spec {
            TextureSpec::Checker {
                size,
                cells,
                colors,
                ..
            } => (*size, *size, checker_texels(*size, *cells, colors)),
            TextureSpec::Pixels {
                width,
                height,
                data,
                ..
            } => (*width, *height, data.clone()),
        };
        Texture {
            name: name.to_string(),
            unit,
            width,
            height,
            texels,
            filter: spec.filter(),
            wrap: spec.wrap(),
        }
    }

    /// The RGBA of texel (x, y), row `y` counted from data row 0.
    pub fn texel(&self, x: u32, y: u32) -> [u8; 4] {
        let i = (y as usize * self.width as usize + x as usize) * 4;
        [
            self.texels[i],
            self.texels[i + 1],
            self.texels[i + 2],
            self.texels[i + 3],
        ]
    }
}

/// `size`×`size` texels, texel (x, y) = `colors[((x*cells) div size + (y*cells) div size) mod 2]`.
pub fn checker_texels(size: u32, cells: u32, colors: &[[u8; 4]; 2]) -> Vec<u8> {
    let (size64, cells64) = (u64::from(size), u64::from(cells));
    let mut out = Vec::with_capacity(size as usize * size as usize * 4);
    for y in 0..size64 {
        for x in 0..size64 {
            let k = ((x * cells64) / size64 + (y * cells64) / size64) % 2;
            out.extend_from_slice(&colors[k as usize]);
        }
    }
    out
}

/// Builds every texture of a scene with its unit: unit `k` for the `k`-th name in code-point
/// order (a name whose sampler is not active still takes its unit).
pub fn build_textures(specs: &OrderedMap<TextureSpec>) -> Vec<Texture> {
    let mut names: Vec<(&str, &TextureSpec)> = specs.iter().collect();
    names.sort_by(|a, b| a.0.cmp(b.0));
    names
        .into_iter()
        .enumerate()
        .map(|(unit, (name, spec))| Texture::build(name, unit as u32, spec))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checker_corner_and_cells() {
        let c = [[255, 255, 255, 255], [0, 0, 0, 255]];
        let t = Texture::build(
            "t",
            0,
            &TextureSpec::Checker {
                size: 8,
                cells: 2,
                colors: c,
                filter: Filter::Nearest,
                wrap: Wrap::Repeat,
            },
        );
        assert_eq!(t.texels.len(), 8 * 8 * 4);
        assert_eq!(t.texel(0, 0), c[0]);
        assert_eq!(t.texel(3, 3), c[0]);
        assert_eq!(t.texel(4, 0), c[1]);
        assert_eq!(t.texel(0, 4), c[1]);
        assert_eq!(t.texel(7, 7), c[0]);
    }

    #[test]
    fn units_follow_sorted_names() {
        let spec = |w| TextureSpec::Pixels {
            width: w,
            height: 1,
            data: vec![0; w as usize * 4],
            filter: Filter::Linear,
            wrap: Wrap::Clamp,
        };
        let map = OrderedMap(vec![
            ("u_b".to_string(), spec(1)),
            ("u_B".to_string(), spec(2)),
            ("u_a".to_string(), spec(3)),
        ]);
        let t = build_textures(&map);
        let got: Vec<(&str, u32, u32)> = t
            .iter()
            .map(|t| (t.name.as_str(), t.unit, t.width))
            .collect();
        assert_eq!(got, vec![("u_B", 0, 2), ("u_a", 1, 3), ("u_b", 2, 1)]);
    }
}
