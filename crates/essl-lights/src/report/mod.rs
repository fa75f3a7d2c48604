//! The report: error against run time for the library's shader variants, drawn through essl-gl
//! (`essl report`, `docs/report.md`).
//!
//! Each [`Variant`] (a lit scene on a geometry, drawn by one program) is
//!
//! - drawn once at the error size (256², `--quick`: 64²) and compared with the float64
//!   reference of its lit scene evaluated at every pixel ([`per_pixel`]; with
//!   [`crate::gpu::reference_band`]: a band across hard edges),
//!   leaving out the pixels within one pixel of a silhouette (a coverage change of the
//!   reference): largest error, RMS, % of pixels more than 1/255 off, in 1/255 units; its NaN
//!   probe ([`crate::gpu::probe_program`]) counts NaN or infinite fragments. A `mediump`
//!   variant's error is the CPU's binary16 emulation ([`MediumpShader`]), since lavapipe
//!   computes every precision in 32 bits;
//! - timed at each timing size (256² and 1024², `--quick`: 64² and 128²): every variant is set
//!   up on its own context, then in each of several rounds each variant draws one untimed and
//!   up to `frames` timed frames (at least 3; fewer when frames are slow, about
//!   [`FRAME_BUDGET_MS`] a round; clear + draw + `readPixels` of one pixel, as
//!   `webgl2-render.py --times` times them) in turn; a round's value is the median of its
//!   frames, the result the median of the rounds (interleaving spreads the shared machine's
//!   load over every variant).
//!
//! [`run`] does everything and returns a [`Report`]; [`write`] writes `report.md`, the chart
//! `report.svg`, the pictures `report-*.png` and the GPU stiff section of `numerical-stability.md`.

mod chart;
mod doc;
mod variants;

use std::path::{Path, PathBuf};
use std::time::Instant;

use essl_scene::RgbaImage;

use crate::error::LightsError;
use crate::gpu::{self, count_probe, median, probe_program, reference_band, Timer};
use crate::gpu_stiff::{self, GpuRow};
use crate::reference::{compare_band, error_image, render, CompareOptions, Geometry, RefDiff};
use crate::verify;

pub use variants::{
    point_scene, projector_cookie, small_spot_scene, spot_scene, variants, Extent, Group,
    MediumpShader, ProgramKind, Variant, SEED_SCENES,
};

/// The time a variant's timed frames take in one round, about (fewer frames for slow
/// variants).
pub const FRAME_BUDGET_MS: f64 = 120.0;

/// What to run.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// Which variants.
    pub extent: Extent,
    /// The canvas side the error is measured at.
    pub error_size: u32,
    /// The canvas sides frames are timed at.
    pub time_sizes: Vec<u32>,
    /// Timed frames per variant per round.
    pub frames: usize,
    /// Rounds.
    pub rounds: usize,
    /// The canvas side of the GPU stiff matrix; `None` skips it.
    pub stiff_size: Option<u32>,
    /// The folder of the shared seed scenes (`shared/scenes`); the specialised-vs-uber part is
    /// left out when it is `None` or holds no scene.
    pub scenes: Option<PathBuf>,
}

impl Settings {
    /// The full report: errors at 256², times at 256² and 1024² (9 rounds of up to 15 frames), the
    /// GPU stiff matrix at 65².
    pub fn full(scenes: Option<PathBuf>) -> Settings {
        Settings {
            extent: Extent::Full,
            error_size: 256,
            time_sizes: vec![256, 1024],
            frames: 15,
            rounds: 9,
            stiff_size: Some(gpu_stiff::SIZE),
            scenes,
        }
    }

    /// The quick report (for tests): fewer tessellations, errors at 64², times at 64² and 128²
    /// (1 round of 3 frames), no stiff matrix.
    pub fn quick(scenes: Option<PathBuf>) -> Settings {
        Settings {
            extent: Extent::Quick,
            error_size: 64,
            time_sizes: vec![64, 128],
            frames: 3,
            rounds: 1,
            stiff_size: None,
            scenes,
        }
    }
}

