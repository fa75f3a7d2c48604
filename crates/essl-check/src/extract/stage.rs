//! Telling a shader's stage from what surrounds it: a `#pragma essl stage(…)` line, the name
//! the host gives it, or, last, the built-ins only one stage has.

use essl::Stage;

/// The stage a `#pragma essl stage(vertex)` or `#pragma essl stage(fragment)` line names.
pub fn stage_pragma(text: &str) -> Option<Stage> {
    text.lines().find_map(|line| {
        let rest = line.trim_start().strip_prefix('#')?.trim_start();
        let rest = rest.strip_prefix("pragma")?.trim_start();
        let rest = rest.strip_prefix("essl")?.trim_start();
        let rest = rest.strip_prefix("stage")?.trim_start();
        let inner = rest.strip_prefix('(')?.split(')').next()?.trim();
        match inner {
            "vertex" => Some(Stage::Vertex),
            "fragment" => Some(Stage::Fragment),
            _ => None,
        }
    })
}

/// Whether a `#pragma essl chunk` line marks the text as a chunk: code to put into shaders,
/// checked as a library.
pub fn chunk_pragma(text: &str) -> bool {
    text.contains("chunk")
        && text.lines().any(|line| {
            let words: Vec<&str> = line
                .trim_start()
                .strip_prefix('#')
                .map(|r| r.split_whitespace().collect())
                .unwrap_or_default();
            words == ["pragma", "essl", "chunk"]
        })
}

/// The words of a name, lower case: `skyboxVS` → `skybox`, `vs`; `vertex-shader-3d` →
/// `vertex`, `shader`, `3d`; `FS300` → `fs`, `300`.
fn words(name: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let mut current = String::new();
    let mut prev_lower = false;
    let mut prev_upper = false;
    for c in name.chars() {
        if !c.is_ascii_alphanumeric() {
            if !current.is_empty() {
                out.push(std::mem::take(&mut current));
            }
            prev_lower = false;
            prev_upper = false;
            continue;
        }
        let split = (c.is_ascii_uppercase() && prev_lower) || (c.is_ascii_digit() && prev_upper);
        if split && !current.is_empty() {
            out.push(std::mem::take(&mut current));
        }
        prev_lower = c.is_ascii_lowercase() || c.is_ascii_digit();
        prev_upper = c.is_ascii_uppercase();
        current.push(c.to_ascii_lowercase());
    }
    if !current.is_empty() {
        out.push(current);
    }
    out
}

const VERTEX_WORDS: &[&str] = &["vertex", "vs", "vert", "vsh", "vshader"];
const FRAGMENT_WORDS: &[&str] = &["fragment", "fs", "frag", "fsh", "fshader", "pixel"];

/// The stage a name says (`vs`, `skyboxVS`, `vertexShaderSource`, `fragment-shader-3d`).
pub fn stage_from_name(name: &str) -> Option<Stage> {
    let words = words(name);
    let has = |list: &[&str]| words.iter().any(|w| list.contains(&w.as_str()));
    match (has(VERTEX_WORDS), has(FRAGMENT_WORDS)) {
        (true, false) => Some(Stage::Vertex),
        (false, true) => Some(Stage::Fragment),
        _ => None,
    }
}

/// The stage the built-ins say: `gl_Position` is written only by a vertex shader;
/// `gl_FragColor`, `gl_FragCoord`, `discard` and a float precision statement mark a fragment
/// shader (a vertex shader has a default float precision and rarely states one).
pub fn stage_from_text(text: &str) -> Option<Stage> {
    if text.contains("gl_Position") || text.contains("gl_VertexID") {
        return Some(Stage::Vertex);
    }
    let fragment = [
        "gl_FragColor",
        "gl_FragData",
        "gl_FragCoord",
        "gl_FragDepth",
        "discard",
    ];
    if fragment.iter().any(|w| text.contains(w)) || text.contains("precision") {
        return Some(Stage::Fragment);
    }
    if text.contains("attribute ") || text.contains("\nin ") {
        return Some(Stage::Vertex);
    }
    None
}

/// The key two shaders of one program share: the name without its stage words and the words
/// `shader`, `source`, `src`, `program`, `glsl` (`skyboxVS` and `skyboxFS` → `skybox`).
pub fn pair_key(name: &str) -> String {
    let noise = [
        "shader", "source", "src", "program", "glsl", "code", "text", "script",
    ];
    words(name)
        .into_iter()
        .filter(|w| {
            !VERTEX_WORDS.contains(&w.as_str())
                && !FRAGMENT_WORDS.contains(&w.as_str())
                && !noise.contains(&w.as_str())
        })
        .collect::<Vec<_>>()
        .join("-")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names() {
        assert_eq!(stage_from_name("vs"), Some(Stage::Vertex));
        assert_eq!(stage_from_name("skyboxFS"), Some(Stage::Fragment));
        assert_eq!(stage_from_name("vertexShaderSource"), Some(Stage::Vertex));
        assert_eq!(stage_from_name("fragment-shader-3d"), Some(Stage::Fragment));
        assert_eq!(stage_from_name("shader"), None);
        assert_eq!(stage_from_name("FS300"), Some(Stage::Fragment));
        assert_eq!(stage_from_name("vec3Shader"), None);
        assert_eq!(pair_key("skyboxVS"), pair_key("skyboxFS"));
        assert_eq!(pair_key("vertex-shader-3d"), "3d");
        assert_eq!(pair_key("fragmentShaderSource"), "");
    }

    #[test]
    fn chunk() {
        assert!(chunk_pragma("float f();\n  # pragma  essl chunk\n"));
        assert!(!chunk_pragma("// chunk\n#pragma essl chunky\n"));
    }

    #[test]
    fn pragma() {
        let text = "#version 300 es\n  # pragma essl stage( fragment )\n";
        assert_eq!(stage_pragma(text), Some(Stage::Fragment));
        assert_eq!(stage_pragma("#pragma essl stage(geometry)\n"), None);
    }
}
