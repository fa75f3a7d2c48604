//! `essl conformance`: scores the front end on the conformance corpora (`../shared/corpora/`)
//! with each upstream harness's own rules (the corpora README's "How to score").
//!
//! The scoring is compile + link: a case "passes" when essl accepts or rejects it as the
//! harness expects (no rendering, no value checks).

mod es100;
mod es300;
mod markdown;
mod peer;

use std::path::{Path, PathBuf};

use essl::link::link;
use essl::source::SourceFile;
use essl::{compile, CompileOptions, Shader, Stage};
use serde::Deserialize;

pub use es100::{ContextScore, Es100Report};

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
    /// The GLSL ES 1.00 WebGL cases, against Chromium in each context.
    pub es100: Option<Es100Report>,
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
    /// GLSL ES 1.00 WebGL cases, per context: Chromium-accepted cases accepted and
    /// Chromium-rejected cases rejected, percent each.
    pub const ES100_PERCENT: f64 = 99.5;
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
        if let Some(es100) = &self.es100 {
            for target in [essl::Target::WebGl1, essl::Target::WebGl2] {
                let c = es100.context(target);
                for (what, t) in [("accepted", &c.accepted), ("rejected", &c.rejected)] {
                    if t.percent() < bars::ES100_PERCENT {
                        out.push(format!(
                            "GLSL ES 1.00 {} {what} {:.1}% < {}%",
                            target.as_str(),
                            t.percent(),
                            bars::ES100_PERCENT
                        ));
                    }
                }
            }
        }
        if self.fundamentals.ok < self.fundamentals.total {
            out.push(format!(
                "webgl2fundamentals {}/{} compile",
                self.fundamentals.ok, self.fundamentals.total
            ));
        }
        out
    }
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
        message: essl_check::io_message(&e),
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

fn compile_or_trivial(
    name: &str,
    source: Option<&str>,
    stage: Stage,
    options: &CompileOptions,
    trivial: [&str; 2],
) -> Shader {
    let text = match source {
        Some(s) if !s.trim().is_empty() => s,
        _ => match stage {
            Stage::Vertex => trivial[0],
            Stage::Fragment => trivial[1],
        },
    };
    compile(SourceFile::new(name, text), stage, options)
}

/// What compiling and linking a pair gave.
struct Built {
    vertex_ok: bool,
    fragment_ok: bool,
    link_ok: bool,
    first_error: String,
}

fn build(name: &str, vertex: Option<&str>, fragment: Option<&str>) -> Built {
    let trivial = [TRIVIAL_VERTEX, TRIVIAL_FRAGMENT];
    build_with(name, vertex, fragment, &CompileOptions::default(), trivial)
}

/// Compiles and links a pair with `options`, a missing shader replaced by `trivial`'s.
fn build_with(
    name: &str,
    vertex: Option<&str>,
    fragment: Option<&str>,
    options: &CompileOptions,
    trivial: [&str; 2],
) -> Built {
    let vs = compile_or_trivial(
        &format!("{name}.vert"),
        vertex,
        Stage::Vertex,
        options,
        trivial,
    );
    let fs = compile_or_trivial(
        &format!("{name}.frag"),
        fragment,
        Stage::Fragment,
        options,
        trivial,
    );
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

/// Scores every corpus in `dir` (the folder holding the `.jsonl` files).
pub fn score(dir: &Path) -> Result<Report, CorpusError> {
    score_with(dir, false)
}

/// Scores every corpus in `dir`; with `peers`, also runs glslangValidator (when it is on
/// `PATH`) on the GLSL ES 1.00 cases in the same run.
pub fn score_with(dir: &Path, peers: bool) -> Result<Report, CorpusError> {
    let mut report = Report::default();
    es300::score_webgl(dir, &mut report)?;
    es300::score_deqp(dir, &mut report)?;
    es300::score_glslang(dir, &mut report)?;
    es300::score_fundamentals(dir, &mut report)?;
    report.es100 = Some(es100::score(dir, peers, &mut report.failures)?);
    Ok(report)
}

/// The heading of docs/conformance.md's section written by the Node conformance run, which
/// `run` keeps when it rewrites the file.
const KEPT_SECTION: &str = "## The WebGL conformance suite in Node (essl-gl-node)";

/// Runs `essl conformance`: prints the tables (and the failures with `list_failures`), writes
/// the Markdown page when asked (keeping the Node suite's section), and returns the exit
/// status (0, or 2 when the corpora cannot be read or the page cannot be written).
pub fn run(corpora: &Path, markdown: Option<&Path>, list_failures: bool) -> i32 {
    let report = match score_with(corpora, true) {
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
        // The sections other tools write (the WebGL suite in Node, from
        // crates/essl-gl-node/conformance/report.mjs) follow this report's; keep them.
        let kept = std::fs::read_to_string(path)
            .ok()
            .and_then(|old| old.find(KEPT_SECTION).map(|at| old[at..].to_string()))
            .unwrap_or_default();
        let text = if kept.is_empty() {
            report.markdown()
        } else {
            format!("{}\n\n{kept}", report.markdown().trim_end())
        };
        if let Err(e) = std::fs::write(path, text) {
            eprintln!(
                "error: cannot write `{}`: {}",
                path.display(),
                essl_check::io_message(&e)
            );
            return 2;
        }
    }
    0
}
