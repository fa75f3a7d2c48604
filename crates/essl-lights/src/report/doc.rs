//! `report.md`: every number comes from the [`Report`]; the prose around them only says what
//! was measured and how.

use std::fmt::Write as _;

use super::{Group, ProgramKind, Report, VariantResult};
use crate::gpu_stiff;

fn f(x: f64) -> String {
    if !x.is_finite() {
        return format!("{x}");
    }
    let a = x.abs();
    if a == 0.0 {
        "0".into()
    } else if a < 0.01 {
        format!("{x:.4}")
    } else if a < 10.0 {
        format!("{x:.2}")
    } else if a < 100.0 {
        format!("{x:.1}")
    } else {
        format!("{x:.0}")
    }
}

fn ms(r: &VariantResult, size: u32) -> String {
    r.ms(size).map_or("–".into(), |m| format!("{m:.3}"))
}

fn find<'a>(report: &'a Report, name: &str) -> Option<&'a VariantResult> {
    report.results.iter().find(|r| r.variant.name == name)
}

fn largest(report: &Report) -> u32 {
    report
        .settings
        .time_sizes
        .iter()
        .copied()
        .max()
        .unwrap_or(0)
}

/// The main table in Markdown.
fn table(report: &Report) -> String {
    let sizes = &report.settings.time_sizes;
    let big = largest(report);
    let mut s = String::from("| group | variant | label | max | RMS | % > 1/255 | NaN px |");
    for z in sizes {
        let _ = write!(s, " ms {z}² |");
    }
    let _ = writeln!(s, " spread {big}² | Pareto |");
    s.push_str("| --- | --- | --- | ---: | ---: | ---: | ---: |");
    for _ in sizes {
        s.push_str(" ---: |");
    }
    s.push_str(" ---: | :---: |\n");
    for r in &report.results {
        let _ = write!(
            s,
            "| {} | {} | {} | {} | {} | {} | {} |",
            r.variant.group.title(),
            r.variant.name,
            r.variant.label,
            f(r.error.max),
            f(r.error.rms),
            f(r.error.over_one_percent),
            r.non_finite
        );
        for &z in sizes {
            let _ = write!(s, " {} |", ms(r, z));
        }
        let spread = r
            .spread_percent(big)
            .map_or("–".into(), |p| format!("{p:.0} %"));
        let mark = if r.emulated() {
            "emulated"
        } else if r.pareto {
            "●"
        } else if r.pareto_group {
            "○"
        } else {
            ""
        };
        let _ = writeln!(s, " {spread} | {mark} |");
    }
    s
}

/// The main table as aligned plain text.
pub fn text_table(report: &Report) -> String {
    let sizes = &report.settings.time_sizes;
    let mut s = format!(
        "{:<52} {:>8} {:>8} {:>9} {:>6}",
        "variant", "max", "RMS", "%>1/255", "NaN"
    );
    for z in sizes {
        let _ = write!(s, " {:>10}", format!("ms {z}²"));
    }
    s.push_str("  Pareto\n");
    for r in &report.results {
        let _ = write!(
            s,
            "{:<52} {:>8} {:>8} {:>9} {:>6}",
            r.variant.name,
            f(r.error.max),
            f(r.error.rms),
            f(r.error.over_one_percent),
            r.non_finite
        );
        for &z in sizes {
            let _ = write!(s, " {:>10}", ms(r, z));
        }
        let mark = if r.emulated() {
            "emulated"
        } else if r.pareto {
            "global"
        } else if r.pareto_group {
            "group"
        } else {
            ""
        };
        let _ = writeln!(s, "  {mark}");
    }
    s
}

/// The results of one group of variants, in report order.
fn group_rows(report: &Report, group: Group) -> Vec<&VariantResult> {
    report
        .results
        .iter()
        .filter(|r| r.variant.group == group)
        .collect()
}

/// Embeds the report's picture `file` with its caption, if the run made it.
fn embed_picture(report: &Report, file: &str, out: &mut String) {
    if let Some(pic) = report.pictures.iter().find(|p| p.file == file) {
        let _ = writeln!(
            out,
            "\n![{}]({})\n\n*{}*",
            pic.caption, pic.file, pic.caption
        );
    }
}

