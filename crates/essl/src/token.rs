//! Parser tokens: preprocessing tokens classified into keywords, reserved words, identifiers and
//! literals (with GLSL ES 3.00's rules for number syntax).

use crate::diagnostic_code::Code;
use crate::Name;

use crate::diagnostic::{Diagnostic, Fix};
use crate::lex::{PpKind, PpToken, Punct};
use crate::source::Span;
use crate::target::Language;

macro_rules! keywords {
    ($($kw:ident = $text:literal,)*) => {
        /// A GLSL ES 3.00 keyword.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        #[allow(missing_docs)]
        pub enum Kw { $($kw,)* }

        impl Kw {
            /// Every keyword.
            const ALL: &'static [Kw] = &[$(Kw::$kw,)*];

            /// The keyword's text.
            pub fn as_str(self) -> &'static str {
                match self { $(Kw::$kw => $text,)* }
            }

            /// The keyword spelled `text`, if any.
            pub fn lookup(text: &str) -> Option<Kw> {
                match text { $($text => Some(Kw::$kw),)* _ => None }
            }
        }
    };
}

keywords! {
    Const = "const", Uniform = "uniform", Layout = "layout", Centroid = "centroid",
    Flat = "flat", Smooth = "smooth", Break = "break", Continue = "continue", Do = "do",
    For = "for", While = "while", Switch = "switch", Case = "case", Default = "default",
    If = "if", Else = "else", In = "in", Out = "out", Inout = "inout", Float = "float",
    Int = "int", Void = "void", Bool = "bool", True = "true", False = "false",
    Invariant = "invariant", Discard = "discard", Return = "return",
    Mat2 = "mat2", Mat3 = "mat3", Mat4 = "mat4", Mat2x2 = "mat2x2", Mat2x3 = "mat2x3",
    Mat2x4 = "mat2x4", Mat3x2 = "mat3x2", Mat3x3 = "mat3x3", Mat3x4 = "mat3x4",
    Mat4x2 = "mat4x2", Mat4x3 = "mat4x3", Mat4x4 = "mat4x4",
    Vec2 = "vec2", Vec3 = "vec3", Vec4 = "vec4", Ivec2 = "ivec2", Ivec3 = "ivec3",
    Ivec4 = "ivec4", Bvec2 = "bvec2", Bvec3 = "bvec3", Bvec4 = "bvec4", Uint = "uint",
    Uvec2 = "uvec2", Uvec3 = "uvec3", Uvec4 = "uvec4", Lowp = "lowp", Mediump = "mediump",
    Highp = "highp", Precision = "precision",
    Sampler2D = "sampler2D", Sampler3D = "sampler3D", SamplerCube = "samplerCube",
    Sampler2DShadow = "sampler2DShadow", SamplerCubeShadow = "samplerCubeShadow",
    Sampler2DArray = "sampler2DArray", Sampler2DArrayShadow = "sampler2DArrayShadow",
    Isampler2D = "isampler2D", Isampler3D = "isampler3D", IsamplerCube = "isamplerCube",
    Isampler2DArray = "isampler2DArray", Usampler2D = "usampler2D", Usampler3D = "usampler3D",
    UsamplerCube = "usamplerCube", Usampler2DArray = "usampler2DArray", Struct = "struct",
    Attribute = "attribute", Varying = "varying",
}

/// Keywords of GLSL ES 3.00 that GLSL ES 1.00 leaves free for identifiers (ANGLE's
/// `ES3_keyword`).
const ES300_ONLY: &[Kw] = &[
    Kw::Case,
    Kw::Centroid,
    Kw::Smooth,
    Kw::Uint,
    Kw::Mat2x2,
    Kw::Mat2x3,
    Kw::Mat2x4,
    Kw::Mat3x2,
    Kw::Mat3x3,
    Kw::Mat3x4,
    Kw::Mat4x2,
    Kw::Mat4x3,
    Kw::Mat4x4,
    Kw::Uvec2,
    Kw::Uvec3,
    Kw::Uvec4,
    Kw::Sampler2DArray,
    Kw::Isampler2D,
    Kw::Isampler3D,
    Kw::IsamplerCube,
    Kw::Isampler2DArray,
    Kw::Usampler2D,
    Kw::Usampler3D,
    Kw::UsamplerCube,
    Kw::Usampler2DArray,
    Kw::SamplerCubeShadow,
    Kw::Sampler2DArrayShadow,
    Kw::Layout,
];

