//! Comparing a replay with what Chromium answered and drew, as "Replaying a script
//! elsewhere" of `docs/gl-scripts.md` allows: records equal, but floats computed on the GPU
//! (`getBufferSubData` of captured vertices) within `1e-5 · max(1, |v|)`, and the answers that
//! depend on the GPU or the browser reported without being required; pictures within 3/255 on
//! at least 99.9 % of the pixels.

use serde_json::Value as Json;

use essl_scene::{ImageDiff, RgbaImage};

use crate::results::{Failure, Phase, Results};
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
    // Limits the GPU sets, read by scripts that test something else.
    ("sampler-parameters", "MAX_COMBINED_TEXTURE_IMAGE_UNITS"),
    ("uniform-block-too-small", "UNIFORM_BUFFER_OFFSET_ALIGNMENT"),
];

/// Records a rasterizer may round otherwise, with the largest difference allowed: script,
/// record key pattern (as in [`NOT_REQUIRED`]), tolerance.
const ROUNDED: &[(&str, &str, f64)] = &[
    // The multisample resolve rounds the average of four samples to 8 bits its own way.
    ("msaa-resolve", "resolved.*", 1.0),
];

/// Calls where essl-gl answers as the specification says and Chromium does not: script,
/// phase, call index. (`docs/gl-scripts.md`, "Where Chromium's answers surprise".)
const SPEC_OVER_CHROMIUM: &[(&str, Phase, usize)] = &[
    // bindTransformFeedback after a failed begin: NO_ERROR in ES 3.0, INVALID_OPERATION in
    // Chromium.
    ("tf-failed-begin", Phase::Setup, 28),
];

/// How close two pictures must be: the largest difference on a channel, in 1/255, for a
/// pixel to count as equal, and the smallest fraction of such pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PictureBar {
    /// Largest difference on a channel, in 1/255.
    pub within: u8,
    /// Smallest fraction of pixels within it.
    pub fraction: f64,
}

/// The pictures that turn on how a rasterizer rounds, with their bars (the reasons are in
/// `docs/gl-scripts.md`, "How robust the pictures are").
const PICTURE_BARS: &[(&str, PictureBar)] = &[
    // Additive blending of overlapping sprites rounds to 8 bits after every blend.
    (
        "tf-particles",
        PictureBar {
            within: 6,
            fraction: 0.999,
        },
    ),
    // Edge pixels whose four samples the two rasterizers cover differently.
    (
        "msaa-resolve",
        PictureBar {
            within: 3,
            fraction: 0.995,
        },
    ),
    // The mirror sphere's cube-map lookups: level of detail and filtering across faces.
    (
        "cubemap-render",
        PictureBar {
            within: 3,
            fraction: 0.998,
        },
    ),
];

/// The bar script `name`'s picture must clear.
pub fn picture_bar(name: &str) -> PictureBar {
    PICTURE_BARS.iter().find(|(s, _)| *s == name).map_or(
        PictureBar {
            within: PIXEL_TOLERANCE,
            fraction: PIXELS_WITHIN,
        },
        |&(_, bar)| bar,
    )
}

/// Whether a failure of script `name` is one where essl-gl keeps to the specification and
/// Chromium does not.
pub fn spec_over_chromium(name: &str, failure: &Failure) -> bool {
    SPEC_OVER_CHROMIUM
        .iter()
        .any(|&(s, phase, index)| s == name && failure.phase == phase && failure.index == index)
}

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
    /// The bar the picture had to clear.
    pub bar: PictureBar,
}

impl Comparison {
    /// Whether the pictures count as equal.
    pub fn picture_matches(&self) -> bool {
        self.picture.fraction_within() >= self.bar.fraction
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
        let rounded = ROUNDED
            .iter()
            .find(|&&(s, pattern, _)| s == name && matches(pattern, key))
            .map(|&(_, _, t)| t);
        let tolerance = if computed.contains(&key.as_str()) {
            Tolerance::Relative(FLOAT_TOLERANCE)
        } else {
            rounded.map_or(Tolerance::Relative(0.0), Tolerance::Absolute)
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
    let bar = picture_bar(name);
    let picture = essl_scene::compare(ours.1, theirs.1, bar.within)?;
    Ok(Comparison {
        mismatches,
        allowed,
        picture,
        bar,
    })
}

/// How far apart two numbers may be.
#[derive(Clone, Copy)]
enum Tolerance {
    /// Within `t · max(1, |b|)`.
    Relative(f64),
    /// Within `t`.
    Absolute(f64),
}

/// JSON values equal, numbers within `tolerance`.
fn same(a: &Json, b: &Json, tolerance: Tolerance) -> bool {
    match (a, b) {
        (Json::Number(x), Json::Number(y)) => {
            let (x, y) = (
                x.as_f64().unwrap_or(f64::NAN),
                y.as_f64().unwrap_or(f64::NAN),
            );
            let t = match tolerance {
                Tolerance::Relative(t) => t * y.abs().max(1.0),
                Tolerance::Absolute(t) => t,
            };
            x == y || (x - y).abs() <= t
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
