//! Names near a misspelt one: the built-in function, type or keyword a user most likely meant
//! (`normalise` → `normalize`, `flot` → `float`, `unifrom` → `uniform`), for the help of an
//! undeclared-name error, as rustc suggests `did you mean`.

/// The words GLSL ES 3.00 and 1.00 have for types, which an unknown type name may be a
/// misspelling of.
pub(crate) const TYPES: &[&str] = &[
    "void",
    "bool",
    "int",
    "uint",
    "float",
    "vec2",
    "vec3",
    "vec4",
    "bvec2",
    "bvec3",
    "bvec4",
    "ivec2",
    "ivec3",
    "ivec4",
    "uvec2",
    "uvec3",
    "uvec4",
    "mat2",
    "mat3",
    "mat4",
    "mat2x3",
    "mat2x4",
    "mat3x2",
    "mat3x4",
    "mat4x2",
    "mat4x3",
    "sampler2D",
    "sampler3D",
    "samplerCube",
    "sampler2DShadow",
    "samplerCubeShadow",
    "sampler2DArray",
    "sampler2DArrayShadow",
    "isampler2D",
    "isampler3D",
    "isamplerCube",
    "isampler2DArray",
    "usampler2D",
    "usampler3D",
    "usamplerCube",
    "usampler2DArray",
];

/// The keywords that start a declaration (qualifiers), which a word where a type is expected
/// may be a misspelling of.
const QUALIFIERS: &[&str] = &[
    "uniform",
    "const",
    "in",
    "out",
    "inout",
    "attribute",
    "varying",
    "precision",
    "highp",
    "mediump",
    "lowp",
    "flat",
    "smooth",
    "centroid",
    "invariant",
    "layout",
    "struct",
];

/// Levenshtein distance, or 3 for strings whose lengths differ by more than 2.
pub(crate) fn edit_distance(a: &str, b: &str) -> usize {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    if a.len().abs_diff(b.len()) > 2 {
        return 3;
    }
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.iter().enumerate() {
        let mut cur = vec![i + 1];
        for (j, cb) in b.iter().enumerate() {
            let v = (prev[j] + usize::from(ca != cb))
                .min(prev[j + 1] + 1)
                .min(cur[j] + 1);
            cur.push(v);
        }
        prev = cur;
    }
    prev[b.len()]
}

/// How far a candidate may be from `name`: a case difference always, then one edit per three
/// letters (at most two), and none for names of one or two letters (`u` is not `c`).
fn close(name: &str, candidate: &str) -> Option<usize> {
    if candidate.eq_ignore_ascii_case(name) {
        return Some(0);
    }
    if name.len() < 3 {
        return None;
    }
    let most = (name.len() / 3).clamp(1, 2);
    let d = edit_distance(name, candidate);
    (d <= most).then_some(d)
}

/// The nearest of `candidates` to `name`, if one is near enough (the first of equals).
pub(crate) fn nearest<'a>(
    name: &str,
    candidates: impl IntoIterator<Item = &'a str>,
) -> Option<&'a str> {
    let mut best: Option<(usize, &str)> = None;
    for c in candidates {
        if c == name {
            continue;
        }
        if let Some(d) = close(name, c) {
            if best.is_none_or(|(b, _)| d < b) {
                best = Some((d, c));
            }
        }
    }
    best.map(|(_, c)| c)
}

/// The built-in function of GLSL ES 3.00 (or 1.00) nearest to `name`.
pub(crate) fn builtin_function(name: &str, es100: bool) -> Option<&'static str> {
    nearest(name, crate::builtins::function_names(es100))
}

/// The type or declaration keyword nearest to `name`, and which it is.
pub(crate) fn type_or_keyword(name: &str) -> Option<(&'static str, &'static str)> {
    if let Some(t) = nearest(name, TYPES.iter().copied()) {
        return Some((t, "type"));
    }
    nearest(name, QUALIFIERS.iter().copied()).map(|k| (k, "keyword"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn near_words() {
        assert_eq!(builtin_function("normalise", false), Some("normalize"));
        assert_eq!(builtin_function("textur", false), Some("texture"));
        assert_eq!(builtin_function("Normalize", false), Some("normalize"));
        assert_eq!(builtin_function("myLighting", false), None);
        assert_eq!(type_or_keyword("flot"), Some(("float", "type")));
        assert_eq!(type_or_keyword("unifrom"), Some(("uniform", "keyword")));
        assert_eq!(type_or_keyword("Light"), None);
        assert_eq!(nearest("u", ["c", "uv"]), None);
    }
}
