//! What an input's name says it holds: a colour or a normal; what an input's or a uniform's name
//! says of its magnitude: a position in the scene, the animation's time; and what a uniform's name
//! says: a setting a user may set to 0.
//!
//! An input as such — a varying or attribute, or the parameter of a function whose callers pass
//! one unchanged — is unknown to the analysis, and a rule leaves a hazard that needs particular
//! values of it to whoever supplies them. A reviewer reads the name instead: `rgb2cmyk(vec3 rgb)`
//! is written for colours, and black is an ordinary colour; `decimateNormal(vec3 normal)` for
//! unit normals, which lie along an axis over every face that faces that way. So an input whose
//! name says *colour* (`rgb`, `color`, `vColor`, `albedo`) gets a texel's value (per region,
//! `[0, 1]` in [`Mode::Typical`]), and a `vec3` whose name says *normal* (`normal`, `v_normal`,
//! `nor`) the value of a unit vector that, like a texel, holds over whole regions
//! ([`Facts::TEXTURE`] rather than [`Facts::INPUT`]; in [`Mode::Typical`] the ordinary
//! non-negative magnitudes of every external value).
//!
//! Only inputs as such take a name's word: a value the caller computes (a position, arithmetic, a
//! uniform) keeps what the analysis knows of it, whatever the parameter is called.
//!
//! Magnitudes are for [`Mode::Typical`], whose external values are otherwise of magnitude 10: a
//! float vector input or uniform whose name says *position* (`vViewPosition`, `FragPos`,
//! `u_globe_position`, `uPointLightLocation`; not `vUvPos` or `screenPosition`) has components
//! up to [`SCENE`], a scene in pixels or metres; a `float` uniform whose name says it is the
//! animation's time (`iTime`, `u_time`; not `deltaTime`) reaches [`TIME`], an hour. They carry
//! [`Facts::SCENE`] and [`Facts::TIME`], so that `mediump-overflow` can tell what only such
//! values reach (a note) from what modest ones reach too.
//!
//! The word lists are written by hand, from the names WebGL code gives colours, normals,
//! positions and times, and checked on the lint corpora (`docs/lints/corpus.md`), which list
//! the findings a misleading name makes (a vignette's centre in [0, 1] named `position`).

use naga::{Handle, ScalarKind, TypeInner};

use super::{Analysis, Mode, EPS};
use crate::interval::Interval;
use crate::value::{Facts, Num, Val};

/// What a name says an input holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kind {
    /// A colour: components in `[0, 1]`, black and white over whole regions.
    Colour,
    /// A unit normal, the same over every flat face.
    Normal,
    /// A position in a scene's space (view, world, eye, a light's): in [`Mode::Typical`],
    /// components up to [`SCENE`] rather than [`super::TYPICAL`].
    Position,
    /// The time since an animation started, in seconds: in [`Mode::Typical`], up to [`TIME`].
    Time,
}

/// The largest ordinary time in seconds in [`Mode::Typical`]: an hour (a page left open, an
/// animated background).
pub(crate) const TIME: f64 = 3600.0;

/// The largest ordinary component of a position in [`Mode::Typical`]: scenes measured in pixels
/// (p5's camera stands about 700 units from its origin; MapLibre's globe is in pixels) or in
/// metres span hundreds or thousands of units.
pub(crate) const SCENE: f64 = 1000.0;

/// Words that name a colour.
const COLOUR: &[&str] = &[
    "color", "colour", "col", "rgb", "rgba", "srgb", "albedo", "tint",
];
/// Words that name a normal.
const NORMAL: &[&str] = &["normal", "normals", "nor", "nrm"];
/// Words that may stand beside `time` in the name of the time since an animation started
/// (`iGlobalTime`, `u_elapsedTime`); any other word makes it something else (`deltaTime`,
/// `timeScale`, `fadeTime`).
const TIME_WORDS: &[&str] = &[
    "u",
    "i",
    "g",
    "global",
    "current",
    "elapsed",
    "total",
    "anim",
    "animation",
    "shader",
];
/// Words that name a position.
const POSITION: &[&str] = &["position", "pos", "location"];
/// Words that say a position is in a space of modest extent: texture coordinates, the screen's
/// or clip space's normalised coordinates, a cell of a grid, an object's own (unit) space.
const NOT_SCENE: &[&str] = &[
    "uv",
    "st",
    "tex",
    "texture",
    "texel",
    "coord",
    "coords",
    "screen",
    "ndc",
    "clip",
    "norm",
    "normalized",
    "normalised",
    "unit",
    "local",
    "cell",
    "grid",
    "relative",
    "rel",
];

