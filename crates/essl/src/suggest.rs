//! Names near a misspelt one, for tools that name things essl does not know (a library's
//! chunks, a preset's modules): the nearest candidate by edit distance, as essl's own "a
//! built-in function with a similar name exists" helps choose it.

/// The nearest of `candidates` to `name`, if one is near enough: a case difference, or one
/// edit per three letters (two at most); none for names of one or two letters.
pub fn nearest<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    crate::near::nearest(name, candidates)
}

/// The built-in type names of GLSL ES 3.00 and 1.00 (`void`, `float`, `vec3`, `sampler2D`, …),
/// the ones a misspelt type is matched against: for completion lists.
pub const TYPE_NAMES: &[&str] = crate::near::TYPES;
