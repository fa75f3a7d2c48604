//! `essl conformance`: scores the front end on the conformance corpora (`../shared/corpora/`)
//! with each upstream harness's own rules (the corpora README's "How to score").
//!
//! The scoring is compile + link: a case "passes" when essl accepts or rejects it as the
//! harness expects (no rendering, no value checks).

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use essl::link::link;
use essl::source::SourceFile;
use essl::{compile, CompileOptions, Shader, Stage};
use rayon::prelude::*;
use serde::Deserialize;

/// The WebGL corpus file.
pub const WEBGL: &str = "webgl_conformance_es300.jsonl";
/// The dEQP corpus file.
pub const DEQP: &str = "deqp_gles3.jsonl";
/// The glslang corpus file.
pub const GLSLANG: &str = "glslang_es300.jsonl";
/// The webgl2fundamentals corpus file.
pub const FUNDAMENTALS: &str = "webgl2fundamentals_shaders.jsonl";

/// The vertex shader used where a case has none.
pub const TRIVIAL_VERTEX: &str =
    "#version 300 es\nvoid main() {\n    gl_Position = vec4(0.0);\n}\n";
/// The fragment shader used where a case has none.
pub const TRIVIAL_FRAGMENT: &str = "#version 300 es\nprecision mediump float;\nout vec4 color;\nvoid main() {\n    color = vec4(0.0, 1.0, 0.0, 1.0);\n}\n";

/// `ok` of `total` cases agree with the expectation.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Tally {
    /// Cases where essl does what the harness expects.
    pub ok: usize,
    /// Cases.
    pub total: usize,
}

impl Tally {
    fn add(&mut self, ok: bool) {
        self.ok += ok as usize;
        self.total += 1;
    }

    /// The share that agrees, in percent (100 when there are no cases).
    pub fn percent(&self) -> f64 {
        if self.total == 0 {
            100.0
        } else {
            100.0 * self.ok as f64 / self.total as f64
        }
    }

    /// `ok/total (pp.p%)`, or `–` when there are no cases.
    pub fn cell(&self) -> String {
        if self.total == 0 {
            "–".to_string()
        } else {
            format!("{}/{} ({:.1}%)", self.ok, self.total, self.percent())
        }
    }
}

/// Agreement on one group of cases: those expected to build and those expected to fail.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Row {
    /// The group (a corpus or a dEQP file).
    pub name: String,
    /// Cases expected to compile and link.
    pub pass: Tally,
    /// Cases expected to fail.
    pub fail: Tally,
}

/// The glslang corpus's score.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct GlslangScore {
    /// Files expected to compile that essl compiles.
    pub clean: Tally,
    /// Files expected to fail that essl rejects.
    pub errors: Tally,
    /// Expected error lines on which essl reports an error.
    pub error_lines: Tally,
}

/// A case where essl disagrees with the harness.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Failure {
    /// The corpus.
    pub corpus: &'static str,
    /// The case (`file` and name or index).
    pub case: String,
    /// What the harness expects.
    pub expected: String,
    /// essl's first error, or what else it did.
    pub got: String,
}

/// The whole score.
#[derive(Clone, Debug, Default)]
pub struct Report {
    /// WebGL conformance: must_pass / must_fail.
    pub webgl: Row,
    /// dEQP, all `300 es` cases.
    pub deqp: Row,
    /// dEQP per `.test` file.
    pub deqp_files: Vec<Row>,
    /// glslang's tests.
    pub glslang: GlslangScore,
    /// webgl2fundamentals: shaders that must compile.
    pub fundamentals: Tally,
    /// webgl2fundamentals shaders skipped (templated or with no stage).
    pub fundamentals_skipped: usize,
    /// Every disagreement.
    pub failures: Vec<Failure>,
}