/// The machine and software the report ran on.
#[derive(Clone, Debug, PartialEq)]
pub struct Machine {
    /// The adapter (`llvmpipe (LLVM …, 256 bits)`).
    pub renderer: String,
    /// The driver (`llvmpipe Mesa …`).
    pub driver: String,
    /// The CPU model (from `/proc/cpuinfo`).
    pub cpu: String,
    /// Logical cores.
    pub cores: usize,
    /// The 1-minute load average at the start and at the end (from `/proc/loadavg`).
    pub load: (Option<f64>, Option<f64>),
    /// UTC date, `YYYY-MM-DD`.
    pub date: String,
    /// `git rev-parse --short HEAD`, when available.
    pub commit: Option<String>,
    /// Whether this was a release build.
    pub release: bool,
}

/// One variant's measurements.
#[derive(Clone, Debug)]
pub struct VariantResult {
    /// The variant.
    pub variant: Variant,
    /// The error at the error size (silhouettes left out).
    pub error: RefDiff,
    /// Fragments the NaN probe flagged (for a mediump variant: NaN pixels of the emulation).
    pub non_finite: usize,
    /// `(size, median ms per frame, the rounds' medians)` for each timing size.
    pub times: Vec<(u32, f64, Vec<f64>)>,
    /// Vertex + fragment shader bytes.
    pub shader_bytes: (usize, usize),
    /// Active uniforms after essl's link (arrays count once, as WebGL lists them).
    pub active_uniforms: usize,
    /// Scalars uploaded per draw (every declared uniform's components).
    pub uniform_scalars: usize,
    /// Declared uniforms that are inactive plus functions that are unused (0 for a minimal
    /// program).
    pub unused: usize,
    /// On the Pareto front of all variants (error RMS, ms at the largest timing size); never
    /// for an [emulated](VariantResult::emulated) variant.
    pub pareto: bool,
    /// On the Pareto front of its group; never for an emulated variant.
    pub pareto_group: bool,
    /// For a mediump variant: pixels where lavapipe's picture of the mediump program differs
    /// from its picture of the highp one.
    pub mediump_gpu_diff: Option<usize>,
}

impl VariantResult {
    /// Whether the error is emulated: a `mediump` variant's error is the CPU's binary16
    /// emulation while its time is lavapipe's (which computes in 32 bits), so the two do not
    /// describe one program run and the point stays off the Pareto fronts.
    pub fn emulated(&self) -> bool {
        self.variant.program == ProgramKind::Mediump
    }

    /// The median ms at `size`.
    pub fn ms(&self, size: u32) -> Option<f64> {
        self.times.iter().find(|t| t.0 == size).map(|t| t.1)
    }

    /// The rounds' spread at `size`: (max − min) / median, in %.
    pub fn spread_percent(&self, size: u32) -> Option<f64> {
        let t = self.times.iter().find(|t| t.0 == size)?;
        let lo = t.2.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = t.2.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Some(100.0 * (hi - lo) / t.1)
    }

    /// Every number finite (the quick test's check).
    pub fn is_finite(&self) -> bool {
        self.error.max.is_finite()
            && self.error.rms.is_finite()
            && self.error.over_one_percent.is_finite()
            && self.times.iter().all(|t| t.1.is_finite() && t.1 > 0.0)
    }
}

/// A picture written beside the report.
#[derive(Clone, Debug)]
pub struct Picture {
    /// File name (`report-small-spot.png`).
    pub file: String,
    /// What the panels show, left to right.
    pub caption: String,
    /// The image.
    pub image: RgbaImage,
}

