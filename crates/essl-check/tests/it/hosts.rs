//! Shaders inside host files: found, placed on the host's lines, paired, and sharing one copy
//! of the host's text however many there are.

use std::sync::Arc;

use essl_check::{CheckOptions, Overrides};

use crate::{check, lines, write};

#[test]
fn a_page_of_many_shaders_shares_its_text_and_pairs_by_name() {
    let dir = tempfile::tempdir().unwrap();
    let mut page = String::new();
    for i in 0..500 {
        page.push_str(&format!(
            "<script id=\"s{i}-vertex-shader\" type=\"x-shader/x-vertex\">#version 300 es\nin vec4 p;\nvoid main() {{ gl_Position = p; }}\n</script>\n\
             <script id=\"s{i}-fragment-shader\" type=\"x-shader/x-fragment\">#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() {{ c = vec4({i}.0); }}\n</script>\n"
        ));
    }
    // One broken shader, to see where its error lands.
    page.push_str("<script id=\"bad-fragment-shader\" type=\"x-shader/x-fragment\">#version 300 es\nvoid main() { x = 1; }\n</script>\n");
    write(dir.path(), &[("page.html", &page)]);
    let run = check(dir.path(), Overrides::default(), CheckOptions::default());
    let unit = &run.results[0];
    assert_eq!(unit.shaders.len(), 1001);
    assert_eq!(unit.programs.len(), 500);
    let first = unit.shaders[0].file();
    assert!(unit.shaders.iter().all(|s| Arc::ptr_eq(s.file(), first)));
    let line = page.lines().count() - 1;
    assert_eq!(
        lines(dir.path(), &run),
        [format!("page.html:{line}:15 undeclared-identifier")]
    );
    assert_eq!(
        unit.shaders[1000].label(),
        format!("{}:{}", dir.path().join("page.html").display(), line - 1)
    );
}

#[test]
fn a_js_file_and_a_shader_file_in_one_run() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        &[
            ("app.js", "const fs = `#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() { c = vec4(1) }`;\n"),
            ("a.vert", "#version 300 es\nvoid main() { gl_Position = vec4(0); }\n"),
        ],
    );
    let run = check(dir.path(), Overrides::default(), CheckOptions::default());
    assert_eq!(lines(dir.path(), &run), ["app.js:4:26 missing-semicolon"]);
}
