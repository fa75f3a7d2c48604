//! `essl-server`: the Language Server over standard input and output (`essl server` is the
//! same).

fn main() -> std::process::ExitCode {
    match essl_server::run_stdio() {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("essl-server: {e}");
            std::process::ExitCode::from(1)
        }
    }
}

#[cfg(feature = "mimalloc")]
#[global_allocator]
static ALLOCATOR: essl_alloc::Allocator = essl_alloc::Allocator;
