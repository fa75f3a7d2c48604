//! What the validation mode costs: many `uniform*` + `drawArrays` calls with validation off and
//! on, on article 000's spot light (`smoothstep(u_outerLimit, u_innerLimit, …)`, the
//! `pow(…, u_shininess)`, 16 uniforms that must be finite).
//!
//! `cargo run --release -p essl-gl --example validation_cost -- [DRAWS] [REPEATS]`
//!
//! Each draw is one triangle from generic attribute values into a 64×64 framebuffer, so that
//! the API's CPU work dominates; every 256 draws the batch is submitted and waited for
//! (`finish`). Modes, alternated `REPEATS` times (the median of each is printed):
//!
//! - `off`: validation off (the default);
//! - `on, values change`: validation on, five uniforms set to new valid values before every
//!   draw — every check is evaluated at every draw;
//! - `on, same values`: validation on, the same five values set before every draw — the
//!   checks compare the values' bytes with those last checked and stop there;
//! - `off, no uniform calls` and `on, no uniform calls`: draws only (with validation on, one
//!   version test per draw).
//!
//! With `VALIDATION_COST_OFF_ONLY` set, only the two `off` modes run (for a build of essl-gl
//! without validation).
//!
//! For each: nanoseconds per draw (the `uniform*` and `drawArrays` calls only, then with the
//! submissions), and the time of the first draw of the program (with validation on it
//! compiles and analyses the shaders).
//!
//! Lines marked `// validation` are the only ones that use the validation API, so that the
//! example also builds against essl-gl before it had one (`docs/runtime-checks.md`).

use std::time::{Duration, Instant};

use essl_gl::{gl, Context, Program};

const VERT: &str = include_str!("../../../shaders-glsl/spot-smooth-nbsp.fixed.vert");
const FRAG: &str = include_str!("../../essl-lint/tests/articles/spot-smooth-nbsp.fixed.frag");

#[derive(Clone, Copy, PartialEq, Debug)]
enum Mode {
    Off,
    OffNoCalls,
    Changing,
    Same,
    NoCalls,
}

impl Mode {
    fn name(self) -> &'static str {
        match self {
            Mode::Off => "off",
            Mode::OffNoCalls => "off, no uniform calls",
            Mode::Changing => "on, values change",
            Mode::Same => "on, same values",
            Mode::NoCalls => "on, no uniform calls",
        }
    }
}

fn program(ctx: &mut Context) -> Program {
    let p = ctx.create_program();
    for (ty, text) in [(gl::VERTEX_SHADER, VERT), (gl::FRAGMENT_SHADER, FRAG)] {
        let sh = ctx.create_shader(ty).expect("a shader type");
        ctx.shader_source(sh, text);
        ctx.compile_shader(sh);
        ctx.attach_shader(p, sh);
    }
    ctx.link_program(p);
    assert!(ctx.get_program_link_status(p), "link");
    ctx.use_program(Some(p));
    p
}

struct Run {
    api: Duration,
    total: Duration,
    first: Duration,
    warnings: usize,
}

fn run(mode: Mode, draws: usize) -> Run {
    let mut ctx = Context::new(64, 64).expect("a Vulkan adapter");
    ctx.set_validation(!matches!(mode, Mode::Off | Mode::OffNoCalls)); // validation
    let p = program(&mut ctx);
    let loc = |ctx: &mut Context, n: &str| ctx.get_uniform_location(p, n);
    let inner = loc(&mut ctx, "u_innerLimit");
    let outer = loc(&mut ctx, "u_outerLimit");
    let shininess = loc(&mut ctx, "u_shininess");
    let direction = loc(&mut ctx, "u_lightDirection");
    let color = loc(&mut ctx, "u_color");
    let identity = [
        1.0f32, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
    ];
    for m in [
        "u_world",
        "u_worldViewProjection",
        "u_worldInverseTranspose",
    ] {
        let l = loc(&mut ctx, m);
        ctx.uniform_matrix4fv(l, false, &identity);
    }
    let set = |ctx: &mut Context, i: usize| {
        let k = if mode == Mode::Changing {
            (i % 1000) as f32 * 1e-4
        } else {
            0.0
        };
        ctx.uniform1f(inner, 0.98 - k);
        ctx.uniform1f(outer, 0.9 - k);
        ctx.uniform1f(shininess, 150.0 + k);
        ctx.uniform3f(direction, 0.0, -1.0, k);
        ctx.uniform4f(color, 0.2, 1.0, 0.2 + k, 1.0);
    };
    set(&mut ctx, 0);
    // The first draw (with validation on: compiling and analysing the shaders).
    let t = Instant::now();
    ctx.draw_arrays(gl::TRIANGLES, 0, 3);
    let first = t.elapsed();
    ctx.finish();
    let mut api = Duration::ZERO;
    let start = Instant::now();
    let mut i = 0;
    while i < draws {
        let t = Instant::now();
        for _ in 0..256.min(draws - i) {
            i += 1;
            if !matches!(mode, Mode::NoCalls | Mode::OffNoCalls) {
                set(&mut ctx, i);
            }
            ctx.draw_arrays(gl::TRIANGLES, 0, 3);
        }
        api += t.elapsed();
        ctx.finish();
    }
    let total = start.elapsed();
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    let warnings = ctx.take_validation_warnings().len(); // validation
    Run {
        api,
        total,
        first,
        warnings,
    }
}

/// Each run's ns per draw (calls, with submits), first draw (ms), and the warnings.
#[derive(Default)]
struct Samples {
    api: Vec<f64>,
    total: Vec<f64>,
    first: Vec<f64>,
    warnings: usize,
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
        std::env::set_var("XDG_RUNTIME_DIR", std::env::temp_dir());
    }
    let mut args = std::env::args().skip(1);
    let draws: usize = args.next().map_or(20_000, |a| a.parse().expect("DRAWS"));
    let repeats: usize = args.next().map_or(7, |a| a.parse().expect("REPEATS"));
    let modes = [
        Mode::Off,
        Mode::Changing,
        Mode::Same,
        Mode::OffNoCalls,
        Mode::NoCalls,
    ];
    let modes: Vec<Mode> = if std::env::var_os("VALIDATION_COST_OFF_ONLY").is_some() {
        vec![Mode::Off, Mode::OffNoCalls]
    } else {
        modes.to_vec()
    };
    // Warm-up (pipelines, allocator).
    run(Mode::Off, 2_000);
    let mut results: Vec<Samples> = modes.iter().map(|_| Samples::default()).collect();
    for _ in 0..repeats {
        for (m, r) in modes.iter().zip(results.iter_mut()) {
            let x = run(*m, draws);
            r.api.push(x.api.as_nanos() as f64 / draws as f64);
            r.total.push(x.total.as_nanos() as f64 / draws as f64);
            r.first.push(x.first.as_secs_f64() * 1e3);
            r.warnings = x.warnings;
        }
    }
    let adapter = Context::new(1, 1)
        .map(|c| c.adapter_info().name.clone())
        .unwrap_or_default();
    println!("{draws} draws × {repeats} runs per mode, median per run; adapter: {adapter}");
    println!("| mode | ns/draw (uniform* + draw calls) | ns/draw (with submits) | first draw (ms) | warnings |");
    println!("|---|---|---|---|---|");
    for (m, r) in modes.iter().zip(results.iter_mut()) {
        println!(
            "| {} | {:.0} | {:.0} | {:.2} | {} |",
            m.name(),
            median(&mut r.api),
            median(&mut r.total),
            median(&mut r.first),
            r.warnings
        );
    }
}
