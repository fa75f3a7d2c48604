//! Uniform references: a uniform of the default block or a part of it, named as WebGL names it
//! (`light.cutOff`, `spotLights[0].coneCos`, `u_lights[*].position`).

use std::fmt;

/// One step from a uniform to a part of it.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum PathStep {
    /// A struct member (`.cutOff`).
    Member(String),
    /// A constant array index (`[2]`).
    Index(u32),
    /// A dynamic array index (`[i]`): any element.
    AnyIndex,
}

/// A uniform or a part of it, as WebGL names it: `u_innerLimit`, `light.cutOff`,
/// `spotLights[0].coneCos`, `u_lights[*].position` (any element).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct UniformRef {
    /// The uniform's declared name.
    pub base: String,
    /// Members and indices from it.
    pub path: Vec<PathStep>,
}

impl UniformRef {
    /// A uniform itself.
    pub fn new(base: impl Into<String>) -> UniformRef {
        UniformRef {
            base: base.into(),
            path: Vec::new(),
        }
    }

    /// Whether a step is [`PathStep::AnyIndex`].
    pub fn has_any_index(&self) -> bool {
        self.path.contains(&PathStep::AnyIndex)
    }

    /// The WebGL name (`getUniformLocation`'s), with `index` for every
    /// [`PathStep::AnyIndex`] (`*` for `None`).
    pub fn name(&self, index: Option<u32>) -> String {
        let mut s = self.base.clone();
        for step in &self.path {
            match step {
                PathStep::Member(m) => {
                    s.push('.');
                    s.push_str(m);
                }
                PathStep::Index(i) => s.push_str(&format!("[{i}]")),
                PathStep::AnyIndex => match index {
                    Some(i) => s.push_str(&format!("[{i}]")),
                    None => s.push_str("[*]"),
                },
            }
        }
        s
    }

    /// Whether the value WebGL names `name` (a leaf such as `spotLights[0].coneCos` or
    /// `u_weights[3]`) is this uniform or a part of it; `[*]` matches any index.
    pub fn covers(&self, name: &str) -> bool {
        let pattern = self.name(None);
        let (mut p, mut n) = (pattern.as_str(), name);
        loop {
            match p.find("[*]") {
                Some(i) => {
                    if n.len() < i || p[..i] != n[..i] {
                        return false;
                    }
                    let rest = &n[i..];
                    let Some(after) = rest.strip_prefix('[') else {
                        return false;
                    };
                    let digits = after.bytes().take_while(u8::is_ascii_digit).count();
                    if digits == 0 || !after[digits..].starts_with(']') {
                        return false;
                    }
                    n = &after[digits + 1..];
                    p = &p[i + 3..];
                }
                None => {
                    return n == p
                        || (n.starts_with(p)
                            && matches!(n.as_bytes().get(p.len()), Some(b'.' | b'[')));
                }
            }
        }
    }
}

impl fmt::Display for UniformRef {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.name(None))
    }
}
