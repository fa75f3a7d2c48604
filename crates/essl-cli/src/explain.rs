//! `essl explain CODE`: the documentation of a diagnostic code — a front-end code of
//! [`essl::diagnostic_code::Code`] (its doc comment), a code of the checking pipeline
//! ([`essl_check::CheckCode`]: includes, presets) or a lint rule of essl-lint (its page).

use essl::diagnostic_code::Code;

/// The page `essl explain` prints for `code`, or `None` when essl has no such code.
pub fn page(code: &str) -> Option<String> {
    if let Some(c) = Code::from_name(code) {
        return Some(format!(
            "# {c}\n\nA diagnostic of essl's front end (GLSL ES and WebGL's rules).\n\n{}",
            c.doc()
        ));
    }
    if let Some(c) = essl_check::CheckCode::from_name(code) {
        return Some(format!(
            "# {code}\n\nA diagnostic of essl's checking pipeline (what surrounds a shader: \
             includes, presets).\n\n{}",
            c.doc()
        ));
    }
    essl_lint::rule(code).map(|r| format!("{}\n", r.page().trim_end()))
}

/// Every code `essl explain` knows: the front end's, the pipeline's, then the lint rules'.
pub fn codes() -> Vec<&'static str> {
    Code::ALL
        .iter()
        .map(|c| c.as_str())
        .chain(essl_check::CheckCode::ALL.iter().map(|c| c.as_str()))
        .chain(essl_lint::RULES.iter().map(|r| r.id))
        .collect()
}

/// Prints the page of `code` (or, with `None`, every code and its first line); returns the
/// exit status: 0, or 2 for a code essl does not have.
pub fn run(code: Option<&str>) -> i32 {
    let Some(code) = code else {
        for c in codes() {
            let page = page(c).unwrap_or_default();
            let first = page
                .lines()
                .skip(1)
                .find(|l| !l.trim().is_empty() && !l.starts_with("A diagnostic of essl"))
                .unwrap_or("");
            println!("{c:<40} {first}");
        }
        return 0;
    };
    match page(code) {
        Some(p) => {
            print!("{p}");
            0
        }
        None => {
            eprintln!(
                "error: `{code}` is not a diagnostic code of essl (`essl explain` lists them, \
                 `essl rules` the lint rules)"
            );
            2
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_code_has_a_page() {
        for c in codes() {
            let p = page(c).unwrap_or_default();
            assert!(p.starts_with(&format!("# {c}\n")), "{c}: {p}");
            assert!(p.lines().count() >= 3, "{c} has a page with no text: {p}");
        }
        assert!(page("no-such-code").is_none());
    }
}
