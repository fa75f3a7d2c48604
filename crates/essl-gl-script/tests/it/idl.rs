//! WebGL2's IDL (`../shared/specs/webgl{1,2}.idl`) against essl-gl: every method of
//! `WebGL2RenderingContext` is one a script can call (`essl_gl_script::call` knows it by name)
//! and has its row in `docs/api.md`, and every constant has the IDL's value in `essl_gl::gl`.

use std::collections::BTreeMap;
use std::path::Path;

use essl_gl_script::{call, CallError};

/// The mixins `WebGL2RenderingContext` includes, by file.
const MIXINS: &[(&str, &[&str])] = &[
    (
        "webgl1.idl",
        &[
            "WebGLRenderingContextBase",
            "WebGLRenderingContextOverloads",
        ],
    ),
    (
        "webgl2.idl",
        &[
            "WebGL2RenderingContextBase",
            "WebGL2RenderingContextOverloads",
        ],
    ),
];

/// The IDL's methods and constants (name → value) of WebGL2's context.
struct Idl {
    methods: Vec<String>,
    constants: BTreeMap<String, i64>,
}

/// The text between `interface mixin NAME` and its closing `};`, without comments.
fn mixin_body(text: &str, name: &str) -> String {
    let start = text
        .find(&format!("interface mixin {name}"))
        .unwrap_or_else(|| panic!("no mixin {name}"));
    let end = start + text[start..].find("\n};").expect("a closed mixin");
    let mut body = String::new();
    let mut rest = &text[start..end];
    while let Some(i) = rest.find("/*") {
        body.push_str(&rest[..i]);
        rest = rest[i..].find("*/").map_or("", |j| &rest[i + j + 2..]);
    }
    body.push_str(rest);
    body.lines()
        .map(|l| l.split("//").next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n")
}

fn read_idl(dir: &Path) -> Idl {
    let mut methods = Vec::new();
    let mut constants = BTreeMap::new();
    for (file, mixins) in MIXINS {
        let text = std::fs::read_to_string(dir.join(file)).unwrap();
        for mixin in *mixins {
            for statement in mixin_body(&text, mixin).split(';') {
                let words: Vec<&str> = statement.split_whitespace().collect();
                if words.first() == Some(&"const") {
                    // const TYPE NAME = VALUE
                    let (name, value) = (words[2], words[4]);
                    let value = match value.strip_prefix("0x") {
                        Some(hex) => i64::from_str_radix(hex, 16).unwrap(),
                        None => value.parse().unwrap(),
                    };
                    constants.insert(name.to_string(), value);
                } else if words.contains(&"attribute") {
                    continue;
                } else if let Some(open) = statement.find('(') {
                    let name = statement[..open].split_whitespace().last().unwrap_or("");
                    if !name.is_empty() && !methods.iter().any(|m| m == name) {
                        methods.push(name.to_string());
                    }
                }
            }
        }
    }
    methods.sort();
    Idl { methods, constants }
}

fn idl() -> Option<Idl> {
    let dir = essl_testdata::specs()?;
    Some(read_idl(&dir))
}

#[test]
fn every_constant_has_the_idls_value() {
    let Some(idl) = idl() else { return };
    assert!(
        idl.constants.len() > 500,
        "{} constants",
        idl.constants.len()
    );
    let wrong: Vec<String> = idl
        .constants
        .iter()
        .filter(|&(name, &value)| essl_gl::gl::by_name(name) != Some(value))
        .map(|(name, value)| {
            format!(
                "{name}: IDL {value:#x}, essl_gl {:?}",
                essl_gl::gl::by_name(name)
            )
        })
        .collect();
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn every_method_has_a_row_in_the_api_page() {
    let Some(idl) = idl() else { return };
    assert_eq!(idl.methods.len(), 225, "WebGL2RenderingContext's methods");
    let page = std::fs::read_to_string(essl_testdata::repo_root().join("docs/api.md")).unwrap();
    let missing: Vec<&String> = idl
        .methods
        .iter()
        .filter(|m| !page.contains(&format!("| `{m}` |")))
        .collect();
    assert!(missing.is_empty(), "not in docs/api.md: {missing:?}");
}

#[test]
fn every_method_can_be_called_by_name() {
    let Some(idl) = idl() else { return };
    let Some(mut ctx) = essl_testdata::with_adapter(|| essl_gl::Context::new(1, 1)) else {
        return;
    };
    // Without arguments a method runs (`finish`, `createBuffer`), throws a TypeError for the
    // first one missing, or takes the overload a script cannot express; only a name it does
    // not know answers UnknownMethod.
    let unknown: Vec<String> = idl
        .methods
        .iter()
        .filter_map(|m| match call(&mut ctx, m, &mut []) {
            Err(e @ CallError::UnknownMethod(_)) => Some(e.to_string()),
            _ => None,
        })
        .collect();
    assert!(matches!(
        call(&mut ctx, "texImage4D", &mut []),
        Err(CallError::UnknownMethod(_))
    ));
    assert!(unknown.is_empty(), "{}", unknown.join("\n"));
}
