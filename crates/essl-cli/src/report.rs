//! `essl report [--out docs] [--quick] [--scenes ../shared/scenes]`: the light shaders' error
//! against run time, drawn through essl-gl — a thin wrapper over [`essl_lights::report`], which
//! does the work (see `docs/report.md` for what it measures).

use std::path::Path;

use essl_lights::report::{self, Settings};

/// Runs the report and writes `report.md`, `report.svg`, the pictures and (full run) the GPU
/// section of `numerical-stability.md` into `out`; prints the table. Returns the exit status:
/// 0 written, 1 a measurement or a write failed, 2 no Vulkan adapter.
pub fn run(out: &Path, quick: bool, scenes: &Path) -> i32 {
    if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
        // Silences a harmless complaint of the Vulkan loader.
        std::env::set_var("XDG_RUNTIME_DIR", std::env::temp_dir());
    }
    let scenes = scenes.is_dir().then(|| scenes.to_path_buf());
    if scenes.is_none() {
        eprintln!(
            "note: no seed scenes at the given folder: the specialised-vs-uber part is left out"
        );
    }
    let settings = if quick {
        Settings::quick(scenes)
    } else {
        Settings::full(scenes)
    };
    let result = match report::run(&settings, &mut |line| eprintln!("{line}")) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("error: {e}");
            return match e {
                essl_lights::LightsError::Gpu(ref m) if m.contains("no Vulkan adapter") => 2,
                _ => 1,
            };
        }
    };
    print!("{}", report::text_table(&result));
    match report::write(&result, out) {
        Ok(files) => {
            for f in files {
                eprintln!("wrote {}", f.display());
            }
            println!(
                "essl report: {} variants in {:.0} s on {}",
                result.results.len(),
                result.wall_s,
                result.machine.renderer
            );
            0
        }
        Err(e) => {
            eprintln!("error: {e}");
            1
        }
    }
}
