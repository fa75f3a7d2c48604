//! Casting the rays: the mesh mode (Möller–Trumbore against the binned triangles) and the
//! exact mode (against the analytic surface).

use glam::{DMat4, DVec2, DVec3, DVec4};

use essl_scene::{MeshSpec, Scene};

use super::surfaces::{hit_cube, hit_plane, hit_sphere};
use super::{mat, FragmentIn, RefImage, RefShader, VertexIn};
use crate::error::LightsError;

/// The scene's camera in float64: what turns a pixel into a ray and a `gl_FragCoord`.
pub(super) struct Camera {
    /// The model-view-projection matrix.
    mvp: DMat4,
    /// Its inverse.
    inv: DMat4,
    /// Whether the model-view mirrors (GL decides facing in window space; in object space
    /// that is the orientation seen from the eye, reversed when the model-view mirrors).
    mirror: bool,
    /// The canvas width and height.
    size: (u32, u32),
    /// How far every ray is moved from the pixel centre, in pixels (x right, y down).
    offset: DVec2,
}

impl Camera {
    /// The camera of `scene`, rays moved by `offset`; an error when the matrix is singular.
    pub fn new(scene: &Scene, offset: DVec2) -> Result<Camera, LightsError> {
        let mvp = mat(&scene.matrices.model_view_projection);
        let inv = mvp.inverse();
        if !inv.is_finite() || mvp.determinant() == 0.0 {
            return Err(LightsError::Reference(
                "the model-view-projection matrix is singular".into(),
            ));
        }
        let mv3 = glam::DMat3::from_mat4(mat(&scene.matrices.model_view));
        Ok(Camera {
            mvp,
            inv,
            mirror: mv3.determinant() < 0.0,
            size: (scene.width(), scene.height()),
            offset,
        })
    }

    /// The ray through pixel (`x`, `row`) (row 0 at the top): its origin on the near plane
    /// and its direction to the far plane, in object space.
    fn ray(&self, x: u32, row: u32) -> (DVec3, DVec3) {
        let (w, h) = self.size;
        let ndc_x = 2.0 * (f64::from(x) + 0.5 + self.offset.x) / f64::from(w) - 1.0;
        let win_y = f64::from(h - 1 - row) + 0.5 - self.offset.y;
        let ndc_y = 2.0 * win_y / f64::from(h) - 1.0;
        let a = self.inv * DVec4::new(ndc_x, ndc_y, -1.0, 1.0);
        let b = self.inv * DVec4::new(ndc_x, ndc_y, 1.0, 1.0);
        let a = a.truncate() / a.w;
        let b = b.truncate() / b.w;
        (a, b - a)
    }

    /// How many [`TILE`]-pixel tiles cover the canvas across and down.
    fn tiles(&self) -> (u32, u32) {
        (self.size.0.div_ceil(TILE), self.size.1.div_ceil(TILE))
    }

    /// `gl_FragCoord.xy` of pixel (`x`, `row`): its centre, whatever the offset.
    fn frag_coord(&self, x: u32, row: u32) -> DVec2 {
        DVec2::new(f64::from(x) + 0.5, f64::from(self.size.1 - 1 - row) + 0.5)
    }
}

/// A triangle prepared for intersection.
struct Tri {
    idx: [usize; 3],
    p0: DVec3,
    e1: DVec3,
    e2: DVec3,
}

/// The nearest hit of a ray so far: ray parameter, triangle, barycentrics `u`, `v`, facing.
type MeshHit = (f64, usize, f64, f64, bool);

/// The side of the tiles triangles are binned into, in pixels.
const TILE: u32 = 8;

