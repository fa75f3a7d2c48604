//! The stiff-case matrix: every light model × every stiff case × both formulations (the
//! seed's, [`crate::formulas::seed_fragment`], and the library's,
//! [`crate::formulas::library_fragment`]), evaluated on the CPU in float64, `highp` (float32)
//! and `mediump` (binary16 emulation), each measured against the model in exact float64
//! ([`crate::ideal`]).
//!
//! **Error.** The output colour is clamped to [0, 1] as the framebuffer does; the error is the
//! largest channel's distance, in 1/255 units, from the *reference band*: the model evaluated
//! with both cone cosines moved by `−δ`, `0` and `+δ` (`δ = 2^-22`, a few float32 ulps of a
//! cosine near 1). A cone's edge is only defined to the precision of its uploaded cosine, so a
//! hard edge (the step profile, inner == outer, a 0° cone) falling on a sample counts as right
//! on either side; everywhere else the band is a point. An output that is NaN or infinite
//! before the clamp is *not finite*, whatever a GPU's clamp would make of it.
//!
//! **Rejected.** Where the library refuses the parameters ([`crate::LightsError`]) instead of
//! rendering, the library's cell says so; the seed formula is still evaluated (its reference is
//! the corrected scene where one exists — the swapped cone sorted — and none otherwise).

use std::f64::consts::PI;
use std::fmt::Write as _;

use glam::{DVec2, DVec3};

use crate::formulas::{library_fragment, seed_fragment, FragmentInputs, Seed};
use crate::ideal;
use crate::real::{Real, F16, F32, V3};
use crate::scene::*;
use crate::uniforms::inv_viewport;

mod cases;

pub use cases::{setup, Setup, EYE, LIGHT_SPOT};

/// Half-width of the reference band in cosine units (`2^-22`).
pub const BAND: f64 = 2.384185791015625e-7;

/// A light model of the matrix: one light, the reflection model and the seed it comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Model {
    /// Directional light, Phong reflection (article 002).
    Directional,
    /// Directional light, Lambert reflection (article 002's Gouraud vertex shader).
    DirectionalLambert,
    /// Point light, Phong reflection (article 002's positional light).
    Point,
    /// Spot light, step edge, Blinn–Phong (article 001).
    SpotStep,
    /// Spot light, linear edge, Blinn–Phong (article 001).
    SpotLinear,
    /// Spot light, smooth edge, Blinn–Phong (article 000).
    SpotSmooth,
    /// Spot light with a projected cookie and an up vector, smooth edge (article 003).
    SpotProjected,
    /// Flashlight: spot light with a screen-space cookie, linear edge, Phong (article 004).
    Flashlight,
}

impl Model {
    /// Every model, in table order.
    pub const ALL: [Model; 8] = [
        Model::Directional,
        Model::DirectionalLambert,
        Model::Point,
        Model::SpotStep,
        Model::SpotLinear,
        Model::SpotSmooth,
        Model::SpotProjected,
        Model::Flashlight,
    ];

    /// The seed formulation.
    pub fn seed(self) -> Seed {
        match self {
            Model::Directional => Seed::A002Directional,
            Model::DirectionalLambert => Seed::A002Lambert,
            Model::Point => Seed::A002Positional,
            Model::SpotStep => Seed::A001Step,
            Model::SpotLinear => Seed::A001Linear,
            Model::SpotSmooth => Seed::A000Smooth,
            Model::SpotProjected => Seed::A003Projected,
            Model::Flashlight => Seed::A004Flashlight,
        }
    }

