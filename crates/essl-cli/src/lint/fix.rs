//! `--fix`: applying the front end's certain fixes, in rounds, and writing files atomically.

use std::io::Write;
use std::path::Path;

use essl::diagnostic::{apply_fixes, Applicability};
use essl::source::SourceFile;
use essl::{compile, CompileOptions, Shader, Stage};

/// How many rounds of fixes `--fix` applies at most: a fix can unlock another (a parse that
/// recovers further once a `;` is in place), and a few rounds reach a fixed point in practice.
pub const MAX_ROUNDS: usize = 8;

/// The result of fixing one shader's text.
#[derive(Debug)]
pub struct Fixed {
    /// The text after every round.
    pub text: String,
    /// How many fixes were applied, over all rounds.
    pub applied: usize,
    /// The shader compiled from the final text.
    pub shader: Shader,
}

/// Compiles `text`, applies its certain fixes ([`Applicability::Certain`]; with
/// `unsafe_fixes` also the suggested ones, after them) and recompiles, until no fix applies or
/// the text stops changing (at most [`MAX_ROUNDS`] rounds).
pub fn fix_text(
    name: &str,
    text: String,
    stage: Stage,
    options: &CompileOptions,
    unsafe_fixes: bool,
) -> Fixed {
    let mut text = text;
    let mut applied = 0;
    let mut shader = compile(SourceFile::new(name, text.as_str()), stage, options);
    for _ in 0..MAX_ROUNDS {
        let (mut new_text, mut n) = apply_fixes(&text, &shader.diagnostics, Applicability::Certain);
        if n == 0 && unsafe_fixes {
            (new_text, n) = apply_fixes(&text, &shader.diagnostics, Applicability::Suggested);
        }
        if n == 0 || new_text == text {
            break;
        }
        applied += n;
        text = new_text;
        shader = compile(SourceFile::new(name, text.as_str()), stage, options);
    }
    Fixed {
        text,
        applied,
        shader,
    }
}

/// Replaces a file's contents atomically: writes a temporary file beside it (same folder, same
/// permissions), flushes it to disk, then renames it over the original, so a reader sees the
/// old text or the new one, never half of it.
pub fn write_atomically(path: &Path, text: &str) -> std::io::Result<()> {
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let permissions = std::fs::metadata(path)?.permissions();
    let mut attempt = 0u32;
    let (tmp, mut file) = loop {
        let tmp = dir.join(format!(
            ".{name}.essl-fix-{}-{attempt}.tmp",
            std::process::id()
        ));
        match std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&tmp)
        {
            Ok(file) => break (tmp, file),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists && attempt < 100 => {
                attempt += 1
            }
            Err(e) => return Err(e),
        }
    };
    let result = (|| {
        file.write_all(text.as_bytes())?;
        file.sync_all()?;
        drop(file);
        std::fs::set_permissions(&tmp, permissions)?;
        std::fs::rename(&tmp, path)
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fixes_missing_semicolons_in_rounds() {
        let text = "#version 300 es\nprecision highp float;\nuniform float a\nuniform float b\nout vec4 c;\nvoid main() { c = vec4(a + b); }\n";
        let fixed = fix_text(
            "t.frag",
            text.to_string(),
            Stage::Fragment,
            &Default::default(),
            false,
        );
        assert!(fixed.shader.ok(), "{:?}", fixed.shader.diagnostics);
        assert!(fixed.applied >= 2);
        assert!(fixed.text.contains("uniform float a;\nuniform float b;\n"));
    }

    #[test]
    fn writes_atomically() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a.frag");
        std::fs::write(&path, "old").unwrap();
        write_atomically(&path, "new").unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "new");
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    }
}