/// Keywords of GLSL ES 3.00 that GLSL ES 1.00 reserves (ANGLE's `ES2_reserved_ES3_keyword`;
/// `sampler3D` and `sampler2DShadow` need extensions WebGL 1 does not have).
const ES300_RESERVED_IN_ES100: &[Kw] = &[
    Kw::Switch,
    Kw::Default,
    Kw::Flat,
    Kw::Sampler3D,
    Kw::Sampler2DShadow,
];

/// Words GLSL ES 1.00 reserves as WebGL implements it (ANGLE's lexer): the future-use words of
/// the specification, WebGL's own (`image2DShadow`, …), and the extension types WebGL 1 lacks.
pub const RESERVED_ES100: &[&str] = &[
    "asm",
    "class",
    "union",
    "enum",
    "typedef",
    "template",
    "this",
    "packed",
    "goto",
    "inline",
    "noinline",
    "volatile",
    "public",
    "static",
    "extern",
    "external",
    "interface",
    "long",
    "short",
    "double",
    "half",
    "fixed",
    "unsigned",
    "superp",
    "input",
    "output",
    "hvec2",
    "hvec3",
    "hvec4",
    "dvec2",
    "dvec3",
    "dvec4",
    "fvec2",
    "fvec3",
    "fvec4",
    "sampler1D",
    "sampler1DShadow",
    "sampler2DRect",
    "sampler3DRect",
    "sampler2DRectShadow",
    "samplerExternalOES",
    "sizeof",
    "cast",
    "namespace",
    "using",
    "image1DShadow",
    "image2DShadow",
    "image1DArrayShadow",
    "image2DArrayShadow",
];

/// Words GLSL ES 3.00 reserves for future use: using one is an error.
pub const RESERVED: &[&str] = &[
    "coherent",
    "volatile",
    "restrict",
    "readonly",
    "writeonly",
    "resource",
    "atomic_uint",
    "noperspective",
    "patch",
    "sample",
    "subroutine",
    "common",
    "partition",
    "active",
    "asm",
    "class",
    "union",
    "enum",
    "typedef",
    "template",
    "this",
    "goto",
    "inline",
    "noinline",
    "public",
    "static",
    "extern",
    "external",
    "interface",
    "long",
    "short",
    "double",
    "half",
    "fixed",
    "unsigned",
    "superp",
    "input",
    "output",
    "hvec2",
    "hvec3",
    "hvec4",
    "dvec2",
    "dvec3",
    "dvec4",
    "fvec2",
    "fvec3",
    "fvec4",
    "sampler3DRect",
    "filter",
    "image1D",
    "image2D",
    "image3D",
    "imageCube",
    "iimage1D",
    "iimage2D",
    "iimage3D",
    "iimageCube",
    "uimage1D",
    "uimage2D",
    "uimage3D",
    "uimageCube",
    "image1DArray",
    "image2DArray",
    "iimage1DArray",
    "iimage2DArray",
    "uimage1DArray",
    "uimage2DArray",
    "image1DShadow",
    "image2DShadow",
    "image1DArrayShadow",
    "image2DArrayShadow",
    "imageBuffer",
    "iimageBuffer",
    "uimageBuffer",
    "sampler1D",
    "sampler1DShadow",
    "sampler1DArray",
    "sampler1DArrayShadow",
    "isampler1D",
    "isampler1DArray",
    "usampler1D",
    "usampler1DArray",
    "sampler2DRect",
    "sampler2DRectShadow",
    "isampler2DRect",
    "usampler2DRect",
    "samplerBuffer",
    "isamplerBuffer",
    "usamplerBuffer",
    "sampler2DMS",
    "isampler2DMS",
    "usampler2DMS",
    "sampler2DMSArray",
    "isampler2DMSArray",
    "usampler2DMSArray",
    "sizeof",
    "cast",
    "namespace",
    "using",
];

/// What a parser token is. A word's text is the token's [`Token::text`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Tok {
    /// An identifier.
    Ident,
    /// A keyword.
    Kw(Kw),
    /// A reserved word (an error to use; parsed as an identifier to recover).
    Reserved,
    /// An integer literal: its value (possibly past 32 bits: checked later) and `u` suffix.
    Int(u64, bool),
    /// A floating-point literal, rounded to f32.
    Float(f32),
    /// A punctuator.
    P(Punct),
    /// A malformed literal or an invalid character, already reported.
    Error,
    /// End of input.
    Eof,
}

