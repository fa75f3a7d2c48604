//! The integration tests of this crate, one binary (each test file was a binary of its own,
//! and linking them was most of the test suite's time). Each module is one former file.

mod binding_map;
mod clip_distances;
mod corpora;
mod draw_id;
mod hazards;
mod scenes;
mod snapshots;