fn shading_section(report: &Report, out: &mut String) {
    let big = largest(report);
    let rows = group_rows(report, Group::Shading);
    if rows.is_empty() {
        return;
    }
    out.push_str(
        "\n## Gouraud against Phong shading\n\nThe spot-smooth scene (a 10°/20° smooth spot \
         100 units above a 200-unit plane, Blinn–Phong, shininess 150) on grids of n×n cells. \
         Gouraud shading lights the vertices and interpolates colours, so the spot's disc and \
         highlight are only as good as the grid; Phong shading interpolates the normal and the \
         position (both exact on a plane) and lights every pixel.\n\n",
    );
    let _ = writeln!(
        out,
        "| grid | Gouraud max | Gouraud RMS | Phong max | Phong RMS | Gouraud ms {big}² | Phong ms {big}² |\n| --- | ---: | ---: | ---: | ---: | ---: | ---: |"
    );
    for pair in rows.chunks(2) {
        if let [g, p] = pair {
            let grid = g.variant.name.split("grid ").nth(1).unwrap_or("");
            let _ = writeln!(
                out,
                "| {grid} | {} | {} | {} | {} | {} | {} |",
                f(g.error.max),
                f(g.error.rms),
                f(p.error.max),
                f(p.error.rms),
                ms(g, big),
                ms(p, big)
            );
        }
    }
}

fn small_spot_section(report: &Report, out: &mut String) {
    let Some(g) = find(report, "small spot, Gouraud, grid 4×4") else {
        return;
    };
    let p = find(report, "small spot, Phong, grid 4×4");
    let size = report.settings.error_size;
    out.push_str(
        "\n## A coarse grid with Gouraud shading misses a small spot\n\nA 3°/5° spot 100 units \
         above the plane lights a disc 8.7 units in radius, aimed at (25, 0, 25): the centre of \
         a cell of the 4×4 grid, whose vertices are 50 units apart. No vertex is inside the \
         cone, so Gouraud shading computes ambient light at every vertex and interpolates it: \
         the spot is not drawn at all.\n\n",
    );
    let _ = writeln!(
        out,
        "On the 4×4 grid at {size}², Gouraud is up to **{}**/255 off (RMS {}, {} % of the \
         pixels more than 1/255 off: the whole disc); Phong shading on the same grid is {} off \
         at most (RMS {}).",
        f(g.error.max),
        f(g.error.rms),
        f(g.error.over_one_percent),
        p.map_or("–".into(), |p| f(p.error.max)),
        p.map_or("–".into(), |p| f(p.error.rms)),
    );
    if let Some(g64) = find(report, "small spot, Gouraud, grid 64×64") {
        let _ = writeln!(
            out,
            "With 64×64 cells (3.1 units apart, a few vertices inside the disc) Gouraud draws a \
             faceted spot, still {}/255 off at most (RMS {}).",
            f(g64.error.max),
            f(g64.error.rms)
        );
    }
    embed_picture(report, "report-small-spot.png", out);
}

fn edge_section(report: &Report, out: &mut String) {
    let rows = group_rows(report, Group::Edge);
    if rows.is_empty() {
        return;
    }
    let big = largest(report);
    out.push_str(
        "\n## Spot edges: step, linear, smooth\n\nThe same spot with each edge profile (Phong \
         shading, 8×8 grid). The step is discontinuous: its reference is a band (cone cosines \
         moved by ±2⁻²², rays by ±1/256 pixel, as lavapipe snaps vertices to 1/256 pixel), so \
         a pixel whose centre lies within rounding of the edge counts as right on either side. \
         The three programs differ only in the edge computation (`step`, or a clamped ramp with \
         a CPU-computed slope, smoothed or not).\n\n",
    );
    for r in rows {
        let _ = writeln!(
            out,
            "- {}: max {}, RMS {}, {} % > 1/255; {} ms at {big}².",
            r.variant.name,
            f(r.error.max),
            f(r.error.rms),
            f(r.error.over_one_percent),
            ms(r, big)
        );
    }
    embed_picture(report, "report-edges.png", out);
}

