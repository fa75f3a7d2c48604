//! Meshes: the `grid`, `sphere`, `cube` and `arrays` kinds of FORMAT.md, built in float64 with
//! the exact expressions given there, and how they are drawn.

use crate::format::{ArrayStreams, MeshSpec, Stream};
use std::f64::consts::PI;

/// A mesh: float64 vertex streams (flat, `position`/`normal` 3 a vertex, `uv` 2) and, unless it
/// is drawn with `drawArrays`, its triangle indices.
///
/// Generated meshes have all three streams; an `arrays` mesh has those it was given.
#[derive(Clone, Debug, PartialEq)]
pub struct Mesh {
    /// Positions, 3 a vertex.
    pub position: Option<Vec<f64>>,
    /// Normals, 3 a vertex.
    pub normal: Option<Vec<f64>>,
    /// Texture coordinates, 2 a vertex.
    pub uv: Option<Vec<f64>>,
    /// Triangle indices (three a triangle, counter-clockwise from the front), or `None` for
    /// `drawArrays`.
    pub indices: Option<Vec<u32>>,
    vertex_count: usize,
}

/// The index type of a `drawElements` call.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum IndexType {
    /// `UNSIGNED_SHORT`: the mesh has at most 65536 vertices.
    U16,
    /// `UNSIGNED_INT`: more than 65536 vertices.
    U32,
}

impl IndexType {
    /// The GL enum's name, as `--dump` writes it (`"UNSIGNED_SHORT"`).
    pub fn gl_name(self) -> &'static str {
        match self {
            IndexType::U16 => "UNSIGNED_SHORT",
            IndexType::U32 => "UNSIGNED_INT",
        }
    }
}

/// How the mesh is drawn (always `TRIANGLES`, from offset 0).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Draw {
    /// `drawElements(TRIANGLES, count, type, 0)`.
    Elements {
        /// Index type.
        index_type: IndexType,
        /// Number of indices.
        count: usize,
    },
    /// `drawArrays(TRIANGLES, 0, count)`.
    Arrays {
        /// Number of vertices.
        count: usize,
    },
}

/// The indices of a grid-like mesh of `rows` × `cols` quads with `cols + 1` vertices a row:
/// `a, c, b` (unless `skip_first`) then `b, c, d` (unless `skip_second`) for each quad.
fn quad_indices(
    rows: u32,
    cols: u32,
    skip_first: impl Fn(u32) -> bool,
    skip_second: impl Fn(u32) -> bool,
) -> Vec<u32> {
    let mut idx = Vec::with_capacity(rows as usize * cols as usize * 6);
    for j in 0..rows {
        for i in 0..cols {
            let a = j * (cols + 1) + i;
            let (b, c) = (a + 1, a + cols + 1);
            let d = c + 1;
            if !skip_first(j) {
                idx.extend([a, c, b]);
            }
            if !skip_second(j) {
                idx.extend([b, c, d]);
            }
        }
    }
    idx
}

/// Per cube face: normal, right, up with `cross(right, up) == normal`; order +X −X +Y −Y +Z −Z.
const CUBE_FACES: [[[i32; 3]; 3]; 6] = [
    [[1, 0, 0], [0, 0, -1], [0, 1, 0]],
    [[-1, 0, 0], [0, 0, 1], [0, 1, 0]],
    [[0, 1, 0], [1, 0, 0], [0, 0, -1]],
    [[0, -1, 0], [1, 0, 0], [0, 0, 1]],
    [[0, 0, 1], [1, 0, 0], [0, 1, 0]],
    [[0, 0, -1], [-1, 0, 0], [0, 1, 0]],
];

/// Corners top-left, bottom-left, bottom-right, top-right: (right sign, up sign, u, v).
const CUBE_CORNERS: [(i32, i32, f64, f64); 4] = [
    (-1, 1, 0.0, 0.0),
    (-1, -1, 0.0, 1.0),
    (1, -1, 1.0, 1.0),
    (1, 1, 1.0, 0.0),
];

impl Mesh {
    /// Builds the mesh a (validated, see [`crate::SceneFile::validate`]) spec describes.
    pub fn build(spec: &MeshSpec) -> Mesh {
        match spec {
            MeshSpec::Grid { size, cells } => Mesh::grid(*size, *cells),
            MeshSpec::Sphere {
                radius,
                segments,
                rings,
            } => Mesh::sphere(*radius, *segments, *rings),
            MeshSpec::Cube { size } => Mesh::cube(*size),
            MeshSpec::Arrays {
                attributes,
                indices,
            } => Mesh::arrays(attributes, indices.clone()),
        }
    }