    /// A short name.
    pub fn name(self) -> &'static str {
        match self {
            Model::Directional => "directional (002)",
            Model::DirectionalLambert => "directional Lambert (002 Gouraud)",
            Model::Point => "point (002)",
            Model::SpotStep => "spot step (001)",
            Model::SpotLinear => "spot linear (001)",
            Model::SpotSmooth => "spot smooth (000)",
            Model::SpotProjected => "spot projected cookie (003)",
            Model::Flashlight => "flashlight cookie (004)",
        }
    }

    fn is_spot(self) -> bool {
        matches!(
            self,
            Model::SpotStep
                | Model::SpotLinear
                | Model::SpotSmooth
                | Model::SpotProjected
                | Model::Flashlight
        )
    }

    fn positional(self) -> bool {
        !matches!(self, Model::Directional | Model::DirectionalLambert)
    }

    fn reflection(self) -> Reflection {
        match self {
            Model::DirectionalLambert => Reflection::Lambert,
            Model::Directional | Model::Point | Model::Flashlight => Reflection::Phong,
            _ => Reflection::BlinnPhong,
        }
    }

    /// The default cone (inner, outer) of a spot model.
    fn cone(self) -> (f64, f64) {
        if self == Model::Flashlight {
            (12.5, 17.5)
        } else {
            (10.0, 20.0)
        }
    }
}

/// A stiff case.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Case {
    /// Ordinary parameters (the control: nothing should fail here).
    Baseline,
    /// `inner == outer`.
    InnerEqualsOuter,
    /// Inner cone wider than the outer (cosines swapped).
    Swapped,
    /// A 0° cone.
    Cone0,
    /// A 90° outer cone (`cos = 0`).
    Cone90,
    /// A 120° outer cone (`cos < 0`).
    Cone120,
    /// A 180° outer cone (`cos = −1`).
    Cone180,
    /// Samples exactly on the inner and outer limits.
    LimitOnSample,
    /// The projector's up vector parallel to the spot direction.
    UpParallel,
    /// Projector samples along ±up and ±left of a 120° cone, where `dot` rounds past ±1.
    AcosPastOne,
    /// The light exactly on the surface point.
    LightOnSurface,
    /// A zero-length normal.
    ZeroNormal,
    /// The normal perpendicular to the light (`N·L` = 0, ±1e-6, 1e-3).
    Grazing,
    /// The surface seen from behind, light in front; includes `L = −V` exactly.
    BackFace,
    /// The light behind the surface (`N·L < 0`, `N·H < 0`).
    LightBehind,
    /// Shininess 0.
    Shininess0,
    /// Shininess 1e4, samples at the highlight.
    Shininess1e4,
    /// The whole scene scaled by 1e-6.
    ScaleMicro,
    /// The whole scene scaled by 1e6.
    ScaleMega,
    /// The scene scaled by 4: vector lengths around 400, `dot(v, v)` past mediump's 65504.
    MediumpRange,
    /// A 0×0 viewport.
    ZeroViewport,
}

impl Case {
    /// Every case, in table order.
    pub const ALL: [Case; 21] = [
        Case::Baseline,
        Case::InnerEqualsOuter,
        Case::Swapped,
        Case::Cone0,
        Case::Cone90,
        Case::Cone120,
        Case::Cone180,
        Case::LimitOnSample,
        Case::UpParallel,
        Case::AcosPastOne,
        Case::LightOnSurface,
        Case::ZeroNormal,
        Case::Grazing,
        Case::BackFace,
        Case::LightBehind,
        Case::Shininess0,
        Case::Shininess1e4,
        Case::ScaleMicro,
        Case::ScaleMega,
        Case::MediumpRange,
        Case::ZeroViewport,
    ];

