//! The integration tests of this crate, one binary (each test file was a binary of its own,
//! and linking them was most of the test suite's time). Each module is one former file.

mod annotated;
mod codes;
mod differential;
mod minify;
mod oracle;
mod preprocess;
mod robustness;
mod rules;
mod rules_es100;
mod seed;