/// The bars the project holds itself to.
pub mod bars {
    /// WebGL must_pass cases that must pass.
    pub const WEBGL_PASS: usize = 155;
    /// WebGL must_fail cases that must fail.
    pub const WEBGL_FAIL: usize = 60;
    /// dEQP pass cases, percent.
    pub const DEQP_PASS_PERCENT: f64 = 97.0;
    /// dEQP fail cases, percent.
    pub const DEQP_FAIL_PERCENT: f64 = 95.0;
}

impl Report {
    /// The bars that are not met, in words (empty when all are).
    pub fn unmet_bars(&self) -> Vec<String> {
        let mut out = Vec::new();
        if self.webgl.pass.ok < bars::WEBGL_PASS {
            out.push(format!(
                "WebGL must_pass {} < {}",
                self.webgl.pass.ok,
                bars::WEBGL_PASS
            ));
        }
        if self.webgl.fail.ok < bars::WEBGL_FAIL {
            out.push(format!(
                "WebGL must_fail {} < {}",
                self.webgl.fail.ok,
                bars::WEBGL_FAIL
            ));
        }
        if self.deqp.pass.percent() < bars::DEQP_PASS_PERCENT {
            out.push(format!(
                "dEQP pass {:.1}% < {}%",
                self.deqp.pass.percent(),
                bars::DEQP_PASS_PERCENT
            ));
        }
        if self.deqp.fail.percent() < bars::DEQP_FAIL_PERCENT {
            out.push(format!(
                "dEQP fail {:.1}% < {}%",
                self.deqp.fail.percent(),
                bars::DEQP_FAIL_PERCENT
            ));
        }
        if self.fundamentals.ok < self.fundamentals.total {
            out.push(format!(
                "webgl2fundamentals {}/{} compile",
                self.fundamentals.ok, self.fundamentals.total
            ));
        }
        out
    }

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

    /// The score as a Markdown page: what the corpora are, the bars, the peers, the tables.
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
        s.push_str("\n## Bars\n\n");
        let unmet = self.unmet_bars();
        if unmet.is_empty() {
            s.push_str("All bars are met.\n");
        } else {
            s.push_str("Not met yet:\n\n");
            for u in unmet {
                let _ = writeln!(s, "- {u}");
            }
        }
        s
    }
}

/// Where essl answers differently from a WebGL2 browser beyond the scored cases.
const KNOWN_GAPS: &str = "\
## Known gaps

Where essl still answers differently from a WebGL2 browser, beyond the cases above:

- **GLSL ES 1.00 shaders are not compiled yet.** WebGL2 compiles a shader that does not start
  with `#version 300 es` (or that says `#version 100`) as GLSL ES 1.00; essl reports it as an
  error (`missing-version`, with a help on what to change for ES 3.00) and checks the rest as
  ES 3.00, so `attribute`, `varying` and `gl_FragColor` add their own errors. The scores above count `300 es` cases only; the ES 1.00 WebGL conformance cases
  (`webgl_conformance_es100.jsonl`) are not scored.
- **Valid shaders not lowered yet:** arrays of uniform blocks, a struct or array of samplers as
  a function parameter, and `texture()` on an integer cube sampler are accepted by WebGL2; essl
  checks them and then reports an `unsupported` error.
- **Extensions:** `essl::compile` supports no shader extension. `#extension NAME : require`
  is an error (`GL_EXT_conservative_depth` above) and `enable` or `warn` a warning, the
  extension's features staying unavailable, where a browser accepts the extensions its WebGL2
  implementation exposes.

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
  lines essl reports an error on (a measure of where errors are reported, not a bar). glslang
  is more permissive than WebGL2 in places (its clean files include a shader with no `main`,
  which WebGL2 rejects at compile time), so this row informs and is not a bar.
- **webgl2fundamentals** (`webgl2fundamentals_shaders.jsonl`): the lessons' shaders; every one
  with a stage and no `${...}` template must compile.

Cases whose vertex or fragment source is empty use a trivial valid shader of that stage.

## The bar and the peers