    /// A short name.
    pub fn name(self) -> &'static str {
        match self {
            Case::Baseline => "baseline",
            Case::InnerEqualsOuter => "inner == outer",
            Case::Swapped => "inner > outer (swapped)",
            Case::Cone0 => "cone 0°",
            Case::Cone90 => "cone 90°",
            Case::Cone120 => "cone 120°",
            Case::Cone180 => "cone 180°",
            Case::LimitOnSample => "limit on the sample",
            Case::UpParallel => "up ∥ direction",
            Case::AcosPastOne => "acos past ±1",
            Case::LightOnSurface => "light on the surface",
            Case::ZeroNormal => "zero normal",
            Case::Grazing => "grazing",
            Case::BackFace => "back face",
            Case::LightBehind => "light behind (pow of negative)",
            Case::Shininess0 => "shininess 0",
            Case::Shininess1e4 => "shininess 1e4",
            Case::ScaleMicro => "scale 1e-6",
            Case::ScaleMega => "scale 1e6",
            Case::MediumpRange => "mediump range (lengths ≈ 400)",
            Case::ZeroViewport => "viewport 0×0",
        }
    }

    /// Whether the case means something for the model.
    pub fn applies(self, m: Model) -> bool {
        match self {
            Case::InnerEqualsOuter | Case::Swapped => m.is_spot() && m != Model::SpotStep,
            Case::Cone0 | Case::Cone90 | Case::Cone120 | Case::Cone180 | Case::LimitOnSample => {
                m.is_spot()
            }
            Case::UpParallel | Case::AcosPastOne => m == Model::SpotProjected,
            Case::LightOnSurface => m.positional(),
            Case::Shininess0 | Case::Shininess1e4 => m.reflection() != Reflection::Lambert,
            Case::ZeroViewport => m == Model::Flashlight,
            _ => true,
        }
    }
}

/// One evaluation's result.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// The library refused the parameters (the error's message).
    Rejected(String),
    /// Evaluated against the reference band.
    Measured {
        /// Samples whose output was NaN or infinite.
        non_finite: usize,
        /// Samples evaluated.
        samples: usize,
        /// The largest error of the finite samples, 1/255 units.
        max_error: f64,
    },
    /// Evaluated where no reference exists (the parameters have no meaning).
    Unmeasured {
        /// Samples whose output was NaN or infinite.
        non_finite: usize,
        /// Samples evaluated.
        samples: usize,
    },
}

impl Outcome {
    /// Every output finite.
    pub fn finite(&self) -> bool {
        match self {
            Outcome::Rejected(_) => true,
            Outcome::Measured { non_finite, .. } | Outcome::Unmeasured { non_finite, .. } => {
                *non_finite == 0
            }
        }
    }

    /// Finite and within 1/255 everywhere (or rejected).
    pub fn ok(&self) -> bool {
        match self {
            Outcome::Rejected(_) => true,
            Outcome::Measured {
                non_finite,
                max_error,
                ..
            } => *non_finite == 0 && *max_error <= 1.0,
            Outcome::Unmeasured { .. } => false,
        }
    }

    /// A table cell: the error (bold beyond 1/255), `NaN k/n`, `rejected`, or for no
    /// reference `finite` / `NaN k/n`.
    pub fn cell(&self) -> String {
        match self {
            Outcome::Rejected(_) => "rejected".into(),
            Outcome::Measured {
                non_finite,
                samples,
                max_error,
            } => {
                if *non_finite > 0 {
                    format!("**NaN {non_finite}/{samples}**")
                } else if *max_error > 1.0 {
                    format!("**{}**", fmt_err(*max_error))
                } else {
                    fmt_err(*max_error)
                }
            }
            Outcome::Unmeasured {
                non_finite,
                samples,
            } => {
                if *non_finite > 0 {
                    format!("**NaN {non_finite}/{samples}**")
                } else {
                    "finite (no ref.)".into()
                }
            }
        }
    }
}

fn fmt_err(e: f64) -> String {
    if e == 0.0 {
        "0".into()
    } else if e < 0.01 {
        format!("{e:.0e}")
    } else if e < 10.0 {
        format!("{e:.2}")
    } else {
        format!("{e:.0}")
    }
}

/// One row of the matrix.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// The light model.
    pub model: Model,
    /// The case.
    pub case: Case,
    /// The seed's formula in float64.
    pub seed_f64: Outcome,
    /// The seed's formula in float32.
    pub seed_highp: Outcome,
    /// The seed's formula in binary16.
    pub seed_mediump: Outcome,
    /// The library's formula in float32 (what it emits: `precision highp float`).
    pub library_highp: Outcome,
    /// The library's formula in binary16 (for information: the library never emits mediump).
    pub library_mediump: Outcome,
}

