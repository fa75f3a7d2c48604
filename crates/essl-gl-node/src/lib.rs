//! essl-gl as a Node.js addon (napi-rs).
//!
//! The JavaScript package (`package.json`, `index.js`, `lib/`) gives Node programs WebGL's
//! `WebGL2RenderingContext` and `WebGLRenderingContext`: it converts arguments as WebIDL
//! does (a wrong type is a `TypeError`), keeps one JavaScript object per WebGL object, and
//! answers a lost context; this crate is what it calls. [`NativeContext`] owns an
//! [`essl_gl::Context`] and has one method per WebGL call, taking arguments already converted
//! (numbers, booleans, strings, typed arrays borrowed without a copy, objects as ids from
//! [`registry`]) and returning essl-gl's answers as JavaScript values ([`answer`]). Every rule
//! of WebGL — which enums are valid, which errors a call records — is essl-gl's; this crate
//! adds only what a binding alone can see (a `srcOffset` past the end of an array).

#![warn(missing_docs)]
#![deny(clippy::all)]

pub mod answer;
mod calls;
pub mod context;
pub mod error;
mod png;
pub(crate) mod registry;
pub mod view;

pub use context::{Attributes, NativeContext};
pub use error::BindingError;
pub use png::{decode_png, DecodedImage};
