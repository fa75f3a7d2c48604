//! glslangValidator as a peer, run in the same scoring pass as essl (Debian's `glslang-tools`
//! puts it on `PATH`): a pair is accepted when `glslangValidator -l NAME.vert NAME.frag` —
//! compile both, link them — exits with status 0. glslang knows no WebGL context, so its
//! answer is the same for both.

use std::path::PathBuf;
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};

/// A glslangValidator found on `PATH`.
pub(super) struct Glslang {
    /// Its version line (`Glslang Version: 11:12.0.0`).
    pub version: String,
    dir: PathBuf,
}

impl Glslang {
    /// The validator, when `glslangValidator --version` runs.
    pub fn find() -> Option<Glslang> {
        let out = Command::new("glslangValidator")
            .arg("--version")
            .output()
            .ok()?;
        let text = String::from_utf8_lossy(&out.stdout);
        let version = text.lines().next()?.trim().to_string();
        let dir = std::env::temp_dir().join(format!("essl-glslang-{}", std::process::id()));
        std::fs::create_dir_all(&dir).ok()?;
        Some(Glslang { version, dir })
    }

    /// Whether glslang compiles both shaders and links them.
    pub fn accepts(&self, vertex: &str, fragment: &str) -> bool {
        static NEXT: AtomicUsize = AtomicUsize::new(0);
        let n = NEXT.fetch_add(1, Ordering::Relaxed);
        let (v, f) = (
            self.dir.join(format!("{n}.vert")),
            self.dir.join(format!("{n}.frag")),
        );
        if std::fs::write(&v, vertex).is_err() || std::fs::write(&f, fragment).is_err() {
            return false;
        }
        let ok = Command::new("glslangValidator")
            .arg("-l")
            .arg(&v)
            .arg(&f)
            .output()
            .is_ok_and(|o| o.status.success());
        let _ = std::fs::remove_file(&v);
        let _ = std::fs::remove_file(&f);
        ok
    }
}

impl Drop for Glslang {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.dir);
    }
}
