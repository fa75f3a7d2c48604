use essl::*;
fn main() {
    let path = std::env::args().nth(1).unwrap();
    let mut pass_bad = 0; let mut pass_total = 0; let mut fail_total=0; let mut fail_rej=0;
    for line in std::fs::read_to_string(&path).unwrap().lines() {
        let v: serde_json::Value = serde_json::from_str(line).unwrap();
        let expect = v["expect"].as_str().or(v["outcome"].as_str()).unwrap_or("pass");
        for (key, stage) in [("vertex_source", Stage::Vertex), ("fragment_source", Stage::Fragment)] {
            let Some(src) = v[key].as_str() else { continue };
            let src: String = src.lines().map(|l| if l.trim_start().starts_with('#') { "" } else { l }).collect::<Vec<_>>().join("\n");
            let f = source::SourceFile::new("x", src);
            let lexed = lex::lex(&f);
            let pp = preprocess::preprocess(&f, lexed, &Default::default());
            let mut d = pp.diagnostics;
            let toks = token::classify(pp.tokens, &mut d);
            let (_u, pd) = parse::parse(&f, toks, stage);
            d.extend(pd);
            let errs: Vec<_> = d.iter().filter(|d| d.is_error()).collect();
            if expect == "pass" || expect == "must_pass" || expect=="build_successful" {
                pass_total += 1;
                if !errs.is_empty() { pass_bad += 1; if pass_bad < 15 { let lc = f.line_col(errs[0].span.start); println!("{} {}: {}:{} {}", v["name"].as_str().or(v["file"].as_str()).unwrap_or(""), key, lc.line, lc.column, errs[0].message); } }
            } else { fail_total+=1; if !errs.is_empty() {fail_rej+=1;} }
        }
    }
    println!("pass shaders with syntax errors: {pass_bad}/{pass_total}; fail shaders rejected by syntax: {fail_rej}/{fail_total}");
}