/// A parser token.
#[derive(Clone, Debug)]
pub struct Token {
    /// What it is.
    pub tok: Tok,
    /// Where (into the original text).
    pub span: Span,
    /// Its text.
    pub text: Name,
    /// It comes from a macro expansion.
    pub from_macro: bool,
}

/// Classifies the preprocessed tokens of a GLSL ES 3.00 shader ([`classify_as`] for another
/// language). Malformed numbers are reported and become [`Tok::Error`].
pub fn classify(tokens: Vec<PpToken>, diagnostics: &mut Vec<Diagnostic>) -> Vec<Token> {
    classify_as(tokens, &Language::es300(), diagnostics)
}

/// What a word is, in each language, when it is not an identifier in both.
#[derive(Clone, Copy)]
struct Known {
    kw: Option<Kw>,
    reserved_es300: bool,
    reserved_es100: bool,
}

/// Every keyword and reserved word, for one hash lookup per word (the parser classifies every
/// identifier of a shader, so a walk down the keyword and reserved-word lists cost more than
/// the lexing).
fn known(text: &str) -> Option<Known> {
    use rustc_hash::FxHashMap;
    use std::sync::OnceLock;
    static TABLE: OnceLock<FxHashMap<&'static str, Known>> = OnceLock::new();
    let table = TABLE.get_or_init(|| {
        let mut t: FxHashMap<&'static str, Known> = FxHashMap::default();
        let none = Known {
            kw: None,
            reserved_es300: false,
            reserved_es100: false,
        };
        for &kw in Kw::ALL {
            t.insert(
                kw.as_str(),
                Known {
                    kw: Some(kw),
                    ..none
                },
            );
        }
        for &w in RESERVED {
            t.entry(w).or_insert(none).reserved_es300 = true;
        }
        for &w in RESERVED_ES100 {
            t.entry(w).or_insert(none).reserved_es100 = true;
        }
        t
    });
    table.get(text).copied()
}

/// Whether `text` is a keyword or a reserved word of GLSL ES 1.00 or 3.00 (a name no identifier
/// may take in either version).
pub(crate) fn is_taken_word(text: &str) -> bool {
    known(text).is_some()
}

/// A word of the language: a keyword, a reserved word or an identifier.
fn word(text: &str, es100: bool) -> Tok {
    let Some(k) = known(text) else {
        return Tok::Ident;
    };
    match k.kw {
        Some(Kw::Attribute | Kw::Varying) if !es100 => Tok::Reserved,
        Some(kw) if es100 && ES300_ONLY.contains(&kw) => Tok::Ident,
        Some(kw) if es100 && ES300_RESERVED_IN_ES100.contains(&kw) => Tok::Reserved,
        Some(kw) => Tok::Kw(kw),
        None if es100 && k.reserved_es100 => Tok::Reserved,
        None if !es100 && k.reserved_es300 => Tok::Reserved,
        None => Tok::Ident,
    }
}

/// Classifies preprocessed tokens as the language's keywords, reserved words, identifiers and
/// literals. Malformed numbers, and in GLSL ES 1.00 the `u` and `f` suffixes, are reported and
/// become [`Tok::Error`].
pub fn classify_as(
    tokens: Vec<PpToken>,
    lang: &Language,
    diagnostics: &mut Vec<Diagnostic>,
) -> Vec<Token> {
    // A plain loop into a new vector: collecting `into_iter().filter().map()` reused the input's
    // buffer in place, which cost about 5 M instructions over 600 dEQP files beyond the
    // classification itself (docs/performance-history.md, "At `1cfec54`").
    let mut out = Vec::with_capacity(tokens.len());
    for t in tokens {
        let tok = match t.kind {
            PpKind::Newline => continue,
            PpKind::Ident => word(&t.text, lang.es100),
            PpKind::Number if lang.es100 => number_es100(&t.text, t.span, diagnostics),
            PpKind::Number => number(&t.text, t.span, diagnostics),
            PpKind::Punct(p) => Tok::P(p),
            PpKind::Invalid(_) => Tok::Error,
            PpKind::Eof => Tok::Eof,
        };
        out.push(Token {
            tok,
            span: t.span,
            text: t.text,
            from_macro: t.from_macro,
        });
    }
    out
}

