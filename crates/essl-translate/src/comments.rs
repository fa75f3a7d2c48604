//! Comments where the lowering added something the GLSL did not say.
//!
//! naga's writers emit no comments, so they are put in afterwards, each above the first line
//! that holds its anchor: a name essl gives what it adds (the `_essl_DefaultUniforms` struct,
//! the `clip_position_depth_0_to_w`, `frag_coord_y_up` and `dFdy_y_up` values the lowering
//! names for this) or a texture global of the sampler split. A comment whose anchor a
//! backend renamed away is left out rather than put in the wrong place.

use essl::Stage;
use naga::Module;

use crate::{Options, Target};

/// essl's comments for what the lowering added, as the WGSL writer places them (on the
/// declarations and values they are about, rather than by searching the text).
#[derive(Clone, Debug, Default)]
pub(crate) struct Notes {
    pub uniform_buffer: Option<String>,
    pub padding: Option<String>,
    pub framebuffer_height: Option<String>,
    pub draw_id: Option<String>,
    pub samplers: Option<String>,
    /// Above the functions essl adds (`inverse4x4`).
    pub helper: Option<String>,
    named: Vec<(String, String)>,
}

impl Notes {
    /// The notes for the options (none without comments).
    pub(crate) fn new(options: &Options) -> Notes {
        if !options.comments {
            return Notes::default();
        }
        let api = api(options.target);
        Notes {
            uniform_buffer: Some(
                "The loose uniforms, in one std140 buffer: the binding map gives their offsets."
                    .into(),
            ),
            padding: Some("The other stage's uniforms.".into()),
            framebuffer_height: Some(
                "Not the shader's: the host writes the framebuffer height here (gl_FragCoord.y)."
                    .into(),
            ),
            draw_id: Some(
                "Not the shader's: the host writes gl_DrawID here, the draw's index within a \
                 multi-draw call (0 for a single draw)."
                    .into(),
            ),
            samplers: Some(
                "Each GLSL sampler is a texture and a sampler: the binding map gives their bindings."
                    .into(),
            ),
            helper: Some(format!(
                "GLSL's inverse(), which {} lacks: the adjugate over the determinant.",
                match options.target {
                    Target::Wgsl => "WGSL",
                    Target::Msl => "MSL",
                    Target::Hlsl => "HLSL",
                    _ => "the target",
                }
            )),
            named: vec![
                (
                    "clip_position_depth_0_to_w".into(),
                    format!("WebGL's clip-space z runs from -w to w, {api}'s from 0 to w."),
                ),
                (
                    "frag_coord_y_up".into(),
                    format!("gl_FragCoord.y counts up in WebGL, down in {api}."),
                ),
                ("dFdy_y_up".into(), "dFdy changes sign with the flipped y axis.".into()),
            ],
        }
    }

    /// The note for a value essl named.
    pub(crate) fn named(&self, name: &str) -> Option<String> {
        self.named
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, note)| note.clone())
    }
}

fn api(target: Target) -> &'static str {
    match target {
        Target::Wgsl => "WebGPU",
        Target::SpirV | Target::Glsl => "the target API",
        Target::Msl => "Metal",
        Target::Hlsl => "Direct3D",
    }
}

/// The output's first comment lines: what it is, `notes` (what WGSL cannot say), then the
/// comments that open the GLSL files, as the author wrote them (`author`, without `//`).
pub(crate) fn header(what: &str, notes: &[String], author: &[Vec<String>]) -> String {
    let mut out = String::new();
    for l in crate::source::wrap(what, 93) {
        out.push_str(&format!("// {l}\n"));
    }
    for note in notes {
        for l in crate::source::wrap(note, 93) {
            out.push_str(&format!("// {l}\n"));
        }
    }
    for lines in author.iter().filter(|l| !l.is_empty()) {
        out.push_str("//\n");
        for l in lines {
            out.push_str(&format!("//{l}\n"));
        }
    }
    out
}