| | WebGL must_pass | WebGL must_fail | dEQP pass | dEQP fail | webgl2fundamentals |
|---|---|---|---|---|---|
| **bar** | ≥ 155/159 | ≥ 60/67 | ≥ 97% | ≥ 95% | all |
| glslangValidator 12.0.0 (compile + `-l` link) | 155/159 | 52/67 | 4,285/4,287 | 1,332/1,348 | |
| naga 30.0.1 GLSL front end | 0 (rejects `#version 300 es`) | | 0 | | |

(The peers' dEQP figures are the corpora README's, counted over all 35 files with its own case
split; with `#version 450 core` substituted naga accepts 68/159 WebGL and 10/4,287 dEQP
must-pass cases.)
";

#[derive(Deserialize)]
struct WebglCase {
    file: String,
    index: serde_json::Value,
    vertex_source: Option<String>,
    fragment_source: Option<String>,
    outcome: String,
}

#[derive(Deserialize)]
struct DeqpCase {
    file: String,
    name: String,
    expect: String,
    version: Option<String>,
    vertex_source: Option<String>,
    fragment_source: Option<String>,
}

#[derive(Deserialize)]
struct GlslangCase {
    file: String,
    stage: String,
    source: String,
    expect_compile: bool,
    #[serde(default)]
    error_lines: Option<Vec<u32>>,
}

#[derive(Deserialize)]
struct FundamentalsCase {
    file: String,
    stage: Option<String>,
    source: String,
    #[serde(default)]
    templated: bool,
}

/// Why the corpora could not be scored.
#[derive(Debug)]
pub struct CorpusError {
    /// The file.
    pub path: PathBuf,
    /// What went wrong.
    pub message: String,
}

impl std::fmt::Display for CorpusError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.path.display(), self.message)
    }
}

fn read_jsonl<T: for<'de> Deserialize<'de>>(dir: &Path, name: &str) -> Result<Vec<T>, CorpusError> {
    let path = dir.join(name);
    let text = std::fs::read_to_string(&path).map_err(|e| CorpusError {
        path: path.clone(),
        message: crate::files::io_message(&e),
    })?;
    text.lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
        .map(|(i, l)| {
            serde_json::from_str(l).map_err(|e| CorpusError {
                path: path.clone(),
                message: format!("line {}: {e}", i + 1),
            })
        })
        .collect()
}

fn stage_of(name: &str) -> Option<Stage> {
    match name {
        "vertex" | "vert" => Some(Stage::Vertex),
        "fragment" | "frag" => Some(Stage::Fragment),
        _ => None,
    }
}

fn compile_or_trivial(name: &str, source: Option<&str>, stage: Stage) -> Shader {
    let text = match source {
        Some(s) if !s.trim().is_empty() => s,
        _ => match stage {
            Stage::Vertex => TRIVIAL_VERTEX,
            Stage::Fragment => TRIVIAL_FRAGMENT,
        },
    };
    compile(
        SourceFile::new(name, text),
        stage,
        &CompileOptions::default(),
    )
}

/// What compiling and linking a pair gave.
struct Built {
    vertex_ok: bool,
    fragment_ok: bool,
    link_ok: bool,
    first_error: String,
}

fn build(name: &str, vertex: Option<&str>, fragment: Option<&str>) -> Built {
    let vs = compile_or_trivial(&format!("{name}.vert"), vertex, Stage::Vertex);
    let fs = compile_or_trivial(&format!("{name}.frag"), fragment, Stage::Fragment);
    let program = link(&vs, &fs);
    let first_error = [&vs, &fs]
        .iter()
        .find_map(|s| {
            s.diagnostics.iter().find(|d| d.is_error()).map(|d| {
                let line = s.file.line_of(d.span.start);
                format!("{} line {line}: {}", s.stage.as_str(), d.message)
            })
        })
        .or_else(|| program.log.lines().next().map(|l| format!("link: {l}")))
        .unwrap_or_default();
    Built {
        vertex_ok: vs.ok(),
        fragment_ok: fs.ok(),
        link_ok: program.ok,
        first_error,
    }
}