/// Parses a preprocessing number as GLSL ES 3.00 does.
pub fn number(text: &str, span: Span, diagnostics: &mut Vec<Diagnostic>) -> Tok {
    let bad = |diagnostics: &mut Vec<Diagnostic>, why: &str| {
        crate::diagnostic::push_capped(
            diagnostics,
            Diagnostic::error(
                Code::InvalidNumber,
                format!("invalid number `{text}`"),
                span,
            )
            .with_label(why.to_string())
            .with_token(text),
        );
        Tok::Error
    };
    let lower = lowercase(text);
    if let Some(hex) = lower.strip_prefix("0x") {
        let (digits, unsigned) = match hex.strip_suffix('u') {
            Some(d) => (d, true),
            None => (hex, false),
        };
        if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_hexdigit()) {
            return bad(
                diagnostics,
                "a hexadecimal integer has only digits 0-9, a-f after `0x`",
            );
        }
        return int_value(digits, 16, unsigned, text, span, diagnostics);
    }
    let is_float = lower.contains(['.', 'e']) || lower.ends_with('f');
    if is_float {
        let body = lower.strip_suffix('f').unwrap_or(&lower);
        if !valid_float(body) {
            return bad(diagnostics, "not a valid floating-point literal");
        }
        let value: f64 = body.parse().unwrap_or(f64::NAN);
        if value.is_nan() {
            return bad(diagnostics, "not a valid floating-point literal");
        }
        let f = value as f32;
        if f.is_infinite() {
            crate::diagnostic::push_capped(
                diagnostics,
                Diagnostic::warning(
                    Code::FloatLiteralOverflow,
                    format!("`{text}` is too large for a 32-bit float and becomes infinity"),
                    span,
                )
                .with_label("larger than 3.4028235e38")
                .with_token(text),
            );
        }
        return Tok::Float(f);
    }
    let (digits, unsigned) = match lower.strip_suffix('u') {
        Some(d) => (d, true),
        None => (&*lower, false),
    };
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return bad(
            diagnostics,
            "an integer literal has only digits and an optional `u`",
        );
    }
    if digits.len() > 1 && digits.starts_with('0') {
        if !digits.bytes().all(|b| (b'0'..=b'7').contains(&b)) {
            let d = Diagnostic::error(
                Code::InvalidNumber,
                format!("invalid digit in octal literal `{text}`"),
                span,
            )
            .with_label("a leading `0` makes this an octal number, which has only digits 0-7")
            .with_token(text);
            let trimmed = digits.trim_start_matches('0');
            let d = if !trimmed.is_empty() {
                d.with_fix(Fix::suggested(
                    "write it in decimal without the leading zero",
                    span,
                    format!("{trimmed}{}", if unsigned { "u" } else { "" }),
                ))
            } else {
                d
            };
            crate::diagnostic::push_capped(diagnostics, d);
            return Tok::Error;
        }
        return int_value(&digits[1..], 8, unsigned, text, span, diagnostics);
    }
    int_value(digits, 10, unsigned, text, span, diagnostics)
}

/// A number's text in lower case, copied only when it has an upper-case letter (most have none).
fn lowercase(text: &str) -> std::borrow::Cow<'_, str> {
    if text.bytes().any(|b| b.is_ascii_uppercase()) {
        text.to_ascii_lowercase().into()
    } else {
        text.into()
    }
}