/// The mesh's vertices as the vertex stage reads them.
fn vertices(scene: &Scene) -> Result<Vec<VertexIn>, LightsError> {
    let mesh = &scene.mesh;
    let pos = mesh
        .position
        .as_ref()
        .ok_or_else(|| LightsError::Reference("the mesh has no positions".into()))?;
    let get3 = |s: &Option<Vec<f64>>, i: usize| -> DVec3 {
        s.as_ref()
            .map(|v| DVec3::new(v[3 * i], v[3 * i + 1], v[3 * i + 2]))
            .unwrap_or(DVec3::ZERO)
    };
    Ok((0..mesh.vertex_count())
        .map(|i| VertexIn {
            position: DVec3::new(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]),
            normal: get3(&mesh.normal, i),
            uv: mesh
                .uv
                .as_ref()
                .map(|v| DVec2::new(v[2 * i], v[2 * i + 1]))
                .unwrap_or(DVec2::ZERO),
        })
        .collect())
}

/// The tiles (x0, x1, y0, y1, inclusive) a triangle's window bounding box covers: all of
/// them when a vertex is behind the eye, none when it is wholly behind or off screen.
fn tiles_of(camera: &Camera, verts: &[VertexIn], t: &Tri) -> Option<(u32, u32, u32, u32)> {
    let (w, h) = camera.size;
    let (tw, th) = camera.tiles();
    let mut lo = DVec2::splat(f64::INFINITY);
    let mut hi = DVec2::splat(f64::NEG_INFINITY);
    let mut behind = 0;
    for &i in &t.idx {
        let c = camera.mvp * verts[i].position.extend(1.0);
        if c.w <= 0.0 {
            behind += 1;
            continue;
        }
        let win = DVec2::new(
            (c.x / c.w + 1.0) * 0.5 * f64::from(w),
            (1.0 - (c.y / c.w + 1.0) * 0.5) * f64::from(h),
        );
        lo = lo.min(win);
        hi = hi.max(win);
    }
    if behind == 3 {
        // Wholly behind the eye: clipped away.
        return None;
    }
    if behind > 0 {
        return Some((0, tw - 1, 0, th - 1));
    }
    if hi.x < -1.0 || hi.y < -1.0 || lo.x > f64::from(w) + 1.0 || lo.y > f64::from(h) + 1.0 {
        return None;
    }
    let tx = |v: f64, n: u32| ((v.max(0.0) / f64::from(TILE)) as u32).min(n - 1);
    Some((
        tx(lo.x - 1.0, tw),
        tx(hi.x + 1.0, tw),
        tx(lo.y - 1.0, th),
        tx(hi.y + 1.0, th),
    ))
}

/// The triangles binned into [`TILE`]-pixel tiles by their window bounding box.
fn bin(camera: &Camera, verts: &[VertexIn], tris: &[Tri]) -> Vec<Vec<usize>> {
    let (tw, th) = camera.tiles();
    let mut bins: Vec<Vec<usize>> = vec![Vec::new(); (tw * th) as usize];
    for (ti, t) in tris.iter().enumerate() {
        if let Some((x0, x1, y0, y1)) = tiles_of(camera, verts, t) {
            for ty in y0..=y1 {
                for tx in x0..=x1 {
                    bins[(ty * tw + tx) as usize].push(ti);
                }
            }
        }
    }
    bins
}

/// The nearest triangle of `bin` the ray hits (GL's `LESS` depth test: on a tie the earlier
/// triangle; without depth test the last one drawn), back faces skipped when `cull`.
fn nearest(
    (origin, dir): (DVec3, DVec3),
    tris: &[Tri],
    bin: &[usize],
    (cull, depth, mirror): (bool, bool, bool),
) -> Option<MeshHit> {
    let mut best: Option<MeshHit> = None;
    for &ti in bin {
        let t = &tris[ti];
        let pvec = dir.cross(t.e2);
        let det = t.e1.dot(pvec);
        if det == 0.0 || !det.is_finite() {
            continue;
        }
        let front = (det > 0.0) != mirror;
        if cull && !front {
            continue;
        }
        let inv_det = 1.0 / det;
        let tvec = origin - t.p0;
        let u = tvec.dot(pvec) * inv_det;
        if !(0.0..=1.0).contains(&u) {
            continue;
        }
        let qvec = tvec.cross(t.e1);
        let v = dir.dot(qvec) * inv_det;
        if v < 0.0 || u + v > 1.0 {
            continue;
        }
        let s = t.e2.dot(qvec) * inv_det;
        if !(0.0..=1.0).contains(&s) {
            continue;
        }
        let better = match best {
            None => true,
            Some((bs, bi, ..)) => {
                if depth {
                    s < bs || (s == bs && ti < bi)
                } else {
                    ti > bi
                }
            }
        };
        if better {
            best = Some((s, ti, u, v, front));
        }
    }
    best
}