/// Everything [`run`] measured.
#[derive(Clone, Debug)]
pub struct Report {
    /// What ran.
    pub settings: Settings,
    /// Where.
    pub machine: Machine,
    /// One result per variant, in [`variants`] order.
    pub results: Vec<VariantResult>,
    /// The GPU stiff matrix (absent with `--quick`).
    pub stiff: Option<Vec<GpuRow>>,
    /// The pictures.
    pub pictures: Vec<Picture>,
    /// Seconds [`run`] took.
    pub wall_s: f64,
}

fn io_err(path: &Path, e: impl std::fmt::Display) -> LightsError {
    LightsError::Io {
        path: path.display().to_string(),
        message: e.to_string(),
    }
}

/// Days since 1970-01-01 to a civil date (Howard Hinnant's algorithm).
fn civil(days: i64) -> (i64, u32, u32) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let y = yoe + era * 400;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    (if m <= 2 { y + 1 } else { y }, m, d)
}

fn load_average() -> Option<f64> {
    std::fs::read_to_string("/proc/loadavg")
        .ok()?
        .split_whitespace()
        .next()?
        .parse()
        .ok()
}

fn machine() -> Result<Machine, LightsError> {
    let (renderer, driver) = gpu::adapter()?;
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split_once(':'))
                .map(|(_, v)| v.trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_secs() as i64)
        .unwrap_or(0);
    let (y, m, d) = civil(secs.div_euclid(86_400));
    let commit = std::process::Command::new("git")
        .args(["rev-parse", "--short", "HEAD"])
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
        .filter(|s| !s.is_empty());
    Ok(Machine {
        renderer,
        driver,
        cpu,
        cores: std::thread::available_parallelism().map_or(1, |n| n.get()),
        load: (load_average(), None),
        date: format!("{y:04}-{m:02}-{d:02}"),
        commit,
        release: !cfg!(debug_assertions),
    })
}

/// The scene the report measures every variant against: `lit` with Phong shading, i.e. the
/// light model evaluated at every pixel (a Gouraud picture's interpolation is part of its
/// error).
pub fn per_pixel(lit: &crate::LitScene) -> crate::LitScene {
    let mut l = lit.clone();
    l.shading = crate::Shading::Phong;
    l
}

/// Measures one variant's error (and its program's static numbers).
fn measure_error(v: &Variant, size: u32) -> Result<(VariantResult, RgbaImage), LightsError> {
    let shaders = v.shaders()?;
    let (scene, view) = v.scene_with(size, &shaders)?;
    let image = gpu::render(&scene)?;
    let (probe_scene, _) = v.scene_with(size, &probe_program(&shaders)?)?;
    let probe = count_probe(&gpu::render(&probe_scene)?);
    let band = reference_band(&scene, &per_pixel(&v.lit), &view, Geometry::Mesh)?;
    let opts = CompareOptions {
        ignore_silhouettes: true,
    };
    let (error, non_finite, mediump_gpu_diff, shown) = if v.program == ProgramKind::Mediump {
        let emulated = render(&scene, &MediumpShader::new(&v.lit, &view)?, Geometry::Mesh)?;
        let nan = emulated.pixels.iter().filter(|p| !p.is_finite()).count();
        let picture = emulated.to_rgba8();
        // lavapipe's picture of the highp program, against its picture of this one.
        let mut highp = v.clone();
        highp.program = ProgramKind::Specialised;
        let (hs, _) = highp.scene(size)?;
        let himg = gpu::render(&hs)?;
        let diff = image
            .data
            .chunks_exact(4)
            .zip(himg.data.chunks_exact(4))
            .filter(|(a, b)| a != b)
            .count();
        (
            compare_band(&picture, &band, opts)?,
            nan,
            Some(diff),
            picture,
        )
    } else {
        (
            compare_band(&image, &band, opts)?,
            probe.non_finite,
            None,
            image,
        )
    };
    let ver = verify(&shaders);
    Ok((
        VariantResult {
            variant: v.clone(),
            error,
            non_finite,
            times: Vec::new(),
            shader_bytes: (shaders.vertex.len(), shaders.fragment.len()),
            active_uniforms: ver.active_uniforms.len(),
            uniform_scalars: shaders.uniform_scalars(),
            unused: ver.inactive_uniforms.len() + ver.unused_functions.len(),
            pareto: false,
            pareto_group: false,
            mediump_gpu_diff,
        },
        shown,
    ))
}