/// The words of an identifier, lower-cased: split at `_`, digits and lower-to-upper case changes
/// (`v_normalWorld2` → `v`, `normal`, `world`).
pub(crate) fn words(name: &str) -> Vec<String> {
    word_slices(name).map(str::to_ascii_lowercase).collect()
}

/// The words of an identifier as [`words`] gives them, as slices of it in their own case:
/// without allocating, for names read once per analysis.
fn word_slices(name: &str) -> impl Iterator<Item = &str> {
    let b = name.as_bytes();
    let mut i = 0;
    std::iter::from_fn(move || {
        while i < b.len() && !b[i].is_ascii_alphabetic() {
            i += 1;
        }
        if i == b.len() {
            return None;
        }
        let start = i;
        i += 1;
        while i < b.len()
            && b[i].is_ascii_alphabetic()
            && !(b[i].is_ascii_uppercase() && b[i - 1].is_ascii_lowercase())
        {
            i += 1;
        }
        Some(&name[start..i])
    })
}

/// Words that name a setting a user may set to 0: a count (of samples, steps, columns, rows,
/// segments, octaves, iterations…), a length, a radius, a gamma, a falloff (`directionCount`,
/// `numberOfTilesWidth`, `uTileColumns`, `_Blob_Fade_Length_`, `uRadius`, `uGamma`), a fade
/// distance (`Inner_Fade`), the width of a soft edge a user sets to 0 for a hard one
/// (`feather`, `uSmoothing`, `softness`), a tone mapping's white point (`white`), a fraction
/// (`_Glow_Fraction_`), a grid cell's, a stroke's or a filter's size (`cellSize`, `strokeSize`,
/// `filterSize`: a size the user sets, not one the host takes from the canvas).
/// Not sizes, resolutions, ratios or distances, which the host computes from the canvas and the
/// camera and which are not 0 while anything is drawn (`u_resolution`, `u_pixelRatio`,
/// `u_camera_to_center_distance`).
const SETTING: &[&str] = &[
    "count",
    "counts",
    "number",
    "num",
    "samples",
    "steps",
    "length",
    "radius",
    "wavelength",
    "gamma",
    "falloff",
    "columns",
    "rows",
    "cols",
    "divisions",
    "segments",
    "slices",
    "subdivisions",
    "levels",
    "frames",
    "octaves",
    "iterations",
    "bands",
    "cells",
    "tiles",
    "fade",
    "feather",
    "smoothing",
    "softness",
    "cell",
    "white",
    "fraction",
    "stroke",
    "filter",
];

/// Words that say a name with a [`SETTING`] word holds something else: what a draw call draws,
/// whose count (`numVerts`) is not 0 while a vertex shader runs, and a scale the host computes
/// (MapLibre's `u_gamma_scale`, from the camera's pitch and distance).
const NOT_SETTING: &[&str] = &[
    "vert",
    "verts",
    "vertex",
    "vertices",
    "instance",
    "instances",
    "scale",
];

/// Whether a uniform's name says it holds a setting a user may set to 0 ([`SETTING`], not
/// [`NOT_SETTING`]).
pub(crate) fn is_setting(name: &str) -> bool {
    let ws = words(name);
    let has = |list: &[&str]| ws.iter().any(|w| list.contains(&w.as_str()));
    // A near or far distance is an end of a range the user sets (Babylon's
    // `proximityFarDistance`), not the camera's distance the host computes.
    let range_end = has(&["near", "far"]) && has(&["distance"]);
    (has(SETTING) || range_end) && !has(NOT_SETTING)
}

/// Whether a word of `name` is one of `list` (lower case).
pub(crate) fn says_any(name: &str, list: &[&str]) -> bool {
    words(name).iter().any(|w| list.contains(&w.as_str()))
}

/// What a name's words say, whatever the type of the value: read once per name
/// ([`said`]), then matched with a type ([`Said::kind`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct Said {
    normal: bool,
    colour: bool,
    position: bool,
    time: bool,
}

