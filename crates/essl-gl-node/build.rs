//! Links the addon as Node.js loads it (napi-rs's setup of the linker).
fn main() {
    napi_build::setup();
}