/// Marks the Pareto fronts (minimal RMS error and minimal ms at `size`). Emulated variants
/// ([`VariantResult::emulated`]) take no part: they are on no front and dominate no other.
fn mark_pareto(results: &mut [VariantResult], size: u32) {
    let pts: Vec<(f64, f64, Group, bool)> = results
        .iter()
        .map(|r| {
            (
                r.ms(size).unwrap_or(f64::INFINITY),
                r.error.rms,
                r.variant.group,
                r.emulated(),
            )
        })
        .collect();
    let dominated = |i: usize, same_group: bool| {
        pts.iter().enumerate().any(|(j, q)| {
            j != i
                && !q.3
                && (!same_group || q.2 == pts[i].2)
                && q.0 <= pts[i].0
                && q.1 <= pts[i].1
                && (q.0 < pts[i].0 || q.1 < pts[i].1)
        })
    };
    for (i, r) in results.iter_mut().enumerate() {
        let emulated = pts[i].3;
        r.pareto = !emulated && !dominated(i, false);
        r.pareto_group = !emulated && !dominated(i, true);
    }
}

/// Side-by-side panels (all of one height), with a 4-pixel grey gutter.
fn panels(images: &[&RgbaImage]) -> RgbaImage {
    let h = images.iter().map(|i| i.height).max().unwrap_or(0);
    let gutter = 4;
    let w: u32 = images.iter().map(|i| i.width).sum::<u32>() + gutter * (images.len() as u32 - 1);
    let mut data = vec![128u8; (w * h * 4) as usize];
    let mut x0 = 0;
    for img in images {
        for y in 0..img.height {
            for x in 0..img.width {
                let s = ((y * img.width + x) * 4) as usize;
                let d = ((y * w + x0 + x) * 4) as usize;
                data[d..d + 4].copy_from_slice(&img.data[s..s + 4]);
            }
        }
        x0 += img.width + gutter;
    }
    RgbaImage {
        width: w,
        height: h,
        data,
    }
}

/// The picture of one variant pair: GPU picture of `a`, of `b`, the reference, and `a`'s error
/// (black ≤ 1/255, blue ≤ 2, yellow ≤ 8, red beyond, grey left out, magenta where `a`'s NaN
/// probe flags a fragment).
fn pair_picture(
    a: &Variant,
    a_img: &RgbaImage,
    b_img: &RgbaImage,
    size: u32,
) -> Result<RgbaImage, LightsError> {
    let (scene, view) = a.scene(size)?;
    let band = reference_band(&scene, &per_pixel(&a.lit), &view, Geometry::Mesh)?;
    let reference = band.midpoint();
    let mut err = error_image(
        a_img,
        &reference,
        CompareOptions {
            ignore_silhouettes: true,
        },
    )?;
    let (probe, _) = a.scene_with(size, &probe_program(&a.shaders()?)?)?;
    let flags = gpu::render(&probe)?;
    for (e, f) in err.data.chunks_exact_mut(4).zip(flags.data.chunks_exact(4)) {
        if f == gpu::PROBE_NON_FINITE {
            e.copy_from_slice(&gpu::PROBE_NON_FINITE);
        }
    }
    Ok(panels(&[a_img, b_img, &reference.to_rgba8(), &err]))
}

