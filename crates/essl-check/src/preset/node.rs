//! Running a preset's script in Node.js, in the project's folder, so that it reads the library
//! the project has installed: a JSON request on standard input, a JSON answer on standard
//! output.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use std::collections::HashMap;

use super::{key, Prepared, Preset, PresetError};
use crate::extract::HostKind;
use crate::find::Found;
use crate::settings::Configs;

/// The script hosts of `found` whose settings name `preset`, by the project folder whose
/// `node_modules` holds `package`; a host with no such folder above it is recorded as failed.
pub fn projects(
    found: &Found,
    configs: &Configs,
    preset: Preset,
    package: &'static str,
    prepared: &mut Prepared,
) -> HashMap<PathBuf, Vec<usize>> {
    let mut projects: HashMap<PathBuf, Vec<usize>> = HashMap::new();
    for (h, host) in found.hosts.iter().enumerate() {
        let named = configs
            .for_file(&host.path)
            .is_ok_and(|s| s.preset == Some(preset));
        if !named || host.kind != HostKind::Script {
            continue;
        }
        let dir = match host.path.parent() {
            Some(p) if !p.as_os_str().is_empty() => p,
            _ => Path::new("."),
        };
        match project_root(dir, package) {
            Some(root) => projects.entry(root).or_default().push(h),
            None => {
                let e = PresetError::NoPackage {
                    preset: preset.as_str(),
                    package,
                    dir: dir.to_path_buf(),
                };
                prepared.failed.insert(key(&host.path), e);
            }
        }
    }
    projects
}

/// The folder at or above `from` whose `node_modules` holds `package`: where the project's
/// copy of the library is.
pub fn project_root(from: &Path, package: &str) -> Option<PathBuf> {
    let start = std::fs::canonicalize(from).unwrap_or_else(|_| from.to_path_buf());
    start
        .ancestors()
        .find(|dir| {
            dir.join("node_modules")
                .join(package)
                .join("package.json")
                .is_file()
        })
        .map(Path::to_path_buf)
}

/// Runs `script` (an ES module) with Node.js in `cwd`, giving it `input`; its answer.
pub fn run(
    script: &str,
    cwd: &Path,
    input: &serde_json::Value,
) -> Result<serde_json::Value, PresetError> {
    let node = std::env::var_os("ESSL_NODE").unwrap_or_else(|| "node".into());
    let mut child = Command::new(&node)
        .args(["--input-type=module", "-e", script])
        .current_dir(cwd)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| PresetError::NoNode(e.to_string()))?;
    let body = input.to_string();
    if let Some(mut stdin) = child.stdin.take() {
        // A script that stops reading early shows up in its exit status below.
        let _ = stdin.write_all(body.as_bytes());
    }
    let out = child
        .wait_with_output()
        .map_err(|e| PresetError::NoNode(e.to_string()))?;
    if !out.status.success() {
        let err = String::from_utf8_lossy(&out.stderr);
        let first = err
            .lines()
            .find(|l| l.contains("Error"))
            .unwrap_or(err.trim());
        return Err(PresetError::Script(first.chars().take(400).collect()));
    }
    serde_json::from_slice(&out.stdout).map_err(|e| PresetError::Script(e.to_string()))
}
