//! Shaders in an HTML page: `<script type="x-shader/x-vertex">` and `x-shader/x-fragment`
//! tags, `<script type="notjs">` tags whose id ends in `vertex-shader` or `fragment-shader`
//! (the webgl-fundamentals convention), and template literals in the page's inline scripts.

use essl::Stage;

use super::{js, Embedded, Imports, Piece};

/// The shaders in `page`, in the order they appear.
pub fn extract(page: &str, imports: &dyn Imports) -> Vec<Embedded> {
    let lower = page.to_ascii_lowercase();
    let mut found = Vec::new();
    let mut at = 0;
    while let Some(n) = next_script(&lower, at) {
        let open = n;
        let Some(tag_end) = lower[open..].find('>').map(|k| open + k + 1) else {
            break;
        };
        let body_end = lower[tag_end..]
            .find("</script")
            .map_or(page.len(), |k| tag_end + k);
        let attrs = attributes(&page[open + "<script".len()..tag_end - 1]);
        let get = |name: &str| {
            attrs
                .iter()
                .find(|(n, _)| n.eq_ignore_ascii_case(name))
                .map(|(_, v)| v.as_str())
        };
        let kind = get("type").unwrap_or("").trim().to_ascii_lowercase();
        let id = get("id").map(str::to_string);
        let stage = match kind.as_str() {
            "x-shader/x-vertex" => Some(Some(Stage::Vertex)),
            "x-shader/x-fragment" => Some(Some(Stage::Fragment)),
            "notjs" | "text/notjs" => {
                let id = id.as_deref().unwrap_or("").to_ascii_lowercase();
                if id.ends_with("vertex-shader") {
                    Some(Some(Stage::Vertex))
                } else if id.ends_with("fragment-shader") {
                    Some(Some(Stage::Fragment))
                } else if id.contains("shader") {
                    Some(None)
                } else {
                    None
                }
            }
            "" | "text/javascript" | "module" | "application/javascript" => {
                found.extend(js::extract(&page[tag_end..body_end], tag_end, imports));
                None
            }
            _ => None,
        };
        if let Some(stage) = stage {
            found.push(Embedded {
                range: tag_end..body_end,
                pieces: vec![Piece::Raw(tag_end..body_end)],
                chunk: false,
                literal: tag_end,
                defines: Vec::new(),
                stage,
                name: id,
                skip: None,
            });
        }
        at = body_end;
    }
    found
}

/// The start of the next `<script` tag at or after `at`, skipping `<!-- … -->` comments.
fn next_script(lower: &str, mut at: usize) -> Option<usize> {
    loop {
        let script = lower[at..].find("<script").map(|k| at + k)?;
        match lower[at..script].find("<!--").map(|k| at + k) {
            Some(comment) => {
                at = lower[comment..]
                    .find("-->")
                    .map_or(lower.len(), |k| comment + k + 3);
            }
            None => {
                let after = lower.as_bytes().get(script + "<script".len());
                if after.is_some_and(|c| c.is_ascii_whitespace() || *c == b'>') {
                    return Some(script);
                }
                at = script + 1;
            }
        }
    }
}

/// A tag's attributes as `(name, value)` pairs (quoted or bare values; a name alone has an
/// empty value).
fn attributes(tag: &str) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut rest = tag.trim_start();
    while !rest.is_empty() {
        let name_end = rest
            .find(|c: char| c.is_whitespace() || c == '=' || c == '/')
            .unwrap_or(rest.len());
        let name = &rest[..name_end];
        rest = rest[name_end..].trim_start();
        let mut value = String::new();
        if let Some(after) = rest.strip_prefix('=') {
            let after = after.trim_start();
            let (v, next) = match after.chars().next() {
                Some(q @ ('"' | '\'')) => {
                    let end = after[1..].find(q).map_or(after.len(), |k| k + 1);
                    (&after[1..end], &after[(end + 1).min(after.len())..])
                }
                _ => {
                    let end = after.find(char::is_whitespace).unwrap_or(after.len());
                    (&after[..end], &after[end..])
                }
            };
            value = v.to_string();
            rest = next;
        } else if name.is_empty() {
            rest = &rest[1.min(rest.len())..];
        }
        if !name.is_empty() {
            out.push((name.to_string(), value));
        }
        rest = rest.trim_start();
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shader_tags_notjs_tags_and_inline_scripts() {
        let page = "<!-- <script type=\"x-shader/x-vertex\">no</script> -->\n\
            <script id=\"vs\" type=\"x-shader/x-vertex\">#version 300 es\nvoid main() {}</script>\n\
            <SCRIPT type='notjs' id=\"3d-fragment-shader\">#version 300 es\n</SCRIPT>\n\
            <script src=\"a.js\"></script>\n\
            <script>\nconst vs = `#version 300 es\nvoid main() {}`;\n</script>\n";
        let found = extract(page, &super::super::NoImports);
        assert_eq!(found.len(), 3, "{found:?}");
        assert_eq!(
            &page[found[0].range.clone()],
            "#version 300 es\nvoid main() {}"
        );
        assert_eq!(found[0].stage, Some(Stage::Vertex));
        assert_eq!(found[0].name.as_deref(), Some("vs"));
        assert_eq!(found[1].stage, Some(Stage::Fragment));
        assert_eq!(
            &page[found[2].range.clone()],
            "#version 300 es\nvoid main() {}"
        );
        assert_eq!(found[2].name.as_deref(), Some("vs"));
    }

    #[test]
    fn attributes_quoted_and_bare() {
        assert_eq!(
            attributes(" id=a type = \"x y\" defer data-x='1'"),
            [
                ("id".into(), "a".into()),
                ("type".into(), "x y".into()),
                ("defer".into(), String::new()),
                ("data-x".into(), "1".into())
            ]
        );
    }
}