/// Runs the report: every variant's error and times, the pictures, and (unless `settings`
/// skip it) the GPU stiff matrix. `progress` receives one line per step.
pub fn run(settings: &Settings, progress: &mut dyn FnMut(&str)) -> Result<Report, LightsError> {
    let t0 = Instant::now();
    let mut machine = machine()?;
    let scenes = settings.scenes.as_deref().filter(|p| p.is_dir());
    let vs = variants(settings.extent, scenes)?;
    let mut results = Vec::with_capacity(vs.len());
    let mut shown = Vec::with_capacity(vs.len());
    for (i, v) in vs.iter().enumerate() {
        let (r, img) = measure_error(v, settings.error_size)?;
        progress(&format!(
            "[{}/{}] {}: max {:.2}, rms {:.3}, {:.2}% > 1/255, {} non-finite",
            i + 1,
            vs.len(),
            v.name,
            r.error.max,
            r.error.rms,
            r.error.over_one_percent,
            r.non_finite
        ));
        results.push(r);
        shown.push(img);
    }
    for &size in &settings.time_sizes {
        progress(&format!("timing {} variants at {size}²", vs.len()));
        let mut timers = vs
            .iter()
            .map(|v| Timer::new(&v.scene(size)?.0))
            .collect::<Result<Vec<_>, _>>()?;
        // Frames per round: `settings.frames`, fewer for slow frames (about
        // FRAME_BUDGET_MS a variant a round), at least 3.
        let counts: Vec<usize> = timers
            .iter_mut()
            .map(|t| {
                let est = median(&t.frames(3)).unwrap_or(1.0).max(1e-3);
                ((FRAME_BUDGET_MS / est).ceil() as usize).clamp(3, settings.frames.max(3))
            })
            .collect();
        let mut rounds: Vec<Vec<f64>> = vec![Vec::new(); vs.len()];
        for round in 0..settings.rounds {
            // Start each round at another variant, so none is always first after a pause.
            for k in 0..timers.len() {
                let i = (k + round) % timers.len();
                timers[i].frames(1);
                let ms = timers[i].frames(counts[i]);
                rounds[i].push(median(&ms).unwrap_or(f64::NAN));
            }
        }
        for (r, t) in results.iter_mut().zip(rounds) {
            r.times.push((size, median(&t).unwrap_or(f64::NAN), t));
        }
    }
    if let Some(&largest) = settings.time_sizes.iter().max() {
        mark_pareto(&mut results, largest);
    }
    let mut pictures = Vec::new();
    let find = |name: &str| vs.iter().position(|v| v.name == name);
    let size = settings.error_size;
    let small_cells = 4;
    if let (Some(g), Some(p)) = (
        find(&format!(
            "small spot, Gouraud, grid {small_cells}×{small_cells}"
        )),
        find(&format!(
            "small spot, Phong, grid {small_cells}×{small_cells}"
        )),
    ) {
        pictures.push(Picture {
            file: "report-small-spot.png".into(),
            caption: format!(
                "Small spot (3°/5°) aimed between the vertices of a {small_cells}×{small_cells} \
                 grid, {size}²: Gouraud on essl-gl | Phong on essl-gl | float64 reference | \
                 Gouraud's error (black ≤ 1/255, blue ≤ 2, yellow ≤ 8, red more)"
            ),
            image: pair_picture(&vs[g], &shown[g], &shown[p], size)?,
        });
    }
    if let (Some(a), Some(b)) = (
        find("projected cookie, seed 003 acos, zoom along up"),
        find("projected cookie, library atan, zoom along up"),
    ) {
        pictures.push(Picture {
            file: "report-acos.png".into(),
            caption: format!(
                "Projected cookie, zoom on the direction 90° off the projector's axis along its \
                 up vector ({size}², 0.1 units across at 50 from the light, nearest \
                 filtering): article 003's acos \
                 on essl-gl | the library's atan on essl-gl | float64 reference | acos's error \
                 (black ≤ 1/255, blue ≤ 2, magenta: NaN texture coordinates)"
            ),
            image: pair_picture(&vs[a], &shown[a], &shown[b], size)?,
        });
    }
    if let (Some(a), Some(b)) = (
        find("step edge (Phong, grid 8×8)"),
        find("smooth edge (Phong, grid 8×8)"),
    ) {
        pictures.push(Picture {
            file: "report-edges.png".into(),
            caption: format!(
                "Spot edges, {size}²: step on essl-gl | smooth on essl-gl | the step's float64 \
                 reference (band midpoint) | the step's error against its band"
            ),
            image: pair_picture(&vs[a], &shown[a], &shown[b], size)?,
        });
    }
    let stiff = match settings.stiff_size {
        Some(s) => {
            progress(&format!("GPU stiff matrix at {s}²"));
            Some(gpu_stiff::run(s)?)
        }
        None => None,
    };
    machine.load.1 = load_average();
    Ok(Report {
        settings: settings.clone(),
        machine,
        results,
        stiff,
        pictures,
        wall_s: t0.elapsed().as_secs_f64(),
    })
}

