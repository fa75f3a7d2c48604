//! The integration tests of this crate, one binary (each test file was a binary of its own,
//! and linking them was most of the test suite's time). Each module is one former file.

mod cli;
mod conformance;
mod deqp_exec;
mod doors;
mod flags;
mod formats;
mod pages;
mod snapshots;
mod translate;