fn precision_section(report: &Report, out: &mut String) {
    let rows = group_rows(report, Group::Precision);
    if rows.is_empty() {
        return;
    }
    let big = largest(report);
    out.push_str(
        "\n## highp against mediump\n\n**lavapipe computes every precision in 32 bits**, so a \
         `mediump` program draws the same picture as its `highp` twin here. What `mediump` \
         costs on a mobile GPU that implements it as binary16 is shown by emulating it: the \
         library's Phong-shading fragment shader evaluated on the CPU with every value and \
         operation rounded to binary16 (11 significant bits, 10 stored; ±65504; \
         `essl_lights::real::F16`), on the varyings the reference interpolates. The `mediump` \
         rows' error columns are that emulation; their times are lavapipe's for the program \
         with `precision mediump float` (no faster here; a GPU with binary16 arithmetic may \
         be). The rows are marked *emulated* and kept off the Pareto fronts.\n\n",
    );
    for r in rows {
        let gpu = match r.mediump_gpu_diff {
            Some(d) => format!(
                " lavapipe's picture of the mediump program differs from the highp one's in {d} pixels."
            ),
            None => String::new(),
        };
        let _ = writeln!(
            out,
            "- {}: max {}, RMS {}, {} % > 1/255, {} NaN pixels; {} ms at {big}².{gpu}",
            r.variant.name,
            f(r.error.max),
            f(r.error.rms),
            f(r.error.over_one_percent),
            r.non_finite,
            ms(r, big)
        );
    }
}

fn projector_section(report: &Report, out: &mut String) {
    let rows = group_rows(report, Group::Projector);
    if rows.is_empty() {
        return;
    }
    let big = largest(report);
    out.push_str(
        "\n## Projected-texture coordinates: article 003's acos against atan\n\nA projected \
         cookie (a 64×64 checker of 8 cells; linear filtering, or nearest where the row says \
         so and in the zoom) on a 100°/120° spot tilted along \
         (1, −2, 0.5). Article 003 computes the coordinates as `0.5 + (acos(dot(L, up)) − π/2) / \
         (2 · acos(coneCos))` (and likewise with `left = normalize(cross(up, spotDir))`); the \
         library as `0.5 + atan(q.y, length(q.xz)) · scale` with the projector's basis and \
         scale from the CPU. Both map a direction to the same point; they differ where `dot` \
         rounds past ±1 (directions along ±up and ±left, inside cones wider than 90°), where \
         `acos` is NaN, and `acos` is ill-conditioned near ±1. \"Plane\" is the lit plane from \
         above; \"zoom along up\" looks at the point 90° off the axis along `up`, 50 units \
         from the light, 0.1 units across. The seed program is article 003's formulas \
         throughout (`seed_glsl`), equal to the library's elsewhere on this scene. NaN px \
         counts the fragments the NaN probe flags (a NaN colour, or a NaN texture \
         coordinate, which `texture()` turns into some texel).\n\n",
    );
    for r in rows {
        let _ = writeln!(
            out,
            "- {}: max {}, RMS {}, {} % > 1/255, {} NaN fragments; {} ms at {big}².",
            r.variant.name,
            f(r.error.max),
            f(r.error.rms),
            f(r.error.over_one_percent),
            r.non_finite,
            ms(r, big)
        );
    }
    if let (Some(lin), Some(near)) = (
        find(report, "projected cookie, library atan, plane"),
        find(report, "projected cookie, library atan, plane, nearest"),
    ) {
        let _ = write!(
            out,
            "\nOn the plane the library is {} off at most with linear filtering and {} with \
             nearest filtering, the same coordinates sampled without blending",
            f(lin.error.max),
            f(near.error.max)
        );
        if lin.error.max > 1.0 && near.error.max <= 1.0 {
            out.push_str(
                ": the excess over 1/255 is lavapipe's bilinear filter against exact \
                 bilinear interpolation, not the coordinates",
            );
        }
        out.push_str(".\n");
    }
    embed_picture(report, "report-acos.png", out);
}