/// Writes `report.md`, `report.svg` and the pictures into `out` (created if needed), and the
/// GPU stiff section into `out/numerical-stability.md` when the report has it and that file exists.
/// Returns the files written.
pub fn write(report: &Report, out: &Path) -> Result<Vec<PathBuf>, LightsError> {
    std::fs::create_dir_all(out).map_err(|e| io_err(out, e))?;
    let mut written = Vec::new();
    let svg = chart::svg(report)?;
    let p = out.join("report.svg");
    std::fs::write(&p, svg).map_err(|e| io_err(&p, e))?;
    written.push(p);
    for pic in &report.pictures {
        let p = out.join(&pic.file);
        pic.image.write_png(&p).map_err(|e| io_err(&p, e))?;
        written.push(p);
    }
    let p = out.join("report.md");
    std::fs::write(&p, doc::markdown(report)).map_err(|e| io_err(&p, e))?;
    written.push(p);
    if let Some(rows) = &report.stiff {
        let p = out.join("numerical-stability.md");
        if let Ok(text) = std::fs::read_to_string(&p) {
            let section = gpu_stiff::document_section(
                rows,
                report.settings.stiff_size.unwrap_or(gpu_stiff::SIZE),
                &report.machine.renderer,
            );
            std::fs::write(&p, gpu_stiff::replace_section(&text, &section))
                .map_err(|e| io_err(&p, e))?;
            written.push(p);
        }
    }
    Ok(written)
}

/// The report's main table as plain text (for the terminal).
pub fn text_table(report: &Report) -> String {
    doc::text_table(report)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn emulated_points_stay_off_the_pareto_fronts() {
        let vs = variants(Extent::Quick, None).unwrap();
        let highp = vs
            .iter()
            .find(|v| v.group == Group::Precision && v.program == ProgramKind::Specialised)
            .unwrap();
        let mediump = vs
            .iter()
            .find(|v| v.program == ProgramKind::Mediump)
            .unwrap();
        let result = |v: &Variant, rms: f64, ms: f64| VariantResult {
            variant: v.clone(),
            error: RefDiff {
                compared: 1,
                ignored: 0,
                max: rms,
                rms,
                p99: rms,
                over_one: 0,
                over_one_percent: 0.0,
                worst: None,
            },
            non_finite: 0,
            times: vec![(128, ms, vec![ms])],
            shader_bytes: (0, 0),
            active_uniforms: 0,
            uniform_scalars: 0,
            unused: 0,
            pareto: false,
            pareto_group: false,
            mediump_gpu_diff: None,
        };
        // The emulated point is faster and more accurate, yet dominates nothing and is on no
        // front.
        let mut rs = vec![result(highp, 0.5, 2.0), result(mediump, 0.1, 1.0)];
        mark_pareto(&mut rs, 128);
        assert!(!rs[0].emulated() && rs[1].emulated());
        assert!(rs[0].pareto && rs[0].pareto_group);
        assert!(!rs[1].pareto && !rs[1].pareto_group);
    }

    #[test]
    fn civil_dates() {
        assert_eq!(civil(0), (1970, 1, 1));
        assert_eq!(civil(19_723), (2024, 1, 1));
        assert_eq!(civil(20_513), (2026, 3, 1));
    }
}