    /// The plane `y = 0` facing +y: vertex `j * (N + 1) + i` at
    /// `((-S)/2 + (S*i)/N, 0, (-S)/2 + (S*j)/N)`, normal +y, uv `(i/N, j/N)`; `2·N·N` triangles.
    pub fn grid(size: f64, cells: u32) -> Mesh {
        let n = f64::from(cells);
        let verts = (cells as usize + 1).pow(2);
        let (mut pos, mut nor, mut uv) = (
            Vec::with_capacity(verts * 3),
            Vec::with_capacity(verts * 3),
            Vec::with_capacity(verts * 2),
        );
        for j in 0..=cells {
            let j = f64::from(j);
            for i in 0..=cells {
                let i = f64::from(i);
                pos.extend([-size / 2.0 + size * i / n, 0.0, -size / 2.0 + size * j / n]);
                nor.extend([0.0, 1.0, 0.0]);
                uv.extend([i / n, j / n]);
            }
        }
        Mesh::generated(
            pos,
            nor,
            uv,
            quad_indices(cells, cells, |_| false, |_| false),
        )
    }

    /// The UV sphere: vertex `j * (s + 1) + i` with `theta = (π*j)/t`, `phi = ((2π)*i)/s`,
    /// `n = (sin θ · sin φ, cos θ, sin θ · cos φ)`, position `r·n`, uv `(i/s, j/t)`;
    /// `2·s·(t−1)` triangles (the degenerate ones at the poles left out).
    pub fn sphere(radius: f64, segments: u32, rings: u32) -> Mesh {
        let (s, t) = (f64::from(segments), f64::from(rings));
        let verts = (segments as usize + 1) * (rings as usize + 1);
        let (mut pos, mut nor, mut uv) = (
            Vec::with_capacity(verts * 3),
            Vec::with_capacity(verts * 3),
            Vec::with_capacity(verts * 2),
        );
        for j in 0..=rings {
            let j = f64::from(j);
            let theta = PI * j / t;
            for i in 0..=segments {
                let i = f64::from(i);
                let phi = 2.0 * PI * i / s;
                let n = [
                    theta.sin() * phi.sin(),
                    theta.cos(),
                    theta.sin() * phi.cos(),
                ];
                pos.extend([radius * n[0], radius * n[1], radius * n[2]]);
                nor.extend(n);
                uv.extend([i / s, j / t]);
            }
        }
        let last = rings - 1;
        let idx = quad_indices(rings, segments, |j| j == 0, |j| j == last);
        Mesh::generated(pos, nor, uv, idx)
    }

    /// The cube of edge `size` (FORMAT.md's 24-vertex table, `h = size / 2`).
    pub fn cube(size: f64) -> Mesh {
        let h = size / 2.0;
        let (mut pos, mut nor, mut uv, mut idx) = (vec![], vec![], vec![], vec![]);
        for (f, [n, r, u]) in CUBE_FACES.iter().enumerate() {
            for &(sr, su, cu, cv) in &CUBE_CORNERS {
                for k in 0..3 {
                    pos.push(h * f64::from(n[k] + sr * r[k] + su * u[k]));
                }
                nor.extend(n.map(f64::from));
                uv.extend([cu, cv]);
            }
            let f = 4 * f as u32;
            idx.extend([f, f + 1, f + 2, f, f + 2, f + 3]);
        }
        Mesh::generated(pos, nor, uv, idx)
    }

    /// Given data (validated: whole, equal vertex counts; indices in range).
    pub fn arrays(streams: &ArrayStreams, indices: Option<Vec<u32>>) -> Mesh {
        let vertex_count = Stream::ALL
            .into_iter()
            .find_map(|s| streams.get(s).map(|d| d.len() / s.components()))
            .unwrap_or(0);
        Mesh {
            position: streams.position.clone(),
            normal: streams.normal.clone(),
            uv: streams.uv.clone(),
            indices,
            vertex_count,
        }
    }