/// What the words of `name` say ([`Said`]) of a value of type `ty` (or of its elements): nothing
/// unless it holds floats, as scalars or vectors.
pub(super) fn said(module: &naga::Module, name: Option<&str>, ty: Handle<naga::Type>) -> Said {
    let inner = match module.types[ty].inner {
        TypeInner::Array { base, .. } => &module.types[base].inner,
        ref inner => inner,
    };
    let float = match *inner {
        TypeInner::Scalar(s) | TypeInner::Vector { scalar: s, .. } => s.kind == ScalarKind::Float,
        _ => false,
    };
    match name {
        Some(name) if float => said_of(name),
        _ => Said::default(),
    }
}

/// Whether `name` says it holds the time since an animation started (`iTime`, `u_time`; not
/// `deltaTime` or `timeScale`).
pub(crate) fn says_time(name: &str) -> bool {
    said_of(name).time
}

/// What the words of `name` say ([`Said`]), whatever the type.
fn said_of(name: &str) -> Said {
    let is = |w: &str, list: &[&str]| list.iter().any(|l| l.eq_ignore_ascii_case(w));
    let has = |list: &[&str]| word_slices(name).any(|w| is(w, list));
    let (normal, colour) = (has(NORMAL), has(COLOUR));
    Said {
        normal,
        colour,
        position: has(POSITION) && !has(NOT_SCENE) && !normal && !colour,
        time: has(&["time"]) && word_slices(name).all(|w| is(w, &["time"]) || is(w, TIME_WORDS)),
    }
}

impl Said {
    /// What a value of type `ty` so named holds: a colour for a float `vec3` or `vec4`, a
    /// normal for a float `vec3`, a position in a scene for a float vector (not one in texture,
    /// screen or clip space: [`NOT_SCENE`]), the animation's time for a `float`.
    pub(super) fn kind(self, ty: &TypeInner) -> Option<Kind> {
        match *ty {
            TypeInner::Scalar(s) if s.kind == ScalarKind::Float && self.time => Some(Kind::Time),
            TypeInner::Vector { size, scalar } if scalar.kind == ScalarKind::Float => {
                let n = size as u8;
                if n == 3 && self.normal {
                    Some(Kind::Normal)
                } else if n >= 3 && self.colour {
                    Some(Kind::Colour)
                } else if self.position {
                    Some(Kind::Position)
                } else {
                    None
                }
            }
            _ => None,
        }
    }
}

/// What `name` says a value of type `ty` holds ([`Said::kind`]).
#[cfg(test)]
fn kind(name: Option<&str>, ty: &TypeInner) -> Option<Kind> {
    said_of(name?).kind(ty)
}

/// Whether `v` is an input as such: an external value from the shader's inputs (and texels),
/// not a uniform, through copies and swizzles only — at some call at least, where others pass a
/// texel or an input a name has given a value.
pub(super) fn as_such(v: &Val) -> bool {
    matches!(v, Val::Num(n) if n.facts.has(Facts::EXT)
        && n.facts.any(Facts::INPUT)
        && !n.facts.any(Facts::UNIFORM))
}