fn program_section(report: &Report, out: &mut String) {
    let rows = group_rows(report, Group::Program);
    out.push_str("\n## Specialised program against the uber-shader\n\n");
    if rows.is_empty() {
        let where_ = report
            .settings
            .scenes
            .as_ref()
            .map_or("(no folder given)".into(), |p| p.display().to_string());
        let _ = writeln!(
            out,
            "Left out: the shared seed scenes were not found at `{where_}`."
        );
        return;
    }
    out.push_str(
        "Each shared seed scene's library equivalent (`presets::seed_equivalent`) drawn by the \
         specialised program (`generate`: only what the scene uses) and by the uber-shader \
         (`generate_uber`: every model, chosen by uniforms and branches). Same picture, \
         different cost. Sizes are the GLSL text in bytes; active uniforms as essl's link lists \
         them (an array once, as `getActiveUniform`); scalars are the floats and ints uploaded \
         per draw; \"unused\" counts declared-but-inactive uniforms plus unused functions (0: \
         the specialised programs are minimal).\n\n",
    );
    let sizes = &report.settings.time_sizes;
    let mut head = String::from(
        "| scene | program | vertex B | fragment B | active uniforms | scalars | unused | RMS | max |",
    );
    let mut rule = String::from("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
    for z in sizes {
        let _ = write!(head, " ms {z}² |");
        rule.push_str(" ---: |");
    }
    let _ = writeln!(out, "{head}\n{rule}");
    for r in &rows {
        let (scene, prog) = r
            .variant
            .name
            .split_once(", ")
            .unwrap_or((&r.variant.name, ""));
        let _ = write!(
            out,
            "| {scene} | {prog} | {} | {} | {} | {} | {} | {} | {} |",
            r.shader_bytes.0,
            r.shader_bytes.1,
            r.active_uniforms,
            r.uniform_scalars,
            r.unused,
            f(r.error.rms),
            f(r.error.max)
        );
        for &z in sizes {
            let _ = write!(out, " {} |", ms(r, z));
        }
        out.push('\n');
    }
    // Ratios uber / specialised at each size.
    let mut ratios: Vec<(u32, Vec<f64>)> = sizes.iter().map(|&z| (z, Vec::new())).collect();
    for pair in rows.chunks(2) {
        if let [s, u] = pair {
            if s.variant.program == ProgramKind::Specialised
                && u.variant.program == ProgramKind::Uber
            {
                for (z, v) in &mut ratios {
                    if let (Some(a), Some(b)) = (s.ms(*z), u.ms(*z)) {
                        v.push(b / a);
                    }
                }
            }
        }
    }
    out.push('\n');
    for (z, v) in ratios {
        if v.is_empty() {
            continue;
        }
        let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let med = super::median(&v).unwrap_or(f64::NAN);
        let _ = writeln!(
            out,
            "Uber-shader time / specialised time at {z}²: median {med:.2}×, range {lo:.2}–{hi:.2}× \
             over the {} scenes.",
            v.len()
        );
    }
}

fn stiff_section(report: &Report, out: &mut String) {
    out.push_str("\n## Stiff cases on the GPU\n\n");
    match &report.stiff {
        None => out.push_str(
            "Not run (`--quick`). The full run draws every (light model, stiff case) row of \
             `docs/numerical-stability.md` on the GPU.\n",
        ),
        Some(rows) => {
            let (total, seed, lib) = gpu_stiff::summary(rows);
            let nan_seed = rows.iter().filter(|r| !r.seed.finite()).count();
            let _ = writeln!(
                out,
                "Every (light model, stiff case) row of the CPU matrix drawn at {0}×{0} through \
                 essl-gl with the library's program and with the seed's (`gpu_stiff`; the \
                 table, beside the CPU's `highp` column, is in \
                 [numerical-stability.md](numerical-stability.md#the-matrix-on-the-gpu)): of \
                 {total} rows, the library's program is NaN or more than 1/255 off in **{lib}**, the seed's in \
                 **{seed}** ({nan_seed} of them with NaN or infinite fragments). \
                 `tests/it/gpu_stiff.rs` asserts the library's 0.",
                report.settings.stiff_size.unwrap_or(gpu_stiff::SIZE)
            );
        }
    }
}

/// The whole document.
pub fn markdown(report: &Report) -> String {
    let m = &report.machine;
    let s = &report.settings;
    let big = largest(report);
    let mut out = String::from(
        "# Error against run time: the light shaders on essl-gl\n\n\
         <!-- written by `essl report` (essl_lights::report); do not edit by hand -->\n\n",
    );
    let commit = m
        .commit
        .as_ref()
        .map_or(String::new(), |c| format!(", commit `{c}`"));
    let load = |l: Option<f64>| l.map_or("?".into(), |l| format!("{l:.1}"));
    let _ = writeln!(
        out,
        "Generated by `essl report{}` on {}{commit}, {} build. Machine: {} logical cores ({}), \
         load average {} at the start and {} at the end. Renderer: essl-gl on `{}` ({}), \
         Mesa's software rasteriser lavapipe. **Timings are noisy**: the machine is a shared \
         2-core VM where other builds run; each time is the median of {} rounds, each the \
         median of up to {} frames (at least 3; fewer for slow frames, about {:.0} ms a \
         variant a round), rounds interleaved across the variants (the spread column is the \
         range of the round medians, relative to the median).\n",
        if s.extent == super::Extent::Quick {
            " --quick"
        } else {
            ""
        },
        m.date,
        if m.release { "release" } else { "debug" },
        m.cores,
        m.cpu,
        load(m.load.0),
        load(m.load.1),
        m.renderer,
        m.driver,
        s.rounds,
        s.frames,
        super::FRAME_BUDGET_MS,
    );
    let _ = writeln!(
        out,
        "**Method.** Each variant is a lit scene on a geometry drawn by one program through \
         essl-gl's WebGL2 API. *Error*: the picture at {0}×{0} against the float64 reference: \
         the library's light model evaluated at every pixel of the same mesh, positions and \
         normals interpolated as GL interpolates them (`reference::render`; a band across hard \
         edges), so a Gouraud picture's interpolated colours are part of its error. In 1/255 \
         units per channel, the 8-bit rounding alone costing up to 0.5: the largest (max), the \
         RMS over all channels, and the pixels more than 1/255 off. **Mask**: pixels within 1 \
         pixel (Chebyshev) of a coverage change of the reference (silhouettes) are left out. \
         *NaN px*: fragments the NaN probe flags (the program with its output replaced by a \
         flag when the colour or a texture coordinate is NaN or infinite; an RGBA8 target \
         cannot show NaN). *Time*: ms per frame (clear + draw + `readPixels` of one pixel, \
         which waits for the GPU) at {1}. *Pareto*: ● on the front of all variants (no other \
         is both faster at {big}² and lower in RMS error), ○ on the front of its group only. \
         *emulated*: a `mediump` row, whose error comes from the CPU's binary16 emulation while \
         its time is lavapipe's, which computes in 32 bits; error and time do not describe one \
         run, so these rows are drawn as hollow triangles and take no part in either front.\n",
        s.error_size,
        s.time_sizes
            .iter()
            .map(|z| format!("{z}²"))
            .collect::<Vec<_>>()
            .join(" and "),
    );
    out.push_str("![RMS error against time per frame](report.svg)\n\n");
    let front: Vec<String> = report
        .results
        .iter()
        .filter(|r| r.pareto)
        .map(|r| format!("{} ({})", r.variant.name, r.variant.label))
        .collect();
    let _ = writeln!(
        out,
        "The Pareto front (RMS error against ms at {big}²): {}.\n",
        front.join("; ")
    );
    out.push_str("## All variants\n\n");
    out.push_str(&table(report));
    shading_section(report, &mut out);
    small_spot_section(report, &mut out);
    edge_section(report, &mut out);
    precision_section(report, &mut out);
    projector_section(report, &mut out);
    program_section(report, &mut out);
    stiff_section(report, &mut out);
    let _ = writeln!(
        out,
        "\n## Run\n\n`essl report{}` took {:.0} s of wall time ({} variants).",
        if s.extent == super::Extent::Quick {
            " --quick"
        } else {
            ""
        },
        report.wall_s,
        report.results.len()
    );
    out
}
