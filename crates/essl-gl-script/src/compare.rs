//! Comparing a replay with what Chromium answered and drew, as "Replaying a script
//! elsewhere" of `docs/gl-scripts.md` allows: records equal, but floats computed on the GPU
//! (`getBufferSubData` of captured vertices) within `1e-5 · max(1, |v|)`, and the answers that
//! depend on the GPU or the browser reported without being required; pictures within 3/255 on
//! at least 99.9 % of the pixels.

use serde_json::Value as Json;

use essl_scene::{ImageDiff, RgbaImage};

use crate::results::Results;
use crate::script::Script;

/// Largest difference on a channel, in 1/255, for a pixel to count as equal.
pub const PIXEL_TOLERANCE: u8 = 3;
/// Smallest fraction of pixels within [`PIXEL_TOLERANCE`] for pictures to count as equal.
pub const PIXELS_WITHIN: f64 = 0.999;
/// Relative tolerance of floats a GPU computed.
pub const FLOAT_TOLERANCE: f64 = 1e-5;

/// Answers that depend on the GPU or the browser (the list in `docs/gl-scripts.md`): script
/// name and record key; a key `*` stands for every record of the script, `*X` for keys
/// ending in `X`, `X*` for keys starting with `X`.
const NOT_REQUIRED: &[(&str, &str)] = &[
    ("getparameter-limits-framebuffer", "*"),
    ("getparameter-limits-other", "*"),
    ("shader-precision-formats", "VERTEX_SHADER.*"),
    ("shader-precision-formats", "FRAGMENT_SHADER.*"),
    ("supported-extensions", "*"),
    // Chromium adds `desynchronized`, `powerPreference`, `xrCompatible`.
    ("context-attributes-default", "attributes"),
    ("context-attributes-stencil", "attributes"),
    ("rb-internalformat-samples", "*.SAMPLES"),
    ("rb-internalformat-samples-float", "*.SAMPLES"),
    ("rb-storage-errors", "MAX_RENDERBUFFER_SIZE"),
    ("rb-storage-errors", "askedFor2.samples"),
    // A Chromium quirk after a failed beginTransformFeedback.
    ("tf-failed-begin", "*"),
];

fn matches(pattern: &str, key: &str) -> bool {
    if pattern == "*" {
        true
    } else if let Some(suffix) = pattern.strip_prefix('*') {
        key.ends_with(suffix)
    } else if let Some(prefix) = pattern.strip_suffix('*') {
        key.starts_with(prefix)
    } else {
        pattern == key
    }
}

/// Whether a record of script `name` may differ from Chromium's.
pub fn not_required(name: &str, key: &str) -> bool {
    NOT_REQUIRED
        .iter()
        .any(|&(s, pattern)| s == name && matches(pattern, key))
}

/// A record that differs.
#[derive(Clone, Debug, PartialEq)]
pub struct Mismatch {
    /// The record's key.
    pub key: String,
    /// What the replay recorded (`None`: nothing).
    pub ours: Option<Json>,
    /// What Chromium recorded (`None`: nothing).
    pub theirs: Option<Json>,
}

impl std::fmt::Display for Mismatch {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let show = |v: &Option<Json>| v.as_ref().map_or("(none)".to_string(), Json::to_string);
        let (ours, theirs) = (show(&self.ours), show(&self.theirs));
        write!(f, "{}: essl-gl {ours}, Chromium {theirs}", self.key)
    }
}

/// How a replay compares with Chromium's run of the same script.
#[derive(Debug)]
pub struct Comparison {
    /// Records that differ and must not.
    pub mismatches: Vec<Mismatch>,
    /// Records that differ where the GPU or the browser may answer otherwise.
    pub allowed: Vec<Mismatch>,
    /// The pictures' difference.
    pub picture: ImageDiff,
}

impl Comparison {
    /// Whether the pictures count as equal.
    pub fn picture_matches(&self) -> bool {
        self.picture.fraction_within() >= PIXELS_WITHIN
    }

    /// Whether everything required matches.
    pub fn matches(&self) -> bool {
        self.mismatches.is_empty() && self.picture_matches()
    }
}

/// Compares a replay of `script` (named `name`, the file's stem) with Chromium's results
/// and picture.
pub fn compare(
    name: &str,
    script: &Script,
    ours: (&Results, &RgbaImage),
    theirs: (&Results, &RgbaImage),
) -> Result<Comparison, essl_scene::ImageError> {
    let computed: Vec<&str> = script
        .setup
        .iter()
        .chain(&script.frame)
        .filter(|c| c.f == "getBufferSubData")
        .filter_map(|c| c.record.as_deref())
        .collect();
    let mut mismatches = Vec::new();
    let mut allowed = Vec::new();
    let keys = theirs.0.records.iter().map(|(k, _)| k).chain(
        ours.0
            .records
            .iter()
            .map(|(k, _)| k)
            .filter(|k| theirs.0.record(k).is_none()),
    );
    for key in keys {
        let (a, b) = (ours.0.record(key), theirs.0.record(key));
        let tolerance = if computed.contains(&key.as_str()) {
            FLOAT_TOLERANCE
        } else {
            0.0
        };
        let equal = match (a, b) {
            (Some(a), Some(b)) => same(a, b, tolerance),
            _ => false,
        };
        if equal {
            continue;
        }
        let m = Mismatch {
            key: key.clone(),
            ours: a.cloned(),
            theirs: b.cloned(),
        };
        if not_required(name, key) {
            allowed.push(m);
        } else {
            mismatches.push(m);
        }
    }
    let picture = essl_scene::compare(ours.1, theirs.1, PIXEL_TOLERANCE)?;
    Ok(Comparison {
        mismatches,
        allowed,
        picture,
    })
}

/// JSON values equal, numbers within `tolerance · max(1, |b|)`.
fn same(a: &Json, b: &Json, tolerance: f64) -> bool {
    match (a, b) {
        (Json::Number(x), Json::Number(y)) => {
            let (x, y) = (
                x.as_f64().unwrap_or(f64::NAN),
                y.as_f64().unwrap_or(f64::NAN),
            );
            x == y || (x - y).abs() <= tolerance * y.abs().max(1.0)
        }
        (Json::Array(x), Json::Array(y)) => {
            x.len() == y.len() && x.iter().zip(y).all(|(x, y)| same(x, y, tolerance))
        }
        (Json::Object(x), Json::Object(y)) => {
            x.len() == y.len()
                && x.iter()
                    .all(|(k, v)| y.get(k).is_some_and(|w| same(v, w, tolerance)))
        }
        _ => a == b,
    }
}
