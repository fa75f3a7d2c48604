//! The passes of [`compile`](crate::compile), one at a time: for tools that time, fuzz or test
//! a single pass (the per-pass benchmark, the preprocessor's rule-by-rule tests), and the
//! built-in functions' overloads (`overloads_in`, for an editor's hover). A shader
//! compiled through these is the same as one from `compile`, which also runs lowering and
//! bounds the stack (`COMPILE_STACK`); most users want `compile`.
//!
//! ```
//! use essl::passes::{check, classify, lex, parse, preprocess, PreprocessOptions};
//! use essl::source::SourceFile;
//! use essl::Stage;
//!
//! let file = SourceFile::new("a.frag", "#version 300 es\nvoid main() {}\n");
//! let pp = preprocess(&file, lex(&file), &PreprocessOptions::default());
//! let mut diagnostics = pp.diagnostics;
//! let tokens = classify(pp.tokens, &mut diagnostics);
//! let (unit, _) = parse(&file, tokens, Stage::Fragment);
//! let (module, found) = check(&file, &unit, Stage::Fragment, pp.invariant_all);
//! assert!(found.is_empty() && module.entry.is_some());
//! ```

pub use crate::ast::TranslationUnit;
pub use crate::builtins::{overloads_in, Signature};
pub use crate::check::{check, check_as};
pub use crate::lex::{lex, Lexed, PpKind, PpToken, Punct};
pub use crate::parse::{parse, parse_as, MAX_NESTING};
pub use crate::preprocess::{
    preprocess, Expansion, ExtensionBehavior, LineDirective, PreprocessOptions, Preprocessed,
    MAX_EXPANDED_TOKENS,
};
pub use crate::target::Language;
pub use crate::token::{classify, classify_as, Tok, Token};
