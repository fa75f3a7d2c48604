//! Measures how deep a nesting the front end survives on a small stack (development aid).
fn main() {
    let kind = std::env::args().nth(1).unwrap();
    let n: usize = std::env::args().nth(2).unwrap().parse().unwrap();
    let src = match kind.as_str() {
        "parens" => format!(
            "#version 300 es\nvoid main() {{ gl_Position = vec4({}1.0{}); }}\n",
            "(".repeat(n),
            ")".repeat(n)
        ),
        "blocks" => format!(
            "#version 300 es\nvoid main() {{ {} gl_Position = vec4(0.0); {} }}\n",
            "{".repeat(n),
            "}".repeat(n)
        ),
        "sum" => format!(
            "#version 300 es\nvoid main() {{ float x = 1.0{}; gl_Position = vec4(x); }}\n",
            " + 1.0".repeat(n)
        ),
        "ifs" => format!(
            "#version 300 es\nuniform bool b;\nvoid main() {{ {} gl_Position = vec4(0.0); }}\n",
            "if (b) ".repeat(n)
        ),
        "calls" => format!(
            "#version 300 es\nvoid main() {{ gl_Position = vec4({}1.0{}); }}\n",
            "abs(".repeat(n),
            ")".repeat(n)
        ),
        _ => panic!(),
    };
    let h = std::thread::Builder::new()
        .stack_size(2 << 20)
        .spawn(move || {
            let sh = essl::compile(
                essl::source::SourceFile::new("x", src),
                essl::Stage::Vertex,
                &Default::default(),
            );
            (sh.ok(), sh.error_count())
        })
        .unwrap();
    println!("{kind} {n}: {:?}", h.join());
}