/// Parses a preprocessing number as GLSL ES 1.00 does: no `u` or `f` suffix, and an integer past
/// 32 bits is a warning (ANGLE's `int_constant`) that leaves the largest value.
fn number_es100(text: &str, span: Span, diagnostics: &mut Vec<Diagnostic>) -> Tok {
    let lower = lowercase(text);
    let hex = lower.starts_with("0x");
    let suffix = if !hex && lower.ends_with('u') {
        Some(("u", "unsigned integers"))
    } else if !hex && lower.ends_with('f') && lower.len() > 1 {
        Some(("f", "the `f` suffix of floating-point literals"))
    } else {
        None
    };
    if let Some((suffix, what)) = suffix {
        let without = &text[..text.len() - 1];
        crate::diagnostic::push_capped(
            diagnostics,
            Diagnostic::error(
                Code::InvalidNumber,
                format!("`{text}`: GLSL ES 1.00 has no {what}"),
                span,
            )
            .with_label(format!("the `{suffix}` suffix is GLSL ES 3.00"))
            .with_fix(Fix::suggested(
                format!("remove the suffix: `{without}`"),
                span,
                without,
            ))
            .with_token(text),
        );
        return Tok::Error;
    }
    let mut found = Vec::new();
    let tok = number(text, span, &mut found);
    match tok {
        Tok::Error
            if found
                .iter()
                .any(|d| d.code == Code::IntegerOverflow.as_str()) =>
        {
            crate::diagnostic::push_capped(
                diagnostics,
                Diagnostic::warning(
                    Code::IntegerOverflow,
                    format!("integer literal `{text}` does not fit in 32 bits"),
                    span,
                )
                .with_label("becomes 4294967295 (0xFFFFFFFF), that is -1")
                .with_note("GLSL ES 3.00 makes this an error")
                .with_token(text),
            );
            Tok::Int(u64::from(u32::MAX), false)
        }
        _ => {
            diagnostics.extend(found);
            tok
        }
    }
}

fn int_value(
    digits: &str,
    radix: u32,
    unsigned: bool,
    text: &str,
    span: Span,
    diagnostics: &mut Vec<Diagnostic>,
) -> Tok {
    if digits.is_empty() {
        return Tok::Int(0, unsigned);
    }
    match u64::from_str_radix(digits, radix) {
        Ok(v) if v <= u32::MAX as u64 => Tok::Int(v, unsigned),
        _ => {
            crate::diagnostic::push_capped(
                diagnostics,
                Diagnostic::error(
                    Code::IntegerOverflow,
                    format!("integer literal `{text}` does not fit in 32 bits"),
                    span,
                )
                .with_label("larger than 4294967295 (0xFFFFFFFF)")
                .with_token(text),
            );
            Tok::Error
        }
    }
}

/// `digits . digits? exp?` | `. digits exp?` | `digits exp`.
fn valid_float(s: &str) -> bool {
    let (mantissa, exponent) = match s.find('e') {
        Some(i) => (&s[..i], Some(&s[i + 1..])),
        None => (s, None),
    };
    let ok_mantissa = match mantissa.find('.') {
        Some(i) => {
            let (a, b) = (&mantissa[..i], &mantissa[i + 1..]);
            (!a.is_empty() || !b.is_empty())
                && a.bytes().all(|c| c.is_ascii_digit())
                && b.bytes().all(|c| c.is_ascii_digit())
        }
        None => !mantissa.is_empty() && mantissa.bytes().all(|c| c.is_ascii_digit()),
    };
    let ok_exponent = match exponent {
        None => mantissa.contains('.'),
        Some(e) => {
            let e = e.strip_prefix(['+', '-']).unwrap_or(e);
            !e.is_empty() && e.bytes().all(|c| c.is_ascii_digit())
        }
    };
    ok_mantissa && ok_exponent
}

#[cfg(test)]
mod tests {
    use super::*;

    fn num(s: &str) -> Tok {
        number(s, Span::default(), &mut Vec::new())
    }

    #[test]
    fn integer_literals() {
        assert_eq!(num("0"), Tok::Int(0, false));
        assert_eq!(num("017"), Tok::Int(15, false));
        assert_eq!(num("0x1Fu"), Tok::Int(31, true));
        assert_eq!(num("4294967295"), Tok::Int(4294967295, false));
        assert_eq!(num("4294967296"), Tok::Error);
        assert_eq!(num("08"), Tok::Error);
        assert_eq!(num("0x"), Tok::Error);
        assert_eq!(num("12abc"), Tok::Error);
    }

    #[test]
    fn float_literals() {
        assert_eq!(num("1.5"), Tok::Float(1.5));
        assert_eq!(num(".5e1"), Tok::Float(5.0));
        assert_eq!(num("2."), Tok::Float(2.0));
        assert_eq!(num("1e3f"), Tok::Float(1000.0));
        assert_eq!(num("1f"), Tok::Error);
        assert_eq!(num("1.0.0"), Tok::Error);
        assert_eq!(num("1e"), Tok::Error);
    }
}
