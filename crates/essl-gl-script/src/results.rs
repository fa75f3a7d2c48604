//! A replay's results, in the JSON layout `run-chromium.py` writes (`renderer`, `version`,
//! `records` in the order first recorded, `failures`, `ms_per_frame`), so that one reader
//! serves both.

use std::fmt;

use serde_json::{json, Value as Json};

use crate::ScriptError;

/// Where a failure happened.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Phase {
    /// A call of `setup`.
    Setup,
    /// A call of `frame` (its first run).
    Frame,
    /// Reading the picture.
    Readback,
    /// The timed runs of `frame`.
    Timed,
    /// The replay itself (an extension not offered, an error left at the start).
    Runner,
}

impl Phase {
    fn as_str(self) -> &'static str {
        match self {
            Phase::Setup => "setup",
            Phase::Frame => "frame",
            Phase::Readback => "readback",
            Phase::Timed => "timed",
            Phase::Runner => "runner",
        }
    }

    fn parse(s: &str) -> Option<Phase> {
        Some(match s {
            "setup" => Phase::Setup,
            "frame" => Phase::Frame,
            "readback" => Phase::Readback,
            "timed" => Phase::Timed,
            "runner" => Phase::Runner,
            _ => return None,
        })
    }
}

/// A call that did not do what the script says: another error, another status, an
/// exception, an `until` value never reached.
#[derive(Clone, Debug, PartialEq)]
pub struct Failure {
    /// Where.
    pub phase: Phase,
    /// The call's index in its phase.
    pub index: usize,
    /// The method.
    pub f: String,
    /// What happened.
    pub message: String,
}

impl fmt::Display for Failure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let phase = self.phase.as_str();
        write!(f, "{phase}[{}] {}: {}", self.index, self.f, self.message)
    }
}

/// What a run of a script answered.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Results {
    /// The renderer's name.
    pub renderer: String,
    /// `getParameter(VERSION)`.
    pub version: String,
    /// Recorded values, in the order first recorded.
    pub records: Vec<(String, Json)>,
    /// Calls that did not do what the script says.
    pub failures: Vec<Failure>,
    /// Median milliseconds per timed frame, when timed.
    pub ms_per_frame: Option<f64>,
}

impl Results {
    /// The value recorded under `key`.
    pub fn record(&self, key: &str) -> Option<&Json> {
        self.records.iter().find(|(k, _)| k == key).map(|(_, v)| v)
    }

    /// The results as JSON text in `run-chromium.py`'s layout, one record a line.
    pub fn to_json(&self) -> String {
        let mut out = String::from("{\n");
        out += &format!(" \"renderer\": {},\n", Json::from(self.renderer.as_str()));
        out += &format!(" \"version\": {},\n", Json::from(self.version.as_str()));
        out += " \"records\": {";
        for (i, (k, v)) in self.records.iter().enumerate() {
            let sep = if i == 0 { "\n" } else { ",\n" };
            out += &format!("{sep}  {}: {v}", Json::from(k.as_str()));
        }
        out += if self.records.is_empty() {
            "},\n"
        } else {
            "\n },\n"
        };
        let failures: Vec<Json> = self
            .failures
            .iter()
            .map(|f| {
                json!({"phase": f.phase.as_str(), "index": f.index, "f": f.f, "message": f.message})
            })
            .collect();
        out += &format!(" \"failures\": {},\n", Json::Array(failures));
        let ms = self.ms_per_frame.map_or(Json::Null, Json::from);
        out += &format!(" \"ms_per_frame\": {ms}\n}}\n");
        out
    }

    /// Reads results written by `run-chromium.py` or [`Results::to_json`] (the records come
    /// in the order of their keys).
    pub fn from_json(text: &str) -> Result<Results, ScriptError> {
        let bad = |m: &str| ScriptError::Malformed {
            at: "results".into(),
            message: m.into(),
        };
        let json: Json =
            serde_json::from_str(text).map_err(|e| ScriptError::Json(e.to_string()))?;
        let string = |k: &str| json.get(k).and_then(Json::as_str).unwrap_or("").to_string();
        let records = match json.get("records") {
            Some(Json::Object(map)) => map.iter().map(|(k, v)| (k.clone(), v.clone())).collect(),
            _ => return Err(bad("`records` must be an object")),
        };
        let mut failures = Vec::new();
        for f in json
            .get("failures")
            .and_then(Json::as_array)
            .into_iter()
            .flatten()
        {
            failures.push(Failure {
                phase: f
                    .get("phase")
                    .and_then(Json::as_str)
                    .and_then(Phase::parse)
                    .ok_or_else(|| bad("a failure's `phase`"))?,
                index: f.get("index").and_then(Json::as_u64).unwrap_or(0) as usize,
                f: f.get("f").and_then(Json::as_str).unwrap_or("").to_string(),
                message: f
                    .get("message")
                    .and_then(Json::as_str)
                    .unwrap_or("")
                    .to_string(),
            });
        }
        Ok(Results {
            renderer: string("renderer"),
            version: string("version"),
            records,
            failures,
            ms_per_frame: json.get("ms_per_frame").and_then(Json::as_f64),
        })
    }
}