/// The analytic cookie of the matrix: smooth and periodic, so errors in the coordinates show
/// as colour errors and wrapping changes nothing.
pub fn analytic_cookie(u: f64, t: f64) -> DVec3 {
    DVec3::new(
        0.5 + 0.5 * (2.0 * PI * u).cos(),
        0.5 + 0.5 * (2.0 * PI * t).cos(),
        1.0,
    )
}

fn cookie_r<R: Real>(_: usize, u: R, t: R) -> V3<R> {
    V3::of(analytic_cookie(u.to_f64(), t.to_f64()))
}

/// The reference band `[lo, hi]` of every sample (clamped to [0, 1]).
fn bands(setup: &Setup) -> Option<Vec<(DVec3, DVec3)>> {
    let r = setup.reference.as_ref()?;
    let prepared = r.prepare().ok()?;
    let inv = inv_viewport(setup.viewport[0], setup.viewport[1])
        .map(DVec2::from_array)
        .unwrap_or(DVec2::ZERO);
    let cookie = |_: usize, uv: DVec2| analytic_cookie(uv.x, uv.y);
    Some(
        setup
            .samples
            .iter()
            .map(|f| {
                let s = ideal::Surface {
                    position: f.position,
                    normal: f.normal,
                    eye: f.eye,
                    frag_coord: f.frag_coord,
                };
                let vals: Vec<DVec3> = [-BAND, 0.0, BAND]
                    .iter()
                    .map(|&sh| {
                        ideal::terms(
                            r,
                            &prepared,
                            &s,
                            &cookie,
                            inv,
                            ideal::TermOptions {
                                shift: sh,
                                defer_screen: false,
                            },
                        )
                        .base
                        .clamp(DVec3::ZERO, DVec3::ONE)
                    })
                    .collect();
                (
                    vals[0].min(vals[1]).min(vals[2]),
                    vals[0].max(vals[1]).max(vals[2]),
                )
            })
            .collect(),
    )
}

fn measure<R: Real>(
    samples: &[FragmentInputs],
    bands: Option<&[(DVec3, DVec3)]>,
    eval: impl Fn(&FragmentInputs) -> V3<R>,
) -> Outcome {
    let mut non_finite = 0;
    let mut max_error = 0.0f64;
    for (k, s) in samples.iter().enumerate() {
        let out = eval(s).to_f64();
        if !out.is_finite() {
            non_finite += 1;
            continue;
        }
        if let Some(b) = bands {
            let (lo, hi) = b[k];
            let o = out.clamp(DVec3::ZERO, DVec3::ONE);
            let e = (lo - o).max(o - hi).max(DVec3::ZERO).max_element() * 255.0;
            max_error = max_error.max(e);
        }
    }
    match bands {
        Some(_) => Outcome::Measured {
            non_finite,
            samples: samples.len(),
            max_error,
        },
        None => Outcome::Unmeasured {
            non_finite,
            samples: samples.len(),
        },
    }
}

fn seed_outcome<R: Real>(model: Model, setup: &Setup, bands: Option<&[(DVec3, DVec3)]>) -> Outcome {
    measure::<R>(&setup.samples, bands, |s| {
        seed_fragment::<R>(
            model.seed(),
            &setup.scene,
            setup.viewport,
            s,
            &cookie_r::<R>,
        )
    })
}

fn library_outcome<R: Real>(setup: &Setup, bands: Option<&[(DVec3, DVec3)]>) -> Outcome {
    let prepared = match setup.scene.prepare() {
        Ok(p) => p,
        Err(e) => return Outcome::Rejected(e.to_string()),
    };
    let inv = if prepared.shape.has_screen_cookie() {
        match inv_viewport(setup.viewport[0], setup.viewport[1]) {
            Ok(v) => v,
            Err(e) => return Outcome::Rejected(e.to_string()),
        }
    } else {
        [0.0, 0.0]
    };
    measure::<R>(&setup.samples, bands, |s| {
        library_fragment::<R>(&setup.scene, &prepared, inv, s, &cookie_r::<R>)
    })
}

