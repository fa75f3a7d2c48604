//! Scoring the GLSL ES 3.00 corpora: the WebGL conformance tests, dEQP, glslang's tests and the
//! webgl2fundamentals shaders, each with its harness's rules.

use std::collections::BTreeMap;
use std::path::Path;

use essl::source::SourceFile;
use essl::{compile, CompileOptions};
use rayon::prelude::*;
use serde::Deserialize;

use super::{
    build, read_jsonl, stage_of, CorpusError, Failure, Report, Row, DEQP, FUNDAMENTALS, GLSLANG,
    WEBGL,
};

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

pub(super) fn score_webgl(dir: &Path, report: &mut Report) -> Result<(), CorpusError> {
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

pub(super) fn score_deqp(dir: &Path, report: &mut Report) -> Result<(), CorpusError> {
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

pub(super) fn score_glslang(dir: &Path, report: &mut Report) -> Result<(), CorpusError> {
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

pub(super) fn score_fundamentals(dir: &Path, report: &mut Report) -> Result<(), CorpusError> {
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