impl Analysis {
    /// The value of an input (`deps`: [`Facts::INPUT`] or [`Facts::UNIFORM`]) of type `ty` that
    /// holds what `kind` says.
    pub(super) fn named(
        &self,
        module: &naga::Module,
        ty: &TypeInner,
        kind: Kind,
        deps: Facts,
    ) -> Val {
        match kind {
            Kind::Position | Kind::Time => {
                let (bit, largest) = match kind {
                    Kind::Position => (Facts::SCENE, SCENE),
                    _ => (Facts::TIME, TIME),
                };
                match self.external(module, ty, deps.with(bit)) {
                    Val::Num(n) if self.mode == Mode::Typical && self.named_magnitudes => {
                        let c = [Interval::new(0.0, largest); 4];
                        Val::Num(Num::from_components(&c[..n.n as usize], n.facts))
                    }
                    other => other,
                }
            }
            Kind::Colour => self.texel(module, ty, Facts::TEXTURE),
            // The typical analysis keeps external values non-negative, the signs formulas
            // expect (`mediump-overflow` asks about magnitudes), for normals too.
            Kind::Normal if self.mode == Mode::Typical => self.external(module, ty, Facts::TEXTURE),
            Kind::Normal => {
                let one = Interval::new(1.0 - EPS, 1.0 + EPS);
                let c = Interval::new(-one.hi, one.hi);
                let mut r = Num::from_components(&[c; 3], Facts::NZ.with(Facts::TEXTURE));
                r.norm = one;
                Val::Num(r.settle())
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_split_at_underscores_digits_and_case() {
        assert_eq!(words("v_normalWorld2"), ["v", "normal", "world"]);
        assert_eq!(words("vRGB"), ["v", "rgb"]);
        assert_eq!(words("normalMC"), ["normal", "mc"]);
        assert_eq!(words("lh_vec3"), ["lh", "vec"]);
        assert_eq!(
            words("uPointLightLocation"),
            ["u", "point", "light", "location"]
        );
        assert_eq!(words("_x_"), ["x"]);
        assert_eq!(words("été_Pos"), ["t", "pos"]);
    }

    #[test]
    fn settings_are_counts_lengths_radii_and_gammas() {
        for name in [
            "directionCount",
            "numberOfTilesWidth",
            "_Blob_Fade_Length_",
            "uGamma",
            "u_radius",
            "_Proximity_Far_Distance_",
            "Inner_Fade",
            "uIsolateThresholdFeather.z",
            "uSmoothing",
            "white",
            "_Glow_Fraction_",
            "strokeSize",
            "filterSize",
            "cellSize",
        ] {
            assert!(is_setting(name), "{name}");
        }
        for name in [
            "u_resolution",
            "uInputSize",
            "u_camera_to_center_distance",
            "u_pixelRatio",
            "uLengths",
            "numVerts",
            "u_gamma_scale",
            "u_crossfade_to",
            "uCameraDistance",
        ] {
            assert!(!is_setting(name), "{name}");
        }
    }

    #[test]
    fn kinds_need_the_word_and_the_type() {
        let vec = |n| TypeInner::Vector {
            size: match n {
                2 => naga::VectorSize::Bi,
                3 => naga::VectorSize::Tri,
                _ => naga::VectorSize::Quad,
            },
            scalar: naga::Scalar::F32,
        };
        assert_eq!(kind(Some("vNormal"), &vec(3)), Some(Kind::Normal));
        assert_eq!(kind(Some("nor"), &vec(3)), Some(Kind::Normal));
        assert_eq!(kind(Some("rgb"), &vec(3)), Some(Kind::Colour));
        assert_eq!(kind(Some("v_color"), &vec(4)), Some(Kind::Colour));
        // Not a word of its own, or not the type.
        assert_eq!(kind(Some("normalize"), &vec(3)), None);
        assert_eq!(kind(Some("colorUv"), &vec(2)), None);
        assert_eq!(kind(Some("vNormal"), &vec(4)), None);
        assert_eq!(kind(Some("dir"), &vec(3)), None);
        assert_eq!(kind(None, &vec(3)), None);
    }

    #[test]
    fn positions_in_a_scene_and_the_animation_s_time() {
        let vec = |n| TypeInner::Vector {
            size: match n {
                2 => naga::VectorSize::Bi,
                _ => naga::VectorSize::Tri,
            },
            scalar: naga::Scalar::F32,
        };
        for name in [
            "vViewPosition",
            "FragPos",
            "u_globe_position",
            "uPointLightLocation",
        ] {
            assert_eq!(kind(Some(name), &vec(3)), Some(Kind::Position), "{name}");
        }
        assert_eq!(kind(Some("v_pos"), &vec(2)), Some(Kind::Position));
        for name in [
            "vUvPos",
            "screenPosition",
            "texPos",
            "v_clip_pos",
            "cellPos",
            "localPosition",
        ] {
            assert_eq!(kind(Some(name), &vec(3)), None, "{name}");
        }
        // Not a word of its own.
        assert_eq!(kind(Some("compose"), &vec(3)), None);
        let float = TypeInner::Scalar(naga::Scalar::F32);
        for name in ["iTime", "u_time", "time", "iGlobalTime", "uElapsedTime"] {
            assert_eq!(kind(Some(name), &float), Some(Kind::Time), "{name}");
        }
        for name in [
            "deltaTime",
            "u_timeScale",
            "fadeTime",
            "timeOffset",
            "lifetime",
        ] {
            assert_eq!(kind(Some(name), &float), None, "{name}");
        }
        assert_eq!(kind(Some("iTime"), &vec(2)), None);
        assert_eq!(kind(Some("positive"), &vec(3)), None);
    }
}