impl Built {
    fn all_ok(&self) -> bool {
        self.vertex_ok && self.fragment_ok && self.link_ok
    }

    fn got(&self) -> String {
        if self.all_ok() {
            "compiled and linked".to_string()
        } else {
            self.first_error.clone()
        }
    }
}

/// Scores every corpus in `dir` (the folder holding the four `.jsonl` files).
pub fn score(dir: &Path) -> Result<Report, CorpusError> {
    let mut report = Report::default();
    score_webgl(dir, &mut report)?;
    score_deqp(dir, &mut report)?;
    score_glslang(dir, &mut report)?;
    score_fundamentals(dir, &mut report)?;
    Ok(report)
}

fn score_webgl(dir: &Path, report: &mut Report) -> Result<(), CorpusError> {
    let cases: Vec<WebglCase> = read_jsonl(dir, WEBGL)?;
    let results: Vec<(bool, bool, Option<Failure>)> = cases
        .par_iter()
        .filter(|c| c.outcome == "must_pass" || c.outcome == "must_fail")
        .map(|c| {
            let case = format!("{}#{}", c.file, c.index);
            let built = build(
                &case,
                c.vertex_source.as_deref(),
                c.fragment_source.as_deref(),
            );
            let must_pass = c.outcome == "must_pass";
            let ok = built.all_ok() == must_pass;
            let failure = (!ok).then(|| Failure {
                corpus: "webgl",
                case,
                expected: c.outcome.clone(),
                got: built.got(),
            });
            (must_pass, ok, failure)
        })
        .collect();
    report.webgl.name = "WebGL conformance".into();
    for (must_pass, ok, failure) in results {
        if must_pass {
            &mut report.webgl.pass
        } else {
            &mut report.webgl.fail
        }
        .add(ok);
        report.failures.extend(failure);
    }
    Ok(())
}

fn score_deqp(dir: &Path, report: &mut Report) -> Result<(), CorpusError> {
    let cases: Vec<DeqpCase> = read_jsonl(dir, DEQP)?;
    let results: Vec<(&str, bool, bool, Option<Failure>)> = cases
        .par_iter()
        .filter(|c| c.version.as_deref() == Some("300 es"))
        .map(|c| {
            let built = build(
                &c.name,
                c.vertex_source.as_deref(),
                c.fragment_source.as_deref(),
            );
            let compiled = built.vertex_ok && built.fragment_ok;
            let (pass_case, ok) = match c.expect.as_str() {
                "pass" | "build_successful" => (true, built.all_ok()),
                "compile_fail" => (false, !compiled),
                "link_fail" => (false, compiled && !built.link_ok),
                "compile_link_fail" => (false, !built.all_ok()),
                _ => (false, false),
            };
            let failure = (!ok).then(|| Failure {
                corpus: "deqp",
                case: format!("{} {}", c.file, c.name),
                expected: c.expect.clone(),
                got: built.got(),
            });
            (c.file.as_str(), pass_case, ok, failure)
        })
        .collect();
    let mut files: BTreeMap<&str, Row> = BTreeMap::new();
    report.deqp.name = "dEQP GLES3".into();
    for (file, pass_case, ok, failure) in results {
        let name = file.rsplit('/').next().unwrap_or(file);
        let row = files.entry(name).or_insert_with(|| Row {
            name: name.to_string(),
            ..Row::default()
        });
        if pass_case {
            row.pass.add(ok);
            report.deqp.pass.add(ok);
        } else {
            row.fail.add(ok);
            report.deqp.fail.add(ok);
        }
        report.failures.extend(failure);
    }
    report.deqp_files = files.into_values().collect();
    Ok(())
}