/// The text with its comments: a header, then each comment above its anchor's line.
pub fn annotate(
    text: &str,
    module: &Module,
    (stage, language): (Stage, &str),
    options: &Options,
    header: &[String],
) -> String {
    let mut notes: Vec<(Anchor, String)> = vec![
        (
            Anchor::Token(vec!["_essl_DefaultUniforms".into()]),
            "The shader's loose uniforms (`uniform vec3 u_x;`…), gathered into one uniform \
             buffer at group 0, binding 0, in std140 layout: the binding map gives each one's \
             offset. Uniform blocks of the shader follow at bindings 1, 2…"
                .into(),
        ),
        (
            Anchor::Token(vec!["_essl_padding".into()]),
            "Bytes of the buffer that only the other stage reads.".into(),
        ),
        (
            Anchor::Token(vec!["_essl_framebuffer_height".into()]),
            "Not the shader's: the host writes the framebuffer's height in pixels here, for the \
             gl_FragCoord.y flip."
                .into(),
        ),
        (
            Anchor::Token(vec!["_essl_draw_id".into()]),
            "Not the shader's: gl_DrawID, which the target lacks. The host writes the index of \
             the draw within a multi-draw call here before each draw (0 for a single draw)."
                .into(),
        ),
    ];
    for (name, binding) in textures(module) {
        let ident = crate::names::identifier(&name);
        notes.push((
            Anchor::Token(vec![ident.clone(), format!("{ident}_")]),
            format!(
                "GLSL's sampler uniform `{name}` is a texture (group 1, binding {binding}) and a \
                 sampler (binding {}) here: the texture unit set with uniform1i chooses both.",
                binding + 1
            ),
        ));
    }
    let api = api(options.target);
    notes.push((
        Anchor::Named("clip_position_depth_0_to_w".into()),
        format!(
            "WebGL's clip-space z runs from -w to w, {api}'s from 0 to w: z becomes (z + w) / 2 \
             (`--no-depth-remap` leaves this out)."
        ),
    ));
    notes.push((
        Anchor::Named("frag_coord_y_up".into()),
        format!(
            "gl_FragCoord.y counts up from the bottom in WebGL and down from the top in {api}: \
             y becomes height - y, with the height from the uniform buffer (`--no-flip-y` \
             leaves this out)."
        ),
    ));
    notes.push((
        Anchor::Named("dFdy_y_up".into()),
        "dFdy changes sign with the flipped y axis (`--no-flip-y` leaves this out).".into(),
    ));
    let mut out = String::with_capacity(text.len() + 1024);
    out.push_str(&format!(
        "// The {} shader, translated from WebGL's {language} by essl.\n",
        stage.as_str()
    ));
    for note in header {
        for l in wrap(note, 93) {
            out.push_str(&format!("// {l}\n"));
        }
    }
    let mut lines: Vec<String> = Vec::new();
    let mut used = vec![false; notes.len()];
    for line in text.split_inclusive('\n') {
        for (i, (anchor, note)) in notes.iter().enumerate() {
            if (used[i] && !anchor.every_time()) || !anchor.found_in(line) {
                continue;
            }
            used[i] = true;
            // Above the attributes of the declaration (`@group(0) @binding(0)` on a line of
            // their own), not between them and it.
            let mut at = lines.len();
            while at > 0 && lines[at - 1].trim_start().starts_with('@') {
                at -= 1;
            }
            let indent = &line[..line.len() - line.trim_start().len()];
            let comment: Vec<String> = wrap(note, 96usize.saturating_sub(indent.len() + 3))
                .into_iter()
                .map(|l| format!("{indent}// {l}\n"))
                .collect();
            lines.splice(at..at, comment);
        }
        lines.push(line.to_owned());
    }
    out.extend(lines);
    out
}

/// Where a comment goes.
enum Anchor {
    /// Above the first line where one of these identifiers appears.
    Token(Vec<String>),
    /// Above every line that declares a value named this (`let NAME`, `NAME_1`…).
    Named(String),
}

impl Anchor {
    fn every_time(&self) -> bool {
        matches!(self, Anchor::Named(_))
    }

    fn found_in(&self, line: &str) -> bool {
        match self {
            Anchor::Token(ts) => ts.iter().any(|t| has_token(line, t)),
            Anchor::Named(n) => {
                let t = line.trim_start();
                // WGSL `let n =`, GLSL/HLSL/MSL `T n =`: the name before the first `=`.
                t.split_once(" = ").is_some_and(|(lhs, _)| {
                    lhs.split_whitespace()
                        .last()
                        .is_some_and(|w| w == n || w.strip_prefix(n.as_str()).is_some_and(suffix))
                })
            }
        }
    }
}

/// A namer's suffix for a repeated name: `_1`, `_2`…
fn suffix(s: &str) -> bool {
    s.strip_prefix('_')
        .is_some_and(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()))
}

/// Whether `token` appears in `line` as a whole identifier.
fn has_token(line: &str, token: &str) -> bool {
    let ident = |c: char| c.is_ascii_alphanumeric() || c == '_';
    line.match_indices(token).any(|(i, _)| {
        let before = line[..i].chars().next_back();
        let after = line[i + token.len()..].chars().next();
        !before.is_some_and(ident) && !after.is_some_and(ident)
    })
}

/// The texture globals of the sampler split: (name, binding), in binding order.
fn textures(module: &Module) -> Vec<(String, u32)> {
    let mut out: Vec<_> = module
        .global_variables
        .iter()
        .filter_map(|(_, g)| {
            let b = g.binding.as_ref()?;
            let image = matches!(module.types[g.ty].inner, naga::TypeInner::Image { .. });
            (b.group == 1 && image).then(|| (g.name.clone().unwrap_or_default(), b.binding))
        })
        .collect();
    out.sort_by_key(|(_, b)| *b);
    out
}

use crate::source::wrap;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn anchors() {
        assert!(has_token(
            "var<uniform> _essl_uniforms: X;",
            "_essl_uniforms"
        ));
        assert!(!has_token(
            "var<uniform> _essl_uniforms2: X;",
            "_essl_uniforms"
        ));
        let named = Anchor::Named("frag_coord_y_up".into());
        assert!(named.found_in("    let frag_coord_y_up = vec4(1.0);"));
        assert!(named.found_in("    vec4 frag_coord_y_up_1 = vec4(1.0);"));
        assert!(!named.found_in("    x = frag_coord_y_up;"));
        assert!(!named.found_in("    let frag_coord_y_upper = 1;"));
    }

    #[test]
    fn wraps_at_the_width() {
        let lines = wrap("a bb ccc dddd eeeee ffffff ggggggg hhhhhhhh iiiiiiiii", 20);
        assert!(lines.iter().all(|l| l.len() <= 20), "{lines:?}");
        assert_eq!(
            lines.join(" "),
            "a bb ccc dddd eeeee ffffff ggggggg hhhhhhhh iiiiiiiii"
        );
    }
}
