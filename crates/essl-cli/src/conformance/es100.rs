//! Scoring the GLSL ES 1.00 WebGL conformance cases (`webgl_conformance_es100.jsonl`) against
//! what Chromium answered in a WebGL 1 and a WebGL 2 context, with no extension enabled (as the
//! test pages ran): a case agrees when essl accepts it (both compile, the program links)
//! exactly when Chromium does. glslangValidator's figures come from the same run
//! ([`super::peer`]).

use std::path::Path;

use essl::{CompileOptions, Target};
use rayon::prelude::*;
use serde::Deserialize;

use super::{build_with, peer, read_jsonl, CorpusError, Failure, Tally};

/// The ES 1.00 corpus file.
pub const WEBGL_ES100: &str = "webgl_conformance_es100.jsonl";

/// A trivial ES 1.00 pair, for a case that lacks a shader.
const TRIVIAL: [&str; 2] = [
    "attribute vec4 p;\nvoid main() {\n    gl_Position = p;\n}\n",
    "precision mediump float;\nvoid main() {\n    gl_FragColor = vec4(0.0, 1.0, 0.0, 1.0);\n}\n",
];

#[derive(Deserialize)]
struct Case {
    file: String,
    index: serde_json::Value,
    vertex_source: Option<String>,
    fragment_source: Option<String>,
    chromium_webgl1: Answer,
    chromium_webgl2: Answer,
}

#[derive(Deserialize, Clone, Copy)]
struct Answer {
    vertex: bool,
    fragment: bool,
    link: bool,
}

impl Answer {
    fn accepted(self) -> bool {
        self.vertex && self.fragment && self.link
    }
}

/// Agreement with Chromium in one context.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ContextScore {
    /// Cases Chromium accepts that essl accepts.
    pub accepted: Tally,
    /// Cases Chromium rejects that essl rejects.
    pub rejected: Tally,
    /// The same for glslangValidator, when it could be run.
    pub glslang: Option<(Tally, Tally)>,
}

/// The ES 1.00 corpus's score, per context.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Es100Report {
    /// Against Chromium's WebGL 1 answers.
    pub webgl1: ContextScore,
    /// Against Chromium's WebGL 2 answers.
    pub webgl2: ContextScore,
    /// glslangValidator's version line, when it ran.
    pub glslang_version: Option<String>,
}

impl Es100Report {
    /// The score of a context.
    pub fn context(&self, target: Target) -> &ContextScore {
        match target {
            Target::WebGl1 => &self.webgl1,
            Target::WebGl2 => &self.webgl2,
        }
    }
}

/// What one case gave: per context (WebGL 1, WebGL 2), Chromium's answer, essl's and a
/// disagreement; glslangValidator's answer (the same in both contexts).
struct Outcome {
    chromium: [bool; 2],
    essl: [bool; 2],
    failures: Vec<Failure>,
    glslang: Option<bool>,
}

/// Scores the ES 1.00 cases in both contexts, adding essl's disagreements to `failures`.
pub(super) fn score(
    dir: &Path,
    peers: bool,
    failures: &mut Vec<Failure>,
) -> Result<Es100Report, CorpusError> {
    let cases: Vec<Case> = read_jsonl(dir, WEBGL_ES100)?;
    let peer = if peers { peer::Glslang::find() } else { None };
    let outcomes: Vec<Outcome> = cases
        .par_iter()
        .map(|c| run_case(c, peer.as_ref()))
        .collect();
    let mut report = Es100Report {
        glslang_version: peer.as_ref().map(|p| p.version.clone()),
        ..Es100Report::default()
    };
    for o in outcomes {
        for (i, score) in [&mut report.webgl1, &mut report.webgl2]
            .into_iter()
            .enumerate()
        {
            let (tally, agrees) = if o.chromium[i] {
                (&mut score.accepted, o.essl[i])
            } else {
                (&mut score.rejected, !o.essl[i])
            };
            tally.add(agrees);
            if let Some(g) = o.glslang {
                let peer = score.glslang.get_or_insert_with(Default::default);
                if o.chromium[i] {
                    peer.0.add(g);
                } else {
                    peer.1.add(!g);
                }
            }
        }
        failures.extend(o.failures);
    }
    Ok(report)
}

/// Builds one case in both contexts (and with glslangValidator).
fn run_case(c: &Case, peer: Option<&peer::Glslang>) -> Outcome {
    let name = format!("{}#{}", c.file, c.index);
    let chromium = [c.chromium_webgl1.accepted(), c.chromium_webgl2.accepted()];
    let mut essl = [false; 2];
    let mut failures = Vec::new();
    for (i, target) in [Target::WebGl1, Target::WebGl2].into_iter().enumerate() {
        let options = CompileOptions {
            target,
            extensions: Vec::new(),
            ..CompileOptions::default()
        };
        let vertex = c.vertex_source.as_deref();
        let fragment = c.fragment_source.as_deref();
        let built = build_with(&name, vertex, fragment, &options, TRIVIAL);
        essl[i] = built.all_ok();
        if essl[i] != chromium[i] {
            failures.push(Failure {
                corpus: if i == 0 {
                    "es100-webgl1"
                } else {
                    "es100-webgl2"
                },
                case: name.clone(),
                expected: if chromium[i] {
                    "Chromium accepts"
                } else {
                    "Chromium rejects"
                }
                .into(),
                got: built.got(),
            });
        }
    }
    let glslang = peer.map(|p| {
        p.accepts(
            c.vertex_source.as_deref().unwrap_or(TRIVIAL[0]),
            c.fragment_source.as_deref().unwrap_or(TRIVIAL[1]),
        )
    });
    Outcome {
        chromium,
        essl,
        failures,
        glslang,
    }
}
