//! Writing Rust source text: indentation and string literals.

/// `text` with every non-empty line indented by four more spaces.
pub(super) fn indent(text: &str) -> String {
    text.lines()
        .map(|l| {
            if l.is_empty() {
                "\n".to_string()
            } else {
                format!("    {l}\n")
            }
        })
        .collect()
}

/// A raw string literal of `text` (`r#"…"#` with as many `#` as it needs), for shader text
/// that stays readable in the generated file.
pub(super) fn raw_string_literal(text: &str) -> String {
    // Rust refuses a bare carriage return in a raw string.
    if text.contains('\r') {
        return string_literal(text);
    }
    let mut hashes = String::new();
    while text.contains(&format!("\"{hashes}")) {
        hashes.push('#');
    }
    format!("r{hashes}\"{text}\"{hashes}")
}

/// A Rust string literal of `text`.
pub(super) fn string_literal(text: &str) -> String {
    format!("{text:?}")
}