/// Renders the scene's mesh: each pixel's ray against the triangles of its tile, the
/// nearest hit's varyings interpolated by its barycentrics.
pub(super) fn render_mesh(
    scene: &Scene,
    shader: &dyn RefShader,
    camera: &Camera,
    image: &mut RefImage,
) -> Result<(), LightsError> {
    let verts = vertices(scene)?;
    let varyings: Vec<Vec<f64>> = verts.iter().map(|v| shader.vertex(v)).collect();
    let nv = varyings.first().map_or(0, Vec::len);
    let tris: Vec<Tri> = scene
        .mesh
        .triangles()
        .into_iter()
        .map(|t| {
            let idx = t.map(|i| i as usize);
            let p0 = verts[idx[0]].position;
            Tri {
                idx,
                p0,
                e1: verts[idx[1]].position - p0,
                e2: verts[idx[2]].position - p0,
            }
        })
        .collect();
    let bins = bin(camera, &verts, &tris);
    let (w, h) = (image.width, image.height);
    let (tw, _) = camera.tiles();
    let tests = (scene.cull_face(), scene.depth_test(), camera.mirror);
    let mut interp = vec![0.0; nv];
    for row in 0..h {
        for x in 0..w {
            let bin = &bins[((row / TILE) * tw + x / TILE) as usize];
            let Some((_, ti, u, v, front)) = nearest(camera.ray(x, row), &tris, bin, tests) else {
                continue;
            };
            let t = &tris[ti];
            let b = [1.0 - u - v, u, v];
            for (k, slot) in interp.iter_mut().enumerate() {
                *slot = b[0] * varyings[t.idx[0]][k]
                    + b[1] * varyings[t.idx[1]][k]
                    + b[2] * varyings[t.idx[2]][k];
            }
            let c = shader.fragment(&FragmentIn {
                varyings: &interp,
                frag_coord: camera.frag_coord(x, row),
                front_facing: front,
            });
            let i = (row * w + x) as usize;
            image.pixels[i] = c;
            image.coverage[i] = true;
        }
    }
    Ok(())
}

/// Renders the analytic surface the scene's mesh tessellates, the vertex stage run at each
/// exact hit point.
pub(super) fn render_exact(
    scene: &Scene,
    shader: &dyn RefShader,
    camera: &Camera,
    image: &mut RefImage,
) -> Result<(), LightsError> {
    let spec = scene.file.mesh.clone();
    if matches!(spec, MeshSpec::Arrays { .. }) {
        return Err(LightsError::Reference(
            "an arrays mesh has no analytic surface for the exact mode".into(),
        ));
    }
    let cull = scene.cull_face();
    let mirror = camera.mirror;
    let (w, h) = (image.width, image.height);
    for row in 0..h {
        for x in 0..w {
            let (o, d) = camera.ray(x, row);
            let hit = match spec {
                MeshSpec::Sphere { radius, .. } => hit_sphere(o, d, radius, cull, mirror),
                MeshSpec::Grid { size, .. } => hit_plane(o, d, size, cull, mirror),
                MeshSpec::Cube { size } => hit_cube(o, d, size, cull, mirror),
                MeshSpec::Arrays { .. } => None,
            };
            if let Some((p, n, uv, front)) = hit {
                let v = shader.vertex(&VertexIn {
                    position: p,
                    normal: n,
                    uv,
                });
                let c = shader.fragment(&FragmentIn {
                    varyings: &v,
                    frag_coord: camera.frag_coord(x, row),
                    front_facing: front,
                });
                let i = (row * w + x) as usize;
                image.pixels[i] = c;
                image.coverage[i] = true;
            }
        }
    }
    Ok(())
}
