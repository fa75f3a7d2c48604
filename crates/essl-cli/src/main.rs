//! `essl`: check WebGL shaders (GLSL ES 3.00 and 1.00, for WebGL 2 and WebGL 1).

#[cfg(feature = "mimalloc")]
#[global_allocator]
static ALLOCATOR: essl_alloc::Allocator = essl_alloc::Allocator;

fn main() -> std::process::ExitCode {
    std::process::ExitCode::from(essl_cli::cli::main_from(std::env::args_os()))
}
