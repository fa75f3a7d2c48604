//! The integration tests of this crate, one binary (each test file was a binary of its own,
//! and linking them was most of the test suite's time). Each module is one former file.

mod docs;
mod examples;
mod idioms;
mod preconditions;
mod recall;
mod rules;
mod seeds;
