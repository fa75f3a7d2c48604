//! Every call script of `tests/gl-scripts/`, mutated — a call dropped, repeated or moved, a
//! number replaced by an edge value, an object by `null`, an enum by another — and replayed
//! through essl-gl. A mutated script may fail its own checks (that is the point of most
//! mutations), but essl-gl must answer every call with a WebGL error, never a panic, and wgpu
//! must report nothing: essl-gl checks each call before it reaches the GPU, so an error from
//! wgpu is a call essl-gl let through that WebGL would refuse.
//!
//! The mutations are drawn from a fixed seed, so a failure names the script and the mutation
//! that reproduce it.

use std::panic::{catch_unwind, AssertUnwindSafe};

use crate::common;

use common::{adapter, scripts};
use essl_gl_script::{read_script, replay, Arg, Phase, ReplayOptions, Script};

/// Mutations per script; `ESSL_GL_MUTATIONS=N` asks for more (a longer hunt).
const PER_SCRIPT: u64 = 4;

/// Numbers a mutation puts in place of an argument: signs, zero, small counts, sizes past
/// every limit, offsets past every buffer.
const EDGE_NUMBERS: &[f64] = &[-1.0, 0.0, 1.0, 3.0, 255.0, 4096.0, 1_000_000.0];

/// Enums a mutation puts in place of another.
const ENUMS: &[&str] = &[
    "TEXTURE_2D",
    "FRAMEBUFFER",
    "RGBA8",
    "DEPTH_COMPONENT16",
    "FLOAT",
    "UNSIGNED_BYTE",
    "TRIANGLES",
    "COLOR_ATTACHMENT3",
    "NONE",
];

/// xorshift64*: deterministic and dependency-free.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

/// Applies one mutation to `script`; what it did, for the failure message.
fn mutate(script: &mut Script, rng: &mut Rng) -> String {
    let frame = rng.below(4) == 0 && !script.frame.is_empty();
    let calls = if frame {
        &mut script.frame
    } else {
        &mut script.setup
    };
    if calls.is_empty() {
        return "nothing (no calls)".into();
    }
    let i = rng.below(calls.len());
    let name = calls[i].f.clone();
    match rng.below(6) {
        0 => {
            calls.remove(i);
            format!("dropped call {i} ({name})")
        }
        1 => {
            let c = calls[i].clone();
            calls.insert(i, c);
            format!("repeated call {i} ({name})")
        }
        2 => {
            let j = rng.below(calls.len());
            let c = calls.remove(i);
            calls.insert(j.min(calls.len()), c);
            format!("moved call {i} ({name}) to {j}")
        }
        kind => {
            let call = &mut calls[i];
            if call.args.is_empty() {
                return format!("nothing ({name} has no arguments)");
            }
            let a = rng.below(call.args.len());
            let new = match kind {
                3 => Arg::Number(EDGE_NUMBERS[rng.below(EDGE_NUMBERS.len())]),
                4 => Arg::Null,
                _ => Arg::Number(
                    essl_gl::gl::by_name(ENUMS[rng.below(ENUMS.len())]).expect("an enum") as f64,
                ),
            };
            let text = format!("argument {a} of call {i} ({name}) → {new:?}");
            call.args[a] = new;
            text
        }
    }
}

#[test]
fn mutated_scripts_get_webgl_errors_not_panics() {
    if !adapter() {
        return;
    }
    let root = essl_testdata::repo_root().join("tests/gl-scripts");
    let mut paths = scripts(&root);
    paths.extend(scripts(&root.join("probes")));
    let mut problems = Vec::new();
    let mut replays = 0;
    let per_script = std::env::var("ESSL_GL_MUTATIONS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(PER_SCRIPT);
    for (n, path) in paths.iter().enumerate() {
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        let original = read_script(path).unwrap();
        for k in 0..per_script {
            let mut rng = Rng(0x9E37_79B9_7F4A_7C15 ^ ((n as u64) << 16 | k));
            let mut script = original.clone();
            let what = mutate(&mut script, &mut rng);
            let options = ReplayOptions::default();
            replays += 1;
            match catch_unwind(AssertUnwindSafe(|| replay(&script, &options))) {
                Err(_) => problems.push(format!("{name}, {what}: panicked")),
                Ok(Err(e)) => problems.push(format!("{name}, {what}: {e}")),
                Ok(Ok(r)) => {
                    for f in r
                        .results
                        .failures
                        .iter()
                        .filter(|f| f.phase == Phase::Runner)
                    {
                        if f.f == "wgpu" {
                            problems.push(format!("{name}, {what}: {}", f.message));
                        }
                    }
                }
            }
        }
    }
    println!("{replays} mutated replays");
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}