fn score_glslang(dir: &Path, report: &mut Report) -> Result<(), CorpusError> {
    let cases: Vec<GlslangCase> = read_jsonl(dir, GLSLANG)?;
    for c in &cases {
        let Some(stage) = stage_of(&c.stage) else {
            continue;
        };
        let shader = compile(
            SourceFile::new(c.file.as_str(), c.source.as_str()),
            stage,
            &CompileOptions::default(),
        );
        let ok = shader.ok() == c.expect_compile;
        if c.expect_compile {
            &mut report.glslang.clean
        } else {
            &mut report.glslang.errors
        }
        .add(ok);
        let error_lines: std::collections::BTreeSet<u32> = shader
            .diagnostics
            .iter()
            .filter(|d| d.is_error())
            .map(|d| shader.file.line_of(d.span.start))
            .collect();
        let mut expected: Vec<u32> = c.error_lines.clone().unwrap_or_default();
        expected.sort_unstable();
        expected.dedup();
        for line in expected {
            report.glslang.error_lines.add(error_lines.contains(&line));
        }
        if !ok {
            report.failures.push(Failure {
                corpus: "glslang",
                case: c.file.clone(),
                expected: if c.expect_compile {
                    "compiles"
                } else {
                    "compile error"
                }
                .into(),
                got: shader
                    .diagnostics
                    .iter()
                    .find(|d| d.is_error())
                    .map(|d| format!("line {}: {}", shader.file.line_of(d.span.start), d.message))
                    .unwrap_or_else(|| "compiled".into()),
            });
        }
    }
    Ok(())
}

fn score_fundamentals(dir: &Path, report: &mut Report) -> Result<(), CorpusError> {
    let cases: Vec<FundamentalsCase> = read_jsonl(dir, FUNDAMENTALS)?;
    let results: Vec<Option<(bool, Option<Failure>)>> = cases
        .par_iter()
        .map(|c| {
            let stage = c
                .stage
                .as_deref()
                .and_then(stage_of)
                .filter(|_| !c.templated)?;
            let shader = compile(
                SourceFile::new(c.file.as_str(), c.source.as_str()),
                stage,
                &CompileOptions::default(),
            );
            let failure = (!shader.ok()).then(|| Failure {
                corpus: "webgl2fundamentals",
                case: c.file.clone(),
                expected: "compiles".into(),
                got: shader
                    .diagnostics
                    .iter()
                    .find(|d| d.is_error())
                    .map(|d| format!("line {}: {}", shader.file.line_of(d.span.start), d.message))
                    .unwrap_or_default(),
            });
            Some((shader.ok(), failure))
        })
        .collect();
    for r in results {
        match r {
            None => report.fundamentals_skipped += 1,
            Some((ok, failure)) => {
                report.fundamentals.add(ok);
                report.failures.extend(failure);
            }
        }
    }
    Ok(())
}

/// Runs `essl conformance`: prints the tables (and the failures with `list_failures`), writes
/// the Markdown page when asked, and returns the exit status (0, or 2 when the corpora cannot
/// be read or the page cannot be written).
pub fn run(corpora: &Path, markdown: Option<&Path>, list_failures: bool) -> i32 {
    let report = match score(corpora) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("error: cannot read the corpora: {e}");
            return 2;
        }
    };
    if list_failures {
        for f in &report.failures {
            println!(
                "{}: {}: expected {}, got {}",
                f.corpus, f.case, f.expected, f.got
            );
        }
        println!();
    }
    print!("{}", report.tables());
    let unmet = report.unmet_bars();
    if unmet.is_empty() {
        println!("\nall bars met");
    } else {
        println!("\nbars not met: {}", unmet.join("; "));
    }
    if let Some(path) = markdown {
        if let Err(e) = std::fs::write(path, report.markdown()) {
            eprintln!(
                "error: cannot write `{}`: {}",
                path.display(),
                crate::files::io_message(&e)
            );
            return 2;
        }
    }
    0
}
