//! Which shader files make a program: `NAME.vert` + `NAME.frag` in one folder (also `.vs`/`.fs`,
//! `.vsh`/`.fsh`, and each before `.glsl`: `NAME.vert.glsl`). One rule for a whole run
//! ([`pairs`]) and for an editor looking for one file's partner ([`partner`]).

use std::collections::HashMap;
use std::ffi::OsStr;
use std::path::{Path, PathBuf};

use essl::Stage;

/// A shader file and its stage.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ShaderFile {
    /// Its path, as given or as found under a folder given.
    pub path: PathBuf,
    /// Its stage.
    pub stage: Stage,
}

/// The stage extensions in the order a name's files are preferred: where a folder has `a.vert`
/// and `a.vs`, `a.vert` is the one paired.
const EXTENSIONS: [(&str, Stage); 6] = [
    ("vert", Stage::Vertex),
    ("frag", Stage::Fragment),
    ("vs", Stage::Vertex),
    ("fs", Stage::Fragment),
    ("vsh", Stage::Vertex),
    ("fsh", Stage::Fragment),
];

/// A file name's base name, stage and rank, where its extension names the stage: `a.vert` →
/// `a`, vertex, 0; `a.fs.glsl` → `a`, fragment, 9.
fn named(path: &Path) -> Option<(&OsStr, Stage, usize)> {
    let name = path.file_name()?.to_str()?;
    let (base, glsl) = match name.strip_suffix(".glsl") {
        Some(b) => (b, true),
        None => (name, false),
    };
    let (stem, ext) = base.rsplit_once('.')?;
    let rank = EXTENSIONS.iter().position(|(e, _)| *e == ext)?;
    Some((
        OsStr::new(stem),
        EXTENSIONS[rank].1,
        rank + 6 * glsl as usize,
    ))
}

/// The pairs to link: for each folder and base name, the vertex and the fragment shader of that
/// name (`light.vert` + `light.frag`, `light.fixed.vert` + `light.fixed.frag`). Indices into
/// `files`, sorted by the vertex path. Where a name has several files of one stage (`a.vert`
/// and `a.vs`), the first in the order `.vert`, `.vs`, `.vsh` (`.frag`, `.fs`, `.fsh`), each
/// before its `.glsl` form, is used. Only files whose name gives their stage pair up.
pub fn pairs(files: &[ShaderFile]) -> Vec<(usize, usize)> {
    // A pair takes two files; one file (a text checked alone) needs no folder resolved.
    if files.len() < 2 {
        return Vec::new();
    }
    // `shaders/a.vert` pairs with `./shaders/a.frag`: compare the folders themselves, each
    // written form resolved once (a folder of 10,000 shaders is one `canonicalize`).
    let mut folder_of: HashMap<&Path, usize> = HashMap::new();
    let mut folders: HashMap<PathBuf, usize> = HashMap::new();
    // Per folder and base name: the vertex and the fragment file, each (index, rank).
    type Slots = [Option<(usize, usize)>; 2];
    let mut by_name: HashMap<(usize, &OsStr), Slots> = HashMap::new();
    for (i, file) in files.iter().enumerate() {
        let Some((stem, stage, rank)) = named(&file.path).filter(|n| n.1 == file.stage) else {
            continue;
        };
        let Some(parent) = file.path.parent() else {
            continue;
        };
        let folder = *folder_of.entry(parent).or_insert_with(|| {
            let real = std::fs::canonicalize(parent).unwrap_or_else(|_| parent.to_path_buf());
            let next = folders.len();
            *folders.entry(real).or_insert(next)
        });
        let slot = &mut by_name.entry((folder, stem)).or_default()[stage_slot(stage)];
        if slot.is_none_or(|(_, r)| rank < r) {
            *slot = Some((i, rank));
        }
    }
    let mut out: Vec<(usize, usize)> = by_name
        .into_values()
        .filter_map(|[v, f]| Some((v?.0, f?.0)))
        .collect();
    // Files listed in path order (as a walk lists them) need no path comparisons.
    out.sort_unstable();
    if !out.is_sorted_by(|a, b| files[a.0].path <= files[b.0].path) {
        out.sort_by(|a, b| files[a.0].path.cmp(&files[b.0].path).then(a.0.cmp(&b.0)));
    }
    out
}

