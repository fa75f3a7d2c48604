//! The score as Markdown: the tables `essl conformance` prints and the page it writes
//! (`docs/conformance.md`), with what the corpora are, the test's thresholds and the peers.

use std::fmt::Write as _;

use super::Report;

/// The GLSL ES 1.00 cases per context, essl and glslangValidator side by side.
fn es100_table(r: &super::Es100Report) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "GLSL ES 1.00 WebGL conformance cases (`webgl_conformance_es100.jsonl`), against Chromium's answer in each context:"
    );
    let _ = writeln!(s);
    let peer = r
        .glslang_version
        .as_deref()
        .unwrap_or("glslangValidator (not run)");
    let _ = writeln!(
        s,
        "| context | essl: Chromium-accepted accepted | essl: Chromium-rejected rejected | glslangValidator: accepted | glslangValidator: rejected |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|");
    for target in [essl::Target::WebGl1, essl::Target::WebGl2] {
        let c = r.context(target);
        let (ga, gr) = match &c.glslang {
            Some((a, b)) => (a.cell(), b.cell()),
            None => ("–".to_string(), "–".to_string()),
        };
        let _ = writeln!(
            s,
            "| {} | {} | {} | {ga} | {gr} |",
            target.display(),
            c.accepted.cell(),
            c.rejected.cell()
        );
    }
    let _ = writeln!(s);
    let _ = writeln!(
        s,
        "Peer: {peer} (compile both shaders, `-l` link), same run."
    );
    s
}

impl Report {
    /// The score as Markdown tables (a summary, then dEQP per file).
    pub fn tables(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "| corpus | expected to build: ok/total | expected to fail: ok/total |"
        );
        let _ = writeln!(s, "|---|---|---|");
        let _ = writeln!(
            s,
            "| WebGL conformance (must_pass / must_fail) | {} | {} |",
            self.webgl.pass.cell(),
            self.webgl.fail.cell()
        );
        let _ = writeln!(s, "| dEQP GLES3, `300 es` (pass + build_successful / compile_fail, link_fail, compile_link_fail) | {} | {} |", self.deqp.pass.cell(), self.deqp.fail.cell());
        let _ = writeln!(
            s,
            "| glslang tests (compile status agrees with `expect_compile`) | {} | {} |",
            self.glslang.clean.cell(),
            self.glslang.errors.cell()
        );
        let _ = writeln!(
            s,
            "| webgl2fundamentals (all must compile; {} skipped: templated or no stage) | {} | – |",
            self.fundamentals_skipped,
            self.fundamentals.cell()
        );
        if let Some(es100) = &self.es100 {
            let _ = writeln!(s);
            s.push_str(&es100_table(es100));
        }
        let _ = writeln!(s);
        let _ = writeln!(
            s,
            "glslang: essl reports an error on {} of the expected error lines.",
            self.glslang.error_lines.cell()
        );
        let _ = writeln!(s);
        let _ = writeln!(s, "dEQP per file:");
        let _ = writeln!(s);
        let _ = writeln!(s, "| file | pass cases ok/total | fail cases ok/total |");
        let _ = writeln!(s, "|---|---|---|");
        for row in &self.deqp_files {
            let _ = writeln!(
                s,
                "| `{}` | {} | {} |",
                row.name,
                row.pass.cell(),
                row.fail.cell()
            );
        }
        s
    }

    /// The score as a Markdown page: what the corpora are, the test's thresholds, the peers, the
    /// tables, and any threshold the score is below.
    pub fn markdown(&self) -> String {
        let mut s = String::from(MARKDOWN_INTRO);
        s.push_str("\n## Score\n\n");
        s.push_str(&self.tables());
        s.push_str("\n## Where essl disagrees\n\n");
        if self.failures.is_empty() {
            s.push_str("Nowhere.\n");
        } else if self.failures.len() > 100 {
            let _ = writeln!(
                s,
                "{} cases (list them with `essl conformance --failures`).",
                self.failures.len()
            );
        } else {
            for f in &self.failures {
                let _ = writeln!(
                    s,
                    "- {} `{}`: expected {}, essl: {}",
                    f.corpus, f.case, f.expected, f.got
                );
            }
        }
        s.push('\n');
        s.push_str(KNOWN_GAPS);
        let unmet = self.unmet_bars();
        if !unmet.is_empty() {
            s.push_str("\n## Below the test's thresholds\n\n");
            for u in unmet {
                let _ = writeln!(s, "- {u}");
            }
        }
        s
    }
}

/// Where essl answers differently from a WebGL browser beyond the scored cases.
const KNOWN_GAPS: &str = "\
## Known gaps

Where essl still answers differently from a WebGL browser, beyond the cases above:

- **Extensions of WebGL 2:** `essl::compile` offers GLSL ES 3.00 shaders four extensions,
  `GL_ANGLE_clip_cull_distance` (`WEBGL_clip_cull_distance`: `gl_ClipDistance[8]`, and
  `gl_CullDistance` with `gl_MaxCullDistances` 0, as the extension allows where a device has no
  cull distances), `GL_EXT_conservative_depth` (`layout(depth_any | depth_greater |
  depth_less)` on `gl_FragDepth`), `GL_NV_shader_noperspective_interpolation` (the
  `noperspective` qualifier) and `GL_ANGLE_multi_draw` (`WEBGL_multi_draw`: `gl_DrawID`, in
  GLSL ES 1.00 shaders of either context too). Another `#extension NAME : require` is an
  error and `enable` or `warn` a warning, the extension's features staying unavailable, where a
  browser accepts the extensions its WebGL 2 implementation exposes (`OVR_multiview2`, …). A WebGL 1 context offers GLSL ES 1.00 shaders
  `OES_standard_derivatives`, `EXT_shader_texture_lod`, `EXT_frag_depth` and
  `WEBGL_draw_buffers` (`CompileOptions::extensions`).
- **Limits that depend on the device** are those of the reference implementation (Chromium
  156, ANGLE on SwiftShader: `tests/oracle/ES100.md`); past WebGL's guaranteed minimums a
  shader gets a warning, not an error, as it links there.
- **Differential testing** (`tests/differential/essl-wrong/`, run by
  `crates/essl/tests/it/differential.rs`): every minimised case where essl answered otherwise
  than Chromium agrees with it. See [differential testing](differential.md#where-essl-differs-from-chromium).

Rendering has its own list: [what essl-gl does not do](rendering.md#what-differs-from-webgl2).
";

const MARKDOWN_INTRO: &str = "\
# Conformance

How often essl's front end accepts and rejects shaders as the upstream conformance suites
expect. Generated by `cargo run --release -p essl-cli -- conformance --markdown docs/conformance.md`
from the corpora in `../shared/corpora/` (see its README); scored with each harness's own rules.
The score is **compile + link** (`essl::compile`, with whatever checking and lowering it does, then
`essl::link::link`); rendering and the dEQP value checks are not scored.

## The corpora

- **WebGL conformance** (`webgl_conformance_es300.jsonl`): the Khronos WebGL2 conformance tests
  whose shader is `#version 300 es` — 159 must_pass cases (both shaders compile and the program
  links) and 67 must_fail cases (pass if compiling *or* linking fails).
- **dEQP GLES3** (`deqp_gles3.jsonl`): dEQP's shader tests as the WebGL2 suite runs them, only
  the `300 es` cases. `pass`/`build_successful` need compile and link to succeed; `compile_fail`
  needs a shader to fail to compile; `link_fail` needs both shaders to compile and the link to
  fail; `compile_link_fail` accepts either failure.
- **glslang tests** (`glslang_es300.jsonl`): glslang's own `300 es` test files; essl's compile
  status should agree with `expect_compile`, and the table counts how many of glslang's expected error
  lines essl reports an error on (a measure of where errors are reported, with no threshold). glslang
  is more permissive than WebGL2 in places (its clean files include a shader with no `main`,
  which WebGL2 rejects at compile time), so this row informs and has no threshold.
- **webgl2fundamentals** (`webgl2fundamentals_shaders.jsonl`): the lessons' shaders; every one
  with a stage and no `${...}` template must compile.
- **WebGL conformance, GLSL ES 1.00** (`webgl_conformance_es100.jsonl`): the same suite's 2,021
  cases whose shaders are GLSL ES 1.00, each with what Chromium answered in a WebGL 1 and in a
  WebGL 2 context (no extension enabled, as the test pages ran). A case agrees when essl, for
  that context (`CompileOptions::target`, no extensions), accepts it — both shaders compile and
  the program links — exactly when Chromium does. Chromium's answer wins over the upstream
  `outcome` where they differ (26 cases whose pages queried the implementation's limits).
  glslangValidator runs on the same cases in the same run (`essl conformance`), for comparison.

Cases whose vertex or fragment source is empty use a trivial valid shader of that stage.

## The test's thresholds and the peers

| | WebGL must_pass | WebGL must_fail | dEQP pass | dEQP fail | webgl2fundamentals |
|---|---|---|---|---|---|
| **test threshold** | ≥ 155/159 | ≥ 60/67 | ≥ 97% | ≥ 95% | all |
| glslangValidator 12.0.0 (compile + `-l` link) | 155/159 | 52/67 | 4,285/4,287 | 1,332/1,348 | |
| naga 30.0.1 GLSL front end | 0 (rejects `#version 300 es`) | | 0 | | |

`crates/essl-cli/tests/it/conformance.rs` fails when a score is below its threshold.
(The peers' dEQP figures are the corpora README's, counted over all 35 files with its own case
split; with `#version 450 core` substituted naga accepts 68/159 WebGL and 10/4,287 dEQP
must-pass cases.) The threshold for the GLSL ES 1.00 cases is, in each context, at least 99.5% of the
cases Chromium accepts accepted and at least 99.5% of those it rejects rejected; glslang's
figures for them are in the table below the score, from the same run.
";
