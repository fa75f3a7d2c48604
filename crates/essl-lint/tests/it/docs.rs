//! `docs/lints/<id>.md` is each rule's page ([`essl_lint::Rule::page`]), and
//! `docs/lints/README.md` lists every rule. `ESSL_LINT_BLESS=1 cargo test -p essl-lint --test it docs::`
//! rewrites the pages from the rules' text.

use std::path::Path;

#[test]
fn rule_pages_are_up_to_date() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/lints");
    let bless = std::env::var_os("ESSL_LINT_BLESS").is_some();
    let mut stale = Vec::new();
    for r in essl_lint::RULES {
        let path = dir.join(format!("{}.md", r.id));
        let page = r.page();
        if bless {
            std::fs::create_dir_all(&dir).expect("docs/lints is writable");
            std::fs::write(&path, &page).expect("a writable page");
        } else if std::fs::read_to_string(&path).ok().as_deref() != Some(page.as_str()) {
            stale.push(path.display().to_string());
        }
    }
    assert!(
        stale.is_empty(),
        "stale rule pages (run with ESSL_LINT_BLESS=1): {stale:?}"
    );
}

#[test]
fn the_index_lists_every_rule() {
    let index = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/lints/README.md"),
    )
    .expect("docs/lints/README.md");
    for r in essl_lint::RULES {
        assert!(
            index.contains(&format!("[`{}`]({}.md)", r.id, r.id)),
            "README.md lists {}",
            r.id
        );
    }
}