fn stage_slot(stage: Stage) -> usize {
    (stage == Stage::Fragment) as usize
}

/// The file the shader at `path` is linked with, as [`pairs`] would pair them among the files
/// `exists` knows: `None` when `path` has no partner, or when another file of its name and
/// stage is the one paired (`a.vert` beside `a.vs`).
pub fn partner(path: &Path, exists: impl Fn(&Path) -> bool) -> Option<PathBuf> {
    let (stem, stage, rank) = named(path)?;
    let stem = stem.to_str()?;
    let candidates = |want: Stage| {
        let exists = &exists;
        (0..12).filter_map(move |r| {
            let (ext, s) = EXTENSIONS[r % 6];
            let glsl = if r >= 6 { ".glsl" } else { "" };
            let p = path.with_file_name(format!("{stem}.{ext}{glsl}"));
            (s == want && exists(&p)).then_some((p, r))
        })
    };
    if candidates(stage).any(|(_, r)| r < rank) {
        return None;
    }
    let other = match stage {
        Stage::Vertex => Stage::Fragment,
        Stage::Fragment => Stage::Vertex,
    };
    candidates(other).next().map(|(p, _)| p)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn file(path: impl Into<PathBuf>, stage: Stage) -> ShaderFile {
        ShaderFile {
            path: path.into(),
            stage,
        }
    }

    #[test]
    fn pairs_by_folder_and_base_name() {
        let files = vec![
            file("d/a.fixed.frag", Stage::Fragment),
            file("d/a.fixed.vert", Stage::Vertex),
            file("d/a.frag", Stage::Fragment),
            file("d/a.vert", Stage::Vertex),
            file("d/a.vs", Stage::Vertex),
            file("d/b.vert", Stage::Vertex),
            file("e/a.frag", Stage::Fragment),
            file("d/c.glsl", Stage::Vertex),
            file("d/c.frag", Stage::Fragment),
        ];
        assert_eq!(pairs(&files), vec![(1, 0), (3, 2)]);
    }

    #[test]
    fn pairs_come_in_vertex_path_order_however_files_are_listed() {
        let files = vec![
            file("z.vert", Stage::Vertex),
            file("b/a.frag", Stage::Fragment),
            file("a.frag", Stage::Fragment),
            file("z.frag", Stage::Fragment),
            file("b/a.vert", Stage::Vertex),
            file("a.vert", Stage::Vertex),
        ];
        assert_eq!(pairs(&files), vec![(5, 2), (4, 1), (0, 3)]);
    }

    #[test]
    fn a_folder_pairs_with_itself_however_it_is_written() {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path().join("d");
        std::fs::create_dir(&d).unwrap();
        let files = vec![
            file(d.join("a.vert"), Stage::Vertex),
            file(d.join("../d/a.frag"), Stage::Fragment),
        ];
        assert_eq!(pairs(&files), vec![(0, 1)]);
    }

    #[test]
    fn glsl_suffixed_names_pair_and_partners_follow_the_same_ranks() {
        let files = vec![
            file("a.vert.glsl", Stage::Vertex),
            file("a.frag.glsl", Stage::Fragment),
            file("b.vs", Stage::Vertex),
        ];
        assert_eq!(pairs(&files), vec![(0, 1)]);
        let exists = |p: &Path| {
            [
                "d/l.vert", "d/l.fs", "d/l.frag", "d/m.vs", "d/m.vert", "d/m.frag",
            ]
            .iter()
            .any(|q| Path::new(q) == p)
        };
        assert_eq!(
            partner(Path::new("d/l.vert"), exists),
            Some(PathBuf::from("d/l.frag"))
        );
        assert_eq!(
            partner(Path::new("d/l.frag"), exists),
            Some(PathBuf::from("d/l.vert"))
        );
        assert_eq!(
            partner(Path::new("d/l.fs"), exists),
            None,
            "l.frag is the pair's"
        );
        assert_eq!(
            partner(Path::new("d/m.vs"), exists),
            None,
            "m.vert is the pair's"
        );
        assert_eq!(partner(Path::new("l.glsl"), exists), None);
    }
}