    fn generated(pos: Vec<f64>, nor: Vec<f64>, uv: Vec<f64>, idx: Vec<u32>) -> Mesh {
        let vertex_count = pos.len() / 3;
        Mesh {
            position: Some(pos),
            normal: Some(nor),
            uv: Some(uv),
            indices: Some(idx),
            vertex_count,
        }
    }

    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.vertex_count
    }

    /// The float64 data of a stream, if the mesh has it.
    pub fn stream(&self, s: Stream) -> Option<&[f64]> {
        match s {
            Stream::Position => self.position.as_deref(),
            Stream::Normal => self.normal.as_deref(),
            Stream::Uv => self.uv.as_deref(),
        }
    }

    /// The streams the mesh has, in the order position, normal, uv.
    pub fn streams(&self) -> Vec<Stream> {
        Stream::ALL
            .into_iter()
            .filter(|&s| self.stream(s).is_some())
            .collect()
    }

    /// A stream as uploaded: each value rounded once to `f32`.
    pub fn stream_f32(&self, s: Stream) -> Option<Vec<f32>> {
        self.stream(s)
            .map(|d| d.iter().map(|&x| x as f32).collect())
    }

    /// Vertex `v` of a stream as float64 (3 or 2 values), if the mesh has the stream.
    pub fn vertex(&self, s: Stream, v: usize) -> Option<&[f64]> {
        let n = s.components();
        self.stream(s).and_then(|d| d.get(v * n..v * n + n))
    }

    /// The index type the tool picks: `U16` for at most 65536 vertices, else `U32`.
    pub fn index_type(&self) -> IndexType {
        if self.vertex_count <= 65536 {
            IndexType::U16
        } else {
            IndexType::U32
        }
    }

    /// The draw call.
    pub fn draw(&self) -> Draw {
        match &self.indices {
            Some(idx) => Draw::Elements {
                index_type: self.index_type(),
                count: idx.len(),
            },
            None => Draw::Arrays {
                count: self.vertex_count,
            },
        }
    }

    /// Number of triangles drawn.
    pub fn triangle_count(&self) -> usize {
        match &self.indices {
            Some(idx) => idx.len() / 3,
            None => self.vertex_count / 3,
        }
    }

    /// The vertex indices of each triangle, in draw order (`0, 1, 2, …` for `drawArrays`).
    pub fn triangles(&self) -> Vec<[u32; 3]> {
        match &self.indices {
            Some(idx) => idx.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect(),
            None => (0..self.triangle_count() as u32)
                .map(|t| [3 * t, 3 * t + 1, 3 * t + 2])
                .collect(),
        }
    }

    /// The index buffer's bytes as uploaded (little-endian `u16` or `u32` per
    /// [`Mesh::index_type`]), or `None` for `drawArrays`.
    pub fn index_bytes(&self) -> Option<Vec<u8>> {
        let idx = self.indices.as_ref()?;
        Some(match self.index_type() {
            IndexType::U16 => idx.iter().flat_map(|&i| (i as u16).to_le_bytes()).collect(),
            IndexType::U32 => idx.iter().flat_map(|&i| i.to_le_bytes()).collect(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cube_matches_formats_table() {
        let m = Mesh::cube(2.0);
        assert_eq!(m.vertex_count(), 24);
        // Rows 0, 6, 13 and 23 of FORMAT.md's table with h = 1.
        assert_eq!(m.vertex(Stream::Position, 0).unwrap(), &[1.0, 1.0, 1.0]);
        assert_eq!(m.vertex(Stream::Position, 6).unwrap(), &[-1.0, -1.0, 1.0]);
        assert_eq!(m.vertex(Stream::Uv, 6).unwrap(), &[1.0, 1.0]);
        assert_eq!(m.vertex(Stream::Position, 13).unwrap(), &[-1.0, -1.0, -1.0]);
        assert_eq!(m.vertex(Stream::Normal, 13).unwrap(), &[0.0, -1.0, 0.0]);
        assert_eq!(m.vertex(Stream::Position, 23).unwrap(), &[-1.0, 1.0, -1.0]);
        assert_eq!(m.vertex(Stream::Uv, 23).unwrap(), &[1.0, 0.0]);
        assert_eq!(
            &m.indices.as_ref().unwrap()[30..],
            &[20, 21, 22, 20, 22, 23]
        );
        // Every triangle is counter-clockwise seen from its normal's side.
        for [a, b, c] in m.triangles() {
            let p = |v: u32| m.vertex(Stream::Position, v as usize).unwrap().to_vec();
            let (pa, pb, pc) = (p(a), p(b), p(c));
            let e1 = [pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]];
            let e2 = [pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2]];
            let n = crate::matrix::cross(e1, e2);
            let vn = m.vertex(Stream::Normal, a as usize).unwrap();
            assert!(crate::matrix::dot(&n, vn) > 0.0);
        }
    }

    #[test]
    fn grid_layout() {
        let m = Mesh::grid(2.0, 2);
        assert_eq!(m.vertex_count(), 9);
        assert_eq!(m.vertex(Stream::Position, 5).unwrap(), &[1.0, 0.0, 0.0]);
        assert_eq!(m.vertex(Stream::Uv, 5).unwrap(), &[1.0, 0.5]);
        assert_eq!(&m.indices.as_ref().unwrap()[..6], &[0, 3, 1, 1, 3, 4]);
        assert_eq!(m.triangle_count(), 8);
        assert_eq!(
            m.draw(),
            Draw::Elements {
                index_type: IndexType::U16,
                count: 24
            }
        );
    }

    #[test]
    fn sphere_counts_and_poles() {
        let m = Mesh::sphere(1.0, 8, 6);
        assert_eq!(m.vertex_count(), 9 * 7);
        assert_eq!(m.triangle_count(), 2 * 8 * 5);
        assert_eq!(m.vertex(Stream::Position, 0).unwrap(), &[0.0, 1.0, 0.0]);
        let south = m.vertex(Stream::Position, 6 * 9 + 1).unwrap();
        assert_eq!(south[1], -1.0);
        assert!(south[0] != 0.0 && south[0].abs() < 1e-15);
    }

    #[test]
    fn large_grid_uses_u32_indices() {
        assert_eq!(Mesh::grid(1.0, 255).index_type(), IndexType::U16);
        assert_eq!(Mesh::grid(1.0, 256).index_type(), IndexType::U32);
    }
}
