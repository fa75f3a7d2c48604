//! `essl rules`: the lint rules and their documentation.

/// Prints the rule table, or one rule's documentation; returns the exit status.
pub fn run(rule: Option<&str>) -> i32 {
    match rule {
        None => {
            for r in essl_lint::RULES {
                println!("{:<24} {:<5} {}", r.id, r.default_level.as_str(), r.summary);
            }
            0
        }
        Some(id) => match essl_lint::rule(id) {
            Some(r) => {
                println!("{}", r.doc);
                0
            }
            None => {
                eprintln!("error: {}", essl_lint::UnknownRule(id.to_string()));
                2
            }
        },
    }
}
