//! The macros defined at a point of the text, by name.
//!
//! The preprocessor asks for every identifier of the text whether it names a macro, and most
//! do not (`vec4`, `gl_FragColor`, the shader's own names). The table keeps a mask of the first
//! bytes of the names ever defined in it — the predefined macros start with `_` or `G` — so that
//! most of those answers take one bit test instead of hashing the name.
//!
//! The predefined macros (`__LINE__`, `GL_ES`, the extensions' names…) are the same in every
//! file: each thread builds them once and shares them with every file it preprocesses, instead
//! of allocating two dozen blocks per file for them.

use crate::Name;
use std::cell::RefCell;
use std::rc::Rc;

use rustc_hash::FxHashMap as HashMap;

use super::expand::{Body, Dynamic, Macro};

/// The macros defined at a point of the text, by name.
#[derive(Default)]
pub(super) struct Defined {
    map: HashMap<Name, Rc<Macro>>,
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
        self.insert_shared(Rc::new(m));
    }

    /// Defines the predefined macro `name` with the value `value` (a number).
    pub fn predefine(&mut self, name: &str, value: &str, dynamic: Option<Dynamic>) {
        self.insert_shared(shared_predefined(name, value, dynamic));
    }

    /// Defines `m`, keeping [`Defined::first`] in step with the names.
    fn insert_shared(&mut self, m: Rc<Macro>) {
        self.first |= bit(&m.name);
        self.map.insert(m.name.clone(), m);
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

/// How many predefined macros a thread keeps: the language's five, `__VERSION__`'s two values
/// and the extensions of a few option sets.
const SHARED: usize = 32;

/// The predefined macro `name` = `value`, from this thread's set when it is there and no other
/// table holds it (so its expansion state is its own), built otherwise.
fn shared_predefined(name: &str, value: &str, dynamic: Option<Dynamic>) -> Rc<Macro> {
    thread_local! {
        static SET: RefCell<Vec<Rc<Macro>>> = const { RefCell::new(Vec::new()) };
    }
    let fresh = || Rc::new(Macro::predefined(name, value, dynamic));
    SET.with(|set| {
        let Ok(mut set) = set.try_borrow_mut() else {
            return fresh();
        };
        let same = |m: &&Rc<Macro>| {
            &*m.name == name
                && m.dynamic == dynamic
                && matches!(&m.body[..], [Body::Tok(t)] if &*t.text == value)
        };
        match set.iter().find(same) {
            Some(m) if Rc::strong_count(m) == 1 => {
                // A file that stopped mid-expansion drops its contexts, which re-enable the
                // macro; set both again all the same.
                m.disabled.set(false);
                m.invoking.set(0);
                m.clone()
            }
            Some(_) => fresh(),
            None => {
                let m = fresh();
                if set.len() < SHARED {
                    set.push(m.clone());
                }
                m
            }
        }
    })
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

    #[test]
    fn predefined_macros_are_shared_only_when_free() {
        let mut a = Defined::default();
        a.predefine("GL_ES", "1", None);
        let first = Rc::as_ptr(a.get("GL_ES").unwrap());
        // While `a` holds it, another table gets its own.
        let mut b = Defined::default();
        b.predefine("GL_ES", "1", None);
        assert_ne!(Rc::as_ptr(b.get("GL_ES").unwrap()), first);
        drop(a);
        drop(b);
        // Once free, the next table shares it, with its expansion state cleared.
        let m = shared_predefined("GL_ES", "1", None);
        assert_eq!(Rc::as_ptr(&m), first);
        m.disabled.set(true);
        drop(m);
        let mut c = Defined::default();
        c.predefine("GL_ES", "1", None);
        assert!(!c.get("GL_ES").unwrap().disabled.get());
        // Another value is another macro.
        c.predefine("__VERSION__", "300", None);
        c.predefine("__VERSION__", "100", None);
        let v = c.get("__VERSION__").unwrap();
        assert!(matches!(&v.body[..], [Body::Tok(t)] if &*t.text == "100"));
    }
}
