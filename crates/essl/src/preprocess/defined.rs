//! The macros defined at a point of the text, by name.
//!
//! The preprocessor asks for every identifier of the text whether it names a macro, and most
//! do not (`vec4`, `gl_FragColor`, the shader's own names). The table keeps a mask of the first
//! bytes of the names ever defined in it — the predefined macros start with `_` or `G` — so that
//! most of those answers take one bit test instead of hashing the name.

use std::rc::Rc;
use std::sync::Arc;

use rustc_hash::FxHashMap as HashMap;

use super::expand::Macro;

/// The macros defined at a point of the text, by name.
#[derive(Default)]
pub(super) struct Defined {
    map: HashMap<Arc<str>, Rc<Macro>>,
    /// Bit `b & 127` is set when a name starting with byte `b` was ever defined (an `#undef`
    /// leaves it set: the mask only rules names out).
    first: u128,
}

/// The bit of `name`'s first byte in [`Defined::first`].
fn bit(name: &str) -> u128 {
    1 << (name.as_bytes().first().copied().unwrap_or(0) & 127)
}

impl Defined {
    /// The macro named `name`, if one is defined.
    pub fn get(&self, name: &str) -> Option<&Rc<Macro>> {
        if self.first & bit(name) == 0 {
            return None;
        }
        self.map.get(name)
    }

    /// Whether a macro named `name` is defined.
    pub fn contains_key(&self, name: &str) -> bool {
        self.get(name).is_some()
    }

    /// Defines (or redefines) the macro `m`.
    pub fn insert(&mut self, m: Macro) {
        self.first |= bit(&m.name);
        self.map.insert(m.name.clone(), Rc::new(m));
    }

    /// Undefines the macro named `name`.
    pub fn remove(&mut self, name: &str) {
        self.map.remove(name);
    }

    /// Makes room for `n` more macros.
    pub fn reserve(&mut self, n: usize) {
        self.map.reserve(n);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_found_whatever_their_first_byte() {
        let mut d = Defined::default();
        for name in ["A", "_x", "GL_ES", "z9", "\u{e9}t\u{e9}"] {
            assert!(!d.contains_key(name));
            d.insert(Macro::predefined(name, "1", None));
            assert!(d.contains_key(name), "{name}");
        }
        // A name sharing a first byte with a defined one is still looked up, and absent.
        assert!(!d.contains_key("Ab"));
        assert!(!d.contains_key("y"));
        d.remove("GL_ES");
        assert!(!d.contains_key("GL_ES"));
        assert!(d.get("A").is_some_and(|m| &*m.name == "A"));
    }
}