/// Evaluates one cell row.
pub fn evaluate(model: Model, case: Case) -> Row {
    let setup = setup(model, case);
    let b = bands(&setup);
    let b = b.as_deref();
    Row {
        model,
        case,
        seed_f64: seed_outcome::<f64>(model, &setup, b),
        seed_highp: seed_outcome::<F32>(model, &setup, b),
        seed_mediump: seed_outcome::<F16>(model, &setup, b),
        library_highp: library_outcome::<F32>(&setup, b),
        library_mediump: library_outcome::<F16>(&setup, b),
    }
}

/// The whole matrix: every model × every case that applies to it.
pub fn run() -> Vec<Row> {
    let mut rows = Vec::new();
    for m in Model::ALL {
        for c in Case::ALL {
            if c.applies(m) {
                rows.push(evaluate(m, c));
            }
        }
    }
    rows
}

/// The matrix as a Markdown table (seed precision marked `*`).
pub fn markdown(rows: &[Row]) -> String {
    let mut s = String::from(
        "| light model | case | seed f64 | seed highp | seed mediump | library highp | library mediump |\n\
         | --- | --- | --- | --- | --- | --- | --- |\n",
    );
    for r in rows {
        let seed_prec = r.model.seed().precision();
        let mark = |o: &Outcome, p: &str| {
            let c = o.cell();
            if p == seed_prec {
                format!("{c} *")
            } else {
                c
            }
        };
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {} | {} |",
            r.model.name(),
            r.case.name(),
            r.seed_f64.cell(),
            mark(&r.seed_highp, "highp"),
            mark(&r.seed_mediump, "mediump"),
            r.library_highp.cell(),
            r.library_mediump.cell(),
        );
    }
    s
}

/// Counts for a summary: rows, seed failures at the seed's own precision, library highp
/// failures (must be 0).
pub fn summary(rows: &[Row]) -> (usize, usize, usize) {
    let seed_fail = rows
        .iter()
        .filter(|r| {
            let o = if r.model.seed().precision() == "mediump" {
                &r.seed_mediump
            } else {
                &r.seed_highp
            };
            !o.ok()
        })
        .count();
    let lib_fail = rows.iter().filter(|r| !r.library_highp.ok()).count();
    (rows.len(), seed_fail, lib_fail)
}

/// The start marker of the generated section in `docs/numerical-stability.md`.
pub const BEGIN_MARKER: &str = "<!-- stiff-table:begin -->";
/// The end marker.
pub const END_MARKER: &str = "<!-- stiff-table:end -->";

/// The generated section: a summary line and the table.
pub fn document_section(rows: &[Row]) -> String {
    let (total, seed_fail, lib_fail) = summary(rows);
    format!(
        "{BEGIN_MARKER}\n\
         <!-- written by `cargo run -p essl-lights --bin stiff-table`; do not edit by hand -->\n\n\
         {total} (model, case) rows. The seed's formula, at the precision its article declares \
         (marked `*`), is NaN or more than 1/255 off in **{seed_fail}** of them; the library's \
         `highp` formula in **{lib_fail}**.\n\n{}\n{END_MARKER}",
        markdown(rows)
    )
}

/// `doc` with the text between the markers (inclusive) replaced by `section`; `None` without
/// markers.
pub fn replace_section(doc: &str, section: &str) -> Option<String> {
    let a = doc.find(BEGIN_MARKER)?;
    let b = doc[a..].find(END_MARKER)? + a + END_MARKER.len();
    Some(format!("{}{}{}", &doc[..a], section, &doc[b..]))
}
