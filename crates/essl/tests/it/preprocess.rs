//! The preprocessor against dEQP's and WebGL's conformance cases, and rule by rule.

use essl::diagnostic::{Applicability, Diagnostic, Severity};
use essl::passes::{lex, PpKind};
use essl::passes::{preprocess, ExtensionBehavior, PreprocessOptions, Preprocessed};
use essl::source::SourceFile;
use essl::Stage;
use essl::Version;

// ---------------------------------------------------------------------------------------------
// Helpers

fn run_with(src: &str, options: &PreprocessOptions) -> (SourceFile, Preprocessed) {
    let f = SourceFile::new("t.frag", src);
    let lexed = lex(&f);
    let p = preprocess(&f, lexed, options);
    (f, p)
}

fn run(src: &str) -> (SourceFile, Preprocessed) {
    run_with(src, &PreprocessOptions::default())
}

/// A shader with `#version 300 es` on line 1.
fn v(body: &str) -> String {
    format!("#version 300 es\n{body}")
}

/// The output tokens' texts, without `Eof`.
fn texts(p: &Preprocessed) -> Vec<String> {
    p.tokens
        .iter()
        .filter(|t| t.kind != PpKind::Eof)
        .map(|t| t.text.to_string())
        .collect()
}

/// The output as one string, tokens separated by single spaces.
fn out(src: &str) -> String {
    let (_, p) = run(&v(src));
    let errs = errors(&p);
    assert!(errs.is_empty(), "unexpected errors for {src:?}: {errs:?}");
    texts(&p).join(" ")
}

fn errors(p: &Preprocessed) -> Vec<&'static str> {
    p.diagnostics
        .iter()
        .filter(|d| d.is_error())
        .map(|d| d.code)
        .collect()
}

fn warnings(p: &Preprocessed) -> Vec<&'static str> {
    p.diagnostics
        .iter()
        .filter(|d| d.severity == Severity::Warning)
        .map(|d| d.code)
        .collect()
}

/// The only error of a shader (body after `#version 300 es`), which must have `code`.
fn the_error(body: &str, code: &str) -> (SourceFile, Diagnostic) {
    let (f, p) = run(&v(body));
    let errs: Vec<&Diagnostic> = p.diagnostics.iter().filter(|d| d.is_error()).collect();
    assert_eq!(
        errs.iter().map(|d| d.code).collect::<Vec<_>>(),
        vec![code],
        "errors of {body:?}: {errs:#?}"
    );
    let d = errs[0].clone();
    (f, d)
}

/// The text a diagnostic's primary span covers.
fn at(f: &SourceFile, d: &Diagnostic) -> String {
    f.slice(d.span).to_string()
}

// ---------------------------------------------------------------------------------------------
// Corpora

fn corpus(name: &str) -> Option<Vec<serde_json::Value>> {
    let path = essl_testdata::corpus_file(name)?;
    let text = std::fs::read_to_string(&path).expect("the corpus file reads");
    Some(
        text.lines()
            .filter(|l| !l.trim().is_empty())
            .map(|l| serde_json::from_str(l).expect("valid JSON line"))
            .collect(),
    )
}

/// Error diagnostics of one shader source.
fn shader_errors(src: &str, stage: Stage) -> Vec<Diagnostic> {
    let options = PreprocessOptions {
        stage: Some(stage),
        ..Default::default()
    };
    let (_, p) = run_with(src, &options);
    p.diagnostics.into_iter().filter(|d| d.is_error()).collect()
}

#[test]
fn deqp_preprocessor_cases() {
    let Some(rows) = corpus("deqp_gles3.jsonl") else {
        return;
    };
    let mut pass = 0;
    let mut pass_bad = Vec::new();
    let mut fail = 0;
    let mut rejected = 0;
    let mut not_rejected = Vec::new();
    for row in rows.iter().filter(|r| {
        r["file"]
            .as_str()
            .unwrap_or("")
            .ends_with("preprocessor.test")
    }) {
        let name = row["name"].as_str().unwrap_or("?");
        let expect = row["expect"].as_str().unwrap_or("?");
        let mut errs = Vec::new();
        for (key, stage) in [
            ("vertex_source", Stage::Vertex),
            ("fragment_source", Stage::Fragment),
        ] {
            if let Some(src) = row[key].as_str() {
                errs.extend(
                    shader_errors(src, stage)
                        .into_iter()
                        .map(|d| format!("{key}: {} {}", d.code, d.message)),
                );
            }
        }
        match expect {
            "pass" | "build_successful" => {
                pass += 1;
                if !errs.is_empty() {
                    pass_bad.push(format!("{name}: {errs:?}"));
                }
            }
            "compile_fail" => {
                fail += 1;
                if errs.is_empty() {
                    not_rejected.push(name.to_string());
                } else {
                    rejected += 1;
                }
            }
            _ => {}
        }
    }
    println!(
        "dEQP preprocessor.test: pass cases clean {}/{pass}",
        pass - pass_bad.len()
    );
    println!(
        "dEQP preprocessor.test: compile_fail cases rejected by the preprocessor {rejected}/{fail}"
    );
    for n in &not_rejected {
        println!("  not rejected (later stages' job): {n}");
    }
    assert!(pass > 0, "no preprocessor.test cases found");
    assert!(
        pass_bad.is_empty(),
        "pass cases with preprocessor errors:\n{}",
        pass_bad.join("\n")
    );
}

#[test]
fn webgl_conformance_preprocessor_cases() {
    let Some(rows) = corpus("webgl_conformance_es300.jsonl") else {
        return;
    };
    let re = [
        "preprocess",
        "macro",
        "version",
        "line",
        "extension",
        "pragma",
        "invariant",
        "define",
    ];
    let mut must_pass_bad = Vec::new();
    let (mut fails, mut rejected) = (0, 0);
    for row in &rows {
        let file = row["file"].as_str().unwrap_or("");
        let vs = row["vertex_source"].as_str().unwrap_or("");
        let fs = row["fragment_source"].as_str().unwrap_or("");
        let mentions = re.iter().any(|w| file.contains(w))
            || [vs, fs].iter().any(|s| {
                s.contains("#define")
                    || s.contains("#extension")
                    || s.contains("#pragma")
                    || s.contains("#line")
            });
        if !mentions {
            continue;
        }
        let errs: Vec<String> = shader_errors(vs, Stage::Vertex)
            .into_iter()
            .chain(shader_errors(fs, Stage::Fragment))
            .map(|d| format!("{} {}", d.code, d.message))
            .collect();
        let id = format!("{}#{}", file, row["index"]);
        match row["outcome"].as_str() {
            Some("must_pass") if !errs.is_empty() => must_pass_bad.push(format!("{id}: {errs:?}")),
            Some("must_fail") => {
                fails += 1;
                if errs.is_empty() {
                    println!("  not rejected by the preprocessor: {id}");
                } else {
                    rejected += 1;
                }
            }
            _ => {}
        }
    }
    println!("WebGL conformance (preprocessor-related): must_fail rejected {rejected}/{fails}");
    assert!(must_pass_bad.is_empty(), "{}", must_pass_bad.join("\n"));
}

// ---------------------------------------------------------------------------------------------
// Macro expansion

#[test]
fn object_and_function_like_macros_expand() {
    assert_eq!(out("#define A 1.0\nfloat x = A;"), "float x = 1.0 ;");
    assert_eq!(
        out("#define F(a, b) (a - b)\nfloat x = F(3.0, 2.0);"),
        "float x = ( 3.0 - 2.0 ) ;"
    );
    assert_eq!(out("#define E\nE x E;"), "x ;");
    assert_eq!(out("#define F(a)\nF(1) x;"), "x ;");
    assert_eq!(out("#define Z() 7\nZ() Z( );"), "7 7 ;");
    assert_eq!(
        out("#define FOO(a, b) (1 a 9) b 2\nFOO(+, *)"),
        "( 1 + 9 ) * 2"
    );
}

#[test]
fn expanded_tokens_carry_the_invocation_span() {
    let src = v("#define A (1.0 + x)\n#define F(a, b) a * b\nA; F(y,\n  2.0);");
    let (f, p) = run(&src);
    assert!(errors(&p).is_empty());
    let toks: Vec<_> = p.tokens.iter().filter(|t| t.kind != PpKind::Eof).collect();
    // `A` expands to five tokens with A's span.
    for t in &toks[..5] {
        assert!(t.from_macro);
        assert_eq!(f.slice(t.span), "A");
    }
    assert_eq!(&*toks[5].text, ";");
    assert!(!toks[5].from_macro);
    // Function-like: the replacement list's tokens span the whole call, across lines; the
    // arguments' tokens where they are written.
    assert!(toks[6..9].iter().all(|t| t.from_macro));
    assert_eq!(
        toks[6..9]
            .iter()
            .map(|t| f.slice(t.span))
            .collect::<Vec<_>>(),
        ["y", "F(y,\n  2.0)", "2.0"]
    );
    assert_eq!(
        toks[6..9].iter().map(|t| &*t.text).collect::<Vec<_>>(),
        ["y", "*", "2.0"]
    );
}

#[test]
fn an_argument_from_another_expansion_takes_that_invocation_span() {
    // `x` is written in `A`'s replacement list, `v` in the text, `B` is expanded in `F`'s
    // argument.
    let src = v("#define B 2.0\n#define F(a) (a)\n#define A(x) F(x + 1.0)\nA(v); F(B);");
    let (f, p) = run(&src);
    assert!(errors(&p).is_empty());
    let spans: Vec<_> = p
        .tokens
        .iter()
        .filter(|t| t.kind != PpKind::Eof)
        .map(|t| (&*t.text, f.slice(t.span)))
        .collect();
    assert_eq!(
        spans,
        [
            ("(", "A(v)"),
            ("v", "v"),
            ("+", "A(v)"),
            ("1.0", "A(v)"),
            (")", "A(v)"),
            (";", ";"),
            ("(", "F(B)"),
            ("2.0", "B"),
            (")", "F(B)"),
            (";", ";"),
        ]
    );
}

#[test]
fn nested_expansions_take_the_outermost_span() {
    let src = v("#define B 2.0\n#define A (B)\nA");
    let (f, p) = run(&src);
    assert_eq!(texts(&p), ["(", "2.0", ")"]);
    assert!(p.tokens[..3]
        .iter()
        .all(|t| f.slice(t.span) == "A" && t.from_macro));
}

#[test]
fn function_like_name_without_parenthesis_is_an_identifier() {
    assert_eq!(
        out("#define F(x) x\nfloat F; F + F(2);"),
        "float F ; F + 2 ;"
    );
    // The parenthesis may come on a later line.
    assert_eq!(out("#define F(x) [x]\nF\n\n(1)"), "[ 1 ]");
}

#[test]
fn arguments_span_lines_and_nest() {
    assert_eq!(
        out("#define F(a, b) a|b\nF((1, 2),\n (3, (4)))"),
        "( 1 , 2 ) | ( 3 , ( 4 ) )"
    );
    // Brackets do not group: only parentheses do.
    the_error("#define F(a, b) a|b\nF(x[1, 2], y)", "macro-argument-count");
}

#[test]
fn arguments_are_expanded_first_and_rescanned() {
    // dEQP function_definitions.complex_func.
    let got = out(
        "#define AAA(a,b) a*(BBB(a,b))\n#define BBB(a,b) a-b\nBBB(AAA(8.0/4.0, 2.0)*BBB(2.0*2.0,0.75*2.0), AAA(40.0,10.0*BBB(5.0,3.0)))",
    );
    assert_eq!(
        got,
        "8.0 / 4.0 * ( 8.0 / 4.0 - 2.0 ) * 2.0 * 2.0 - 0.75 * 2.0 - 40.0 * ( 40.0 - 10.0 * 5.0 - 3.0 )"
    );
    // semantic.correct_order: the argument `A` expands before substitution.
    assert_eq!(
        out("#define FUNC(A) A\n#define A 2.0\nFUNC(A - 1.0)"),
        "2.0 - 1.0"
    );
    // A parameter shadows a macro of the same name.
    assert_eq!(
        out("#define VALUE 1.0\n#define F(VALUE, B) (VALUE-B)\nF(3.0, 2.0)"),
        "( 3.0 - 2.0 )"
    );
}

#[test]
fn a_macro_is_not_expanded_inside_its_own_expansion() {
    assert_eq!(out("#define AAA AAA\nAAA"), "AAA");
    assert_eq!(out("#define AAA BBB\n#define BBB AAA\nAAA BBB"), "AAA BBB");
    assert_eq!(
        out("#define A (1.0+B)\n#define B (2.0+A)\nA"),
        "( 1.0 + ( 2.0 + A ) )"
    );
    assert_eq!(out("#define F(a) F(a)\nF(1.0)"), "F ( 1.0 )");
    assert_eq!(
        out("#define F(a, b) F(b, a)\nF(1.0, 2.0)"),
        "F ( 2.0 , 1.0 )"
    );
    // An argument may use the macro itself: it is expanded before the call is.
    assert_eq!(out("#define F(a) (a)\nF(F(1))"), "( ( 1 ) )");
}

#[test]
fn wrong_argument_count_is_an_error_at_the_call() {
    let (f, d) = the_error(
        "#define FUNC(a,b) a+b\nvec4(FUNC(1.0));",
        "macro-argument-count",
    );
    assert_eq!(at(&f, &d), "FUNC(1.0)");
    assert_eq!(d.message, "macro `FUNC` takes 2 arguments, but 1 was given");
    assert_eq!(d.token, "FUNC");
    assert_eq!(d.secondary.len(), 1);
    assert_eq!(f.slice(d.secondary[0].span), "FUNC");
    let (_, d) = the_error("#define FUNC(a,b) a+b\nFUNC()", "macro-argument-count");
    assert!(d.message.contains("1 was given"), "{}", d.message);
    the_error(
        "#define FUNC(a,b) a+b\nFUNC(1.0, 2.0, 3.0)",
        "macro-argument-count",
    );
    the_error("#define Z() 1\nZ(2)", "macro-argument-count");
    // An empty argument is an argument.
    assert_eq!(out("#define F(a,b) [a|b]\nF(1,)"), "[ 1 | ]");
}

#[test]
fn unterminated_call_is_an_error() {
    let (f, d) = the_error(
        "#define FUNC(a,b) a+b\nvoid main() { vec4(FUNC(((); }",
        "unterminated-macro-call",
    );
    assert_eq!(at(&f, &d), "(");
    assert_eq!(f.line_col(d.span.start).column, 24);
    assert_eq!(f.slice(d.secondary[0].span), "FUNC");
    // In an `#if` line the call ends with the line, and the line is not evaluated further.
    let (_, p) = run(&v("#define F(a) a\n#if F(1\n#endif"));
    assert_eq!(errors(&p), ["unterminated-macro-call"]);
}

#[test]
fn redefinition_must_be_identical() {
    // Identical (white space amount and comments do not matter, only its presence).
    assert!(errors(&run(&v("#define A 1\n#define A 1\n")).1).is_empty());
    assert!(errors(
        &run(&v(
            "#define F(a,b) (a  +b)\n#define F( a, b )(a\t/* c\n */ +b)\n"
        ))
        .1
    )
    .is_empty());
    let (f, d) = the_error(
        "# define VALUE (AAA - 1.0)\n# define VALUE (AAA- 1.0)\n",
        "macro-redefinition",
    );
    assert_eq!(at(&f, &d), "VALUE");
    assert_eq!(f.line_col(d.span.start).line, 3);
    assert_eq!(f.line_col(d.secondary[0].span.start).line, 2);
    for (a, b) in [
        ("(AAA - 1.0)", "(AAA - 1.1)"),
        ("(AAA - 1)", "(AAA - 0x1)"),
        ("(AAA - 1)", "(AAAA - 1)"),
    ] {
        the_error(
            &format!("#define V {a}\n#define V {b}\n"),
            "macro-redefinition",
        );
    }
    the_error(
        "#define F(a,b) a+b\n#define F(A,b) A+b\n",
        "macro-redefinition",
    );
    the_error(
        "#define F(a,b) a+b\n#define F(a,b,c) a+b+c\n",
        "macro-redefinition",
    );
    the_error(
        "#define F(a,b) a+b\n#define F(a,b) b+a\n",
        "macro-redefinition",
    );
    the_error("#define F(a) a\n#define F a\n", "macro-redefinition");
    // `#undef` first makes it fine.
    assert_eq!(
        out("#define F(a,b) a+b\n#undef F\n#define F(a,b) a-b\nF(3.0, 2.0)"),
        "3.0 - 2.0"
    );
}

#[test]
fn define_syntax_errors() {
    let (f, d) = the_error("#define\n", "missing-macro-name");
    assert_eq!(at(&f, &d), "#define");
    let (f, d) = the_error("#define 123 321\n", "invalid-macro-name");
    assert_eq!(at(&f, &d), "123");
    let (f, d) = the_error("# define FUNC(a,a) a+a\n", "duplicate-macro-parameter");
    assert_eq!(f.line_col(d.span.start).column, 17);
    let (f, d) = the_error("# define FUNC(a b) a+b\n", "invalid-macro-parameters");
    assert_eq!(at(&f, &d), "b");
    let (f, d) = the_error("# define FUNC(a + b) a+b\n", "invalid-macro-parameters");
    assert_eq!(at(&f, &d), "+");
    let (f, d) = the_error("# define FUNC(,a,b) a+b\n", "invalid-macro-parameters");
    assert_eq!(at(&f, &d), ",");
    let (f, d) = the_error("# define FUNC(\n", "unterminated-macro-parameters");
    assert_eq!(f.slice(d.secondary[0].span), "(");
    let (f, d) = the_error("# define FUNC(A  a+b\n", "invalid-macro-parameters");
    assert_eq!(at(&f, &d), "a");
    the_error("# define FUNC(A,B,C  a+b\n", "invalid-macro-parameters");
    the_error("# define FUNC(A,\n", "unterminated-macro-parameters");
    // A space before `(` makes an object-like macro.
    assert_eq!(out("#define F (x)\nF(1)"), "( x ) ( 1 )");
    // A failed definition defines nothing.
    let (_, p) = run(&v("#define F(a b) a\nF"));
    assert_eq!(texts(&p), ["F"]);
}

#[test]
fn undef_errors() {
    let (f, d) = the_error("#undef 123\n", "invalid-macro-name");
    assert_eq!(at(&f, &d), "123");
    let (f, d) = the_error("#undef foo.bar\n", "extra-tokens");
    assert_eq!(at(&f, &d), ".bar");
    let (f, d) = the_error("#define VAL 2.0\n#undef VAL sdflkjfds\n", "extra-tokens");
    assert_eq!(at(&f, &d), "sdflkjfds");
    let fix = d.fix.unwrap();
    assert_eq!(fix.applicability, Applicability::Certain);
    assert_eq!(fix.edits[0].replacement, "// ");
    // Undefining something undefined is fine.
    assert!(errors(&run(&v("#undef NOTHING\n")).1).is_empty());
}

#[test]
fn predefined_macros() {
    assert_eq!(
        out("__VERSION__ GL_ES GL_FRAGMENT_PRECISION_HIGH __FILE__"),
        "300 1 1 0"
    );
    assert_eq!(out("#define AAA __VERSION__\nAAA"), "300");
    assert_eq!(out("#define AAA(A) A\nAAA(GL_ES)"), "1");
    for name in [
        "__LINE__",
        "__FILE__",
        "__VERSION__",
        "GL_ES",
        "GL_FRAGMENT_PRECISION_HIGH",
    ] {
        let (f, d) = the_error(&format!("#undef {name}\n"), "predefined-macro-undefined");
        assert_eq!(at(&f, &d), name);
        let (f, d) = the_error(&format!("#define {name} 2\n"), "predefined-macro-redefined");
        assert_eq!(at(&f, &d), name);
        assert_eq!(d.token, name);
    }
}

#[test]
fn line_macro_follows_webgl() {
    // dEQP predefined_macros.line_1 and line_2: arguments are expanded where they are written;
    // the replacement list of a function-like macro is at its closing parenthesis.
    assert_eq!(
        out("const mediump int line = __LINE__;"),
        "const mediump int line = 2 ;"
    );
    let src = "precision mediump float;\nin highp vec4 dEQP_Position; out vec4 out0;\n#define BBB\t\t__LINE__, /*\n\t*/ __LINE__\n#define AAA(a,b) BBB, a, b\n\nvoid main()\n{\n\tout0 = vec4(AAA(__LINE__,\n\t\t__LINE__\n\t\t));\n}\n";
    let (_, p) = run(&v(src));
    assert!(errors(&p).is_empty());
    let t = texts(&p).join(" ");
    assert!(t.contains("vec4 ( 12 , 12 , 10 , 11 )"), "{t}");
}

#[test]
fn line_directive_renumbers() {
    let src = v("void main()\n{\n#line 234 10\n x = vec4(__LINE__, __LINE__, __FILE__, __FILE__);\n y = __LINE__;\n}\n");
    let (f, p) = run(&src);
    assert!(errors(&p).is_empty());
    let t = texts(&p).join(" ");
    assert!(t.contains("vec4 ( 234 , 234 , 10 , 10 )"), "{t}");
    assert!(t.contains("y = 235 ;"), "{t}");
    assert_eq!(p.line_directives.len(), 1);
    let ld = &p.line_directives[0];
    assert_eq!(f.slice(ld.span), "#line 234 10");
    assert_eq!((ld.line, ld.source, ld.source_string), (234, Some(10), 10));
    // WebGL-style positions after the directive.
    let y = src.find(" y =").unwrap() as u32 + 1;
    assert_eq!(p.presumed_line(&f, y), (10, 235));
    assert_eq!(p.presumed_line(&f, 0), (0, 1));
    // Expressions and macros; the source string number carries over.
    assert_eq!(
        out("#line (233 +10) (+10)\n__LINE__ __FILE__\n#line 5\n__LINE__ __FILE__"),
        "243 10 5 10"
    );
    assert_eq!(out("#define A 4\n#line A\n__LINE__"), "4");
    assert_eq!(out("#line +20\n__LINE__"), "20");
}

#[test]
fn line_directive_errors() {
    let (f, d) = the_error("#line\n", "invalid-line-directive");
    assert_eq!(at(&f, &d), "#line");
    let (f, d) = the_error("#line 22 1.234\n", "non-integer-in-expression");
    assert_eq!(at(&f, &d), "1.234");
    let (f, d) = the_error("#line 233 10 2\n", "extra-tokens");
    assert_eq!(at(&f, &d), "2");
    let (f, d) = the_error("#line foobar\n", "undefined-macro-in-if");
    assert_eq!(at(&f, &d), "foobar");
    the_error("#line 4294967295\n", "integer-overflow");
    the_error("#line 200 % 0\n", "division-by-zero");
    // A failed `#line` changes nothing.
    let (_, p) = run(&v("#line foo\n__LINE__"));
    assert_eq!(texts(&p), ["3"]);
}

// ---------------------------------------------------------------------------------------------
// Conditionals and `#if` expressions

/// Whether `#if expr` takes its group (no errors allowed).
fn holds(expr: &str) -> bool {
    let got = out(&format!("#if {expr}\nyes\n#else\nno\n#endif"));
    match got.as_str() {
        "yes" => true,
        "no" => false,
        other => panic!("{other}"),
    }
}

#[test]
fn if_expressions_evaluate_like_c() {
    for e in [
        "1",
        "-4 + 5 == 1",
        "(2 * 2) - 3 >= 0",
        "2 * 3 - 3 == 3",
        "2 - 2 / 2 == 1",
        "!((~2 >> 1) & 1)",
        "( 8 % ! 0 ) == 0",
        "( 8 / ! 0 ) == 8",
        "( 8 % ~ 4 ) == 3",
        "( 8 / ~ 2 ) == -2",
        "( 8 * ~ 2 ) == -24",
        "( 8 % - 2 ) == 0",
        "( 8 - 3 % 2 ) == 7",
        "( 8 >> 3 - 2 ) == 4",
        "( 8 << 3 + 2 ) == 256",
        "( 8 >= 3 >> 2 ) == 1",
        "( 8 <= 3 << 2 ) == 1",
        "( 8 != 3 >= 2 ) == 1",
        "( 8 == 3 < 2 ) == 0",
        "( 8 & 3 != 2 ) == 0",
        "( 8 ^ 3 & 2 ) == 10",
        "( 8 | 3 ^ 2 ) == 9",
        "!( 0 && 3 | 2 )",
        "!( 0 || 4 && 0 )",
        "0x10 == 16",
        "010 == 8",
        "3u == 3",
        "-1 >> 28 == 15",
        "4294967295 == -1",
        "2147483647 + 1 < 0",
        "(4)",
        "((((4)))) == 4",
        "!((~(- - - - - 1 + + + + + +1) >> 1) & 1) == 0",
        "__LINE__ == 2",
        "__VERSION__ == 300",
        "GL_ES",
        "defined GL_ES",
        "defined(GL_ES) && !defined(NOPE)",
        "defined ( __LINE__ )",
    ] {
        assert!(holds(e), "{e}");
    }
    for e in ["0", "1 - 1", "!GL_ES", "defined NOPE", "0 && 1"] {
        assert!(!holds(e), "{e}");
    }
}

#[test]
fn if_short_circuits_errors() {
    for e in [
        "1 || AAA",
        "0 && AAA",
        "0 && 1 / 0",
        "1 || 1 % 0",
        "0 && (1 << 40)",
        "1 || (0 && X) || Y",
    ] {
        holds(e);
    }
}

#[test]
fn undefined_identifier_in_if_is_an_error() {
    let (f, d) = the_error("#if 1 - CCC + 2\n#endif\n", "undefined-macro-in-if");
    assert_eq!(at(&f, &d), "CCC");
    assert_eq!(d.token, "CCC");
    let fix = d.fix.unwrap();
    assert_eq!(fix.applicability, Applicability::Suggested);
    assert_eq!(fix.edits[0].replacement, "defined(CCC)");
    for e in ["!A", "-A", "~A", "A && B", "A || B"] {
        let (_, p) = run(&v(&format!("#if {e}\n#endif\n")));
        assert!(
            errors(&p).iter().all(|c| *c == "undefined-macro-in-if") && !errors(&p).is_empty(),
            "{e}"
        );
    }
    // From a macro: the span is the macro's name in the `#if` line.
    let (f, d) = the_error("#define M X\n#if M\n#endif\n", "undefined-macro-in-if");
    assert_eq!(at(&f, &d), "M");
    // Undefined after `#undef`.
    the_error(
        "#define A 2\n#undef A\n#if A\n#endif\n",
        "undefined-macro-in-if",
    );
}

#[test]
fn if_expression_errors() {
    let cases: &[(&str, &str, &str)] = &[
        ("#if\n", "missing-expression", "#if"),
        ("#if 1.231\n", "non-integer-in-expression", "1.231"),
        ("#if 1 / 0\n", "division-by-zero", "0"),
        ("#if 1 % (2 - 2)\n", "division-by-zero", "(2 - 2)"),
        ("#if 1 << 32\n", "invalid-shift", "32"),
        ("#if 1 >> -1\n", "invalid-shift", "-1"),
        ("#if 4294967296\n", "integer-overflow", "4294967296"),
        ("#if 1 foobar\n", "extra-tokens", "foobar"),
        ("#if 4 4\n", "extra-tokens", "4"),
        ("#if (4)(4)\n", "extra-tokens", "(4)"),
        ("#if 4)\n", "extra-tokens", ")"),
        ("#if ((4 + 7)\n", "invalid-expression", ""),
        ("#if !\n", "invalid-expression", ""),
        ("#if 3+4+\n", "invalid-expression", ""),
        ("#if 4 * * 4\n", "invalid-expression", "*"),
        (
            "#if !((~(+ ++1 - - - -1) >> 1) & 1)\n",
            "invalid-expression",
            "++",
        ),
        ("#if 1 = 1\n", "extra-tokens", "= 1"),
        ("#if defined\n", "invalid-defined", "defined"),
        ("#if defined()\n", "invalid-defined", ")"),
        ("#if defined(\n", "invalid-defined", "defined"),
        ("#if defined)\n", "invalid-defined", ")"),
        ("#if defined((AAA))\n", "invalid-defined", "("),
        ("#if defined(AAA\n", "invalid-defined", ""),
        ("#if 1 $\n", "extra-tokens", "$"),
        ("#if $\n", "invalid-character", "$"),
    ];
    for (src, code, span) in cases {
        let (f, d) = the_error(&format!("{src}#endif\n"), code);
        assert_eq!(at(&f, &d), *span, "{src}");
    }
}

#[test]
fn defined_from_a_macro_is_an_error() {
    for src in [
        "#define AAA defined(BBB)\n#if !AAA\n#endif\n",
        "#define AAA defined\n#if AAA AAA\n#endif\n",
        "#define BBB 1\n#define AAA defined(BBB)\n#undef BBB\n#if !AAA\n#endif\n",
        "#define FOO 1\n#define OPEN defined(\n#define CLOSE FOO)\n#if OPEN CLOSE\n#endif\n",
    ] {
        let (f, d) = the_error(src, "defined-from-macro");
        assert!(["AAA", "OPEN"].contains(&at(&f, &d).as_str()), "{src}");
    }
    // `defined` cannot be defined.
    let (f, d) = the_error("#define defined BBB\n", "reserved-macro-name");
    assert_eq!(at(&f, &d), "defined");
    // Directive names are ordinary names.
    assert_eq!(out("#define define 1\ndefine"), "1");
}

#[test]
fn conditional_groups() {
    assert_eq!(
        out("#if 0\na\n#elif 0\nb\n#elif 1\nc\n#else\nd\n#endif"),
        "c"
    );
    assert_eq!(out("#if 1\na\n#elif 1\nb\n#else\nc\n#endif"), "a");
    assert_eq!(
        out("#ifdef GL_ES\na\n#endif\n#ifndef GL_ES\nb\n#endif"),
        "a"
    );
    assert_eq!(out("#if 1\n#  if 0\na\n#  else\n#    if 0\nb\n#    elif 1\nc\n#    endif\n#  endif\n#endif"), "c");
    assert_eq!(out("#ifndef AAA\na\n#elif 1\nb\n#endif"), "a");
    // A taken group stops later `#elif` expressions from being evaluated.
    assert_eq!(out("#if 1\na\n#elif UNDEFINED\nb\n#endif"), "a");
    assert_eq!(out("#if 1\na\n#elif\nb\n#endif"), "a");
}

#[test]
fn skipped_groups_ignore_all_but_conditionals() {
    let src = "#if 0\n#foo\n#define GL_X 1\n#version 100\n#extension all : require\n#line x\n#error no\n$ @ ` # ##\n\u{2019}\n#if UNDEFINED\n#else garbage\n#elif 1/0\n#endif\n#endif\nok";
    assert_eq!(out(src), "ok");
}

#[test]
fn conditional_structure_errors() {
    let (f, d) = the_error("#if 1\nx\n", "unterminated-conditional");
    assert_eq!(at(&f, &d), "#if");
    assert_eq!(f.line_col(d.span.start).line, 2);
    assert_eq!(d.fix.as_ref().unwrap().edits[0].replacement, "\n#endif\n");
    for src in [
        "#if 0\n",
        "#ifdef FOOBAR\n",
        "#ifndef GL_ES\n",
        "#if 1\n#else\n",
        "#if 0\n#else\n",
        "#if 0\n#elif 1\n",
        "#if 1\n#elif 0\n",
        "#if 0\n#elif 0\n",
    ] {
        the_error(src, "unterminated-conditional");
    }
    let (_, p) = run(&v("#if 1\n#\tif 1\n"));
    assert_eq!(
        errors(&p),
        ["unterminated-conditional", "unterminated-conditional"]
    );
    let (f, d) = the_error("#if 0\n#else\n#elif 1\n#endif\n", "elif-after-else");
    assert_eq!(at(&f, &d), "#elif");
    assert_eq!(f.slice(d.secondary[0].span), "#else");
    let (f, d) = the_error("#if !GL_ES\n#else\n#else\n#endif\n", "else-after-else");
    assert_eq!(f.line_col(d.span.start).line, 4);
    let (f, d) = the_error("#else\n", "else-without-if");
    assert_eq!(at(&f, &d), "#else");
    the_error("#elif 1\n", "elif-without-if");
    let (f, d) = the_error("x\n#endif\n", "endif-without-if");
    assert_eq!(at(&f, &d), "#endif");
    let (f, d) = the_error("#if 1\n#\telif\n#\tendif\n#endif\n", "endif-without-if");
    assert_eq!(f.line_col(d.span.start).line, 5);
    for (src, extra) in [
        ("#if 1\n#else foobar 1.231\n#endif\n", "foobar 1.231"),
        ("#if 1\n#else\n#endif foobar\n", "foobar"),
        ("#ifdef FOOBAR foobar\n#endif\n", "foobar"),
        (
            "#ifndef FOOBAR ,, +- << barbar\n#endif\n",
            ",, +- << barbar",
        ),
    ] {
        let (f, d) = the_error(src, "extra-tokens");
        assert_eq!(at(&f, &d), extra);
    }
    for (src, code) in [
        ("#ifdef\n#endif\n", "missing-macro-name"),
        ("#ifndef\n#endif\n", "missing-macro-name"),
        ("#ifdef 1\n#endif\n", "invalid-macro-name"),
        ("#ifndef 1\n#endif\n", "invalid-macro-name"),
    ] {
        the_error(src, code);
    }
}

// ---------------------------------------------------------------------------------------------
// Other directives

#[test]
fn null_and_unknown_directives() {
    assert_eq!(out("#\n# // comment\n/*sfd*/\t\t# /* */\nx"), "x");
    let (f, d) = the_error("#defin AAA\n", "unknown-directive");
    assert_eq!(at(&f, &d), "#defin");
    assert_eq!(d.token, "defin");
    assert_eq!(d.help.as_deref(), Some("did you mean `#define`?"));
    assert_eq!(d.fix.unwrap().edits[0].replacement, "define");
    the_error("#include \"x.glsl\"\n", "unknown-directive");
    let (f, d) = the_error("# 123\n", "unknown-directive");
    assert_eq!(at(&f, &d), "123");
    // Line continuations inside a directive name.
    assert_eq!(
        out("#def\\\nine A(X) (-1.0*(X))\nA(2.0)"),
        "( - 1.0 * ( 2.0 ) )"
    );
}

#[test]
fn error_directive() {
    let (f, d) = the_error(
        "#define AAA asdf\n#error 1 * AAA /* comment */\n",
        "error-directive",
    );
    assert_eq!(d.message, "1 * AAA");
    assert_eq!(at(&f, &d), "#error 1 * AAA");
    assert_eq!(d.token, "#error");
    let (_, d) = the_error("#error\n", "error-directive");
    assert_eq!(d.message, "`#error` directive");
}

#[test]
fn pragmas() {
    let (f, p) = run(&v("#pragma\n#pragma STDGL invariant(all)\n#pragma debug(off)\n#pragma optimize(on)\n#pragma **%\n#pragma whatever(1.0)\n"));
    assert!(p.diagnostics.is_empty(), "{:?}", p.diagnostics);
    assert!(p.invariant_all);
    assert_eq!(
        f.slice(p.invariant_all_span.unwrap()),
        "#pragma STDGL invariant(all)"
    );
    // Not macro-expanded.
    let (_, p) = run(&v("#define off INVALID\n#pragma debug(off)\n"));
    assert!(p.diagnostics.is_empty());
    // Malformed known pragmas are ignored with a warning.
    let (_, p) = run(&v("#pragma debug(1.23)\n"));
    assert_eq!((errors(&p), warnings(&p)), (vec![], vec!["invalid-pragma"]));
    // Not in a fragment shader.
    let opts = PreprocessOptions {
        stage: Some(Stage::Fragment),
        ..Default::default()
    };
    let (f, p) = run_with(&v("#pragma STDGL invariant(all)\n"), &opts);
    assert_eq!(errors(&p), ["invariant-all-in-fragment-shader"]);
    assert_eq!(
        f.slice(p.diagnostics[0].span),
        "#pragma STDGL invariant(all)"
    );
    let opts = PreprocessOptions {
        stage: Some(Stage::Vertex),
        ..Default::default()
    };
    assert!(run_with(&v("#pragma STDGL invariant(all)\n"), &opts)
        .1
        .diagnostics
        .is_empty());
}

#[test]
fn extensions() {
    let (f, p) = run(&v("#extension all : warn\n#extension all : disable\n#define warn enable\n#extension all : warn\n"));
    assert!(p.diagnostics.is_empty(), "{:?}", p.diagnostics);
    assert_eq!(p.extensions.len(), 3);
    assert_eq!(p.extensions[0].0, "all");
    assert_eq!(p.extensions[0].1, ExtensionBehavior::Warn);
    assert_eq!(f.slice(p.extensions[0].2), "#extension all : warn");
    for (src, code, span) in [
        ("#extension\n", "invalid-extension-directive", "#extension"),
        ("#extension 2 : all\n", "invalid-extension-name", "2"),
        ("#extension all\n", "invalid-extension-directive", ""),
        ("#extension all ;\n", "invalid-extension-directive", ";"),
        ("#extension all :\n", "invalid-extension-behavior", ""),
        (
            "#extension all : WARN\n",
            "invalid-extension-behavior",
            "WARN",
        ),
        (
            "#extension all : require\n",
            "extension-all-behavior",
            "require",
        ),
        (
            "#extension all : enable\n",
            "extension-all-behavior",
            "enable",
        ),
        (
            "#extension all* : warn\n",
            "invalid-extension-directive",
            "*",
        ),
        (
            "#extension all : war*n\n",
            "invalid-extension-behavior",
            "war",
        ),
        ("#extension all : warn *\n", "extra-tokens", "*"),
        (
            "#extension GL_EXT_draw_buffers : require\n",
            "extension-not-supported",
            "GL_EXT_draw_buffers",
        ),
        (
            "void f();\n#extension all : disable\n",
            "extension-after-code",
            "#extension all : disable",
        ),
    ] {
        let (f, d) = the_error(src, code);
        assert_eq!(at(&f, &d), span, "{src}");
    }
    let (_, d) = the_error("#extension all : WARN\n", "invalid-extension-behavior");
    assert_eq!(d.fix.unwrap().applicability, Applicability::Certain);
    // Unknown extensions: a warning unless required; WebGL 1 extensions built into ES 3.00 are
    // not defined as macros.
    let (_, p) = run(&v("#extension GL_OES_standard_derivatives : enable\n#ifdef GL_OES_standard_derivatives\nx\n#endif\n"));
    assert_eq!(
        (errors(&p), warnings(&p)),
        (vec![], vec!["extension-not-supported"])
    );
    assert!(texts(&p).is_empty());
    // Supported ones are macros and may be required.
    let opts = PreprocessOptions {
        extensions: vec!["GL_OVR_multiview2".into()],
        ..Default::default()
    };
    let (_, p) = run_with(
        &v("#extension GL_OVR_multiview2 : require\nGL_OVR_multiview2\n"),
        &opts,
    );
    assert!(p.diagnostics.is_empty());
    assert_eq!(texts(&p), ["1"]);
    assert_eq!(p.extensions[0].1, ExtensionBehavior::Require);
    let (_, p) = run_with(&v("#undef GL_OVR_multiview2\n"), &opts);
    assert_eq!(errors(&p), ["predefined-macro-undefined"]);
}

// ---------------------------------------------------------------------------------------------
// #version

#[test]
fn version_300_es_on_the_first_line() {
    let (_, p) = run("#version 300 es\nx");
    assert!(p.diagnostics.is_empty());
    assert_eq!(p.version, Version::Es300);
    assert_eq!(p.declared_version, Some(Version::Es300));
    let (_, p) = run("/* c */ #version 300 es\n__VERSION__");
    assert!(p.diagnostics.is_empty());
    assert_eq!(texts(&p), ["300"]);
}

#[test]
fn version_not_on_the_first_line() {
    for src in [
        "\n#version 300 es\nx",
        "// This shader is wrong\n#version 300 es\nx",
        "/* a\n */ #version 300 es\nx",
    ] {
        let (f, p) = run(src);
        assert_eq!(errors(&p), ["version-not-first-line"], "{src:?}");
        let d = &p.diagnostics[0];
        assert_eq!(f.slice(d.span), "#version 300 es");
        assert_eq!(d.token, "\n");
        assert_eq!(p.version, Version::Es100, "WebGL compiles it as ES 1.00");
        assert_eq!(p.declared_version, Some(Version::Es300));
        let fix = d.fix.as_ref().unwrap();
        assert_eq!(fix.applicability, Applicability::Certain);
        let (fixed, n) = essl::diagnostic::apply_fixes(src, &p.diagnostics, Applicability::Certain);
        assert_eq!(n, 1);
        assert!(fixed.starts_with("#version 300 es\n"), "{fixed:?}");
        assert_eq!(run(&fixed).1.diagnostics.len(), 0, "{fixed:?}");
    }
    for src in [
        "precision mediump float;\n#version 300 es\n",
        "#define FOO BAR\n#version 300 es\n",
        "#version 300 es\n#version 300 es\n",
    ] {
        let (f, p) = run(src);
        assert_eq!(errors(&p), ["version-not-first"], "{src:?}");
        assert_eq!(f.slice(p.diagnostics[0].span), "#version 300 es");
    }
}

#[test]
fn version_errors() {
    // No `#version`, or `#version 100`: GLSL ES 1.00, no error.
    let (_, p) = run("void main() {}");
    assert!(errors(&p).is_empty());
    assert_eq!(p.version, Version::Es100);
    assert_eq!(texts(&run("__VERSION__").1), ["100"]);
    let (_, p) = run("#version 100\nx");
    assert!(errors(&p).is_empty());
    assert_eq!(p.version, Version::Es100);
    // WebGL 1 compiles GLSL ES 1.00 only.
    let options = PreprocessOptions {
        target: essl::Target::WebGl1,
        ..Default::default()
    };
    let (f, p) = run_with("#version 300 es\nx", &options);
    assert_eq!(errors(&p), ["unsupported-version"]);
    assert_eq!(p.version, Version::Es300);
    assert_eq!(f.slice(p.diagnostics[0].span), "300 es");
    let (f, p) = run("#version 300\nx");
    assert_eq!(errors(&p), ["invalid-version"]);
    assert_eq!(p.version, Version::Es100);
    let (fixed, _) =
        essl::diagnostic::apply_fixes(f.text(), &p.diagnostics, Applicability::Certain);
    assert_eq!(fixed, "#version 300 es\nx");
    let (_, p) = run("#version 310 es\nx");
    assert_eq!(errors(&p), ["unsupported-version"]);
    assert_eq!(p.version, Version::Other(310, true));
    for (src, code, span) in [
        ("#version 299 es\n", "unsupported-version", "299 es"),
        ("#version 301 es\n", "unsupported-version", "301 es"),
        ("#version\n", "invalid-version", ""),
        ("#version 300 es.0\n", "extra-tokens", ".0"),
        ("#version foobar\n", "invalid-version", "foobar"),
        ("#version 300 es foobar\n", "extra-tokens", "foobar"),
    ] {
        let (f, p) = run(src);
        assert_eq!(errors(&p), [code], "{src:?}");
        assert_eq!(f.slice(p.diagnostics[0].span), span, "{src:?}");
    }
}

// ---------------------------------------------------------------------------------------------
// Names and characters

#[test]
fn reserved_macro_names() {
    let (f, d) = the_error("# define GL_VALUE 1.0\n", "reserved-macro-name");
    assert_eq!(at(&f, &d), "GL_VALUE");
    assert_eq!(d.token, "GL_VALUE");
    for name in ["__VALUE__", "__FOO", "FOO__BAR"] {
        let (f, p) = run(&v(&format!("#define {name} 1\n{name}")));
        assert_eq!(
            (errors(&p), warnings(&p)),
            (vec![], vec!["double-underscore-macro-name"])
        );
        assert_eq!(f.slice(p.diagnostics[0].span), name);
        assert_eq!(texts(&p), ["1"]);
    }
    // A parameter named like a predefined macro is fine.
    assert_eq!(
        out("#define FUNCTION(__LINE__, b) __LINE__+b\nFUNCTION(1.0, 2.0)"),
        "1.0 + 2.0"
    );
}

#[test]
fn invalid_characters() {
    let (f, d) = the_error("float a = 1.0 $ 2.0;\n", "invalid-character");
    assert_eq!(at(&f, &d), "$");
    assert_eq!(d.token, "$");
    assert!(d.message.contains("U+0024"), "{}", d.message);
    assert!(d.help.is_some());
    // Non-ASCII: WebGL's log quotes `?`; an invisible one has a certain fix.
    let (f, d) = the_error("float\u{200B} a;\n", "invalid-character");
    assert_eq!(at(&f, &d), "\u{200B}");
    assert_eq!(d.token, "?");
    assert!(d.message.contains("U+200B"), "{}", d.message);
    assert_eq!(d.fix.unwrap().applicability, Applicability::Certain);
    // Still passed on (the parser sees an error token), not reported twice.
    let (_, p) = run(&v("a @ b"));
    assert_eq!(texts(&p), ["a", "@", "b"]);
    // In a `#define`: only an error where the macro is used.
    assert!(run(&v("#define A a \\ b\n#define QUOTE \"ab\"\n"))
        .1
        .diagnostics
        .is_empty());
    let (f, d) = the_error("#define C int q3 = $ 1\nC;\n", "invalid-character");
    assert_eq!(at(&f, &d), "C");
    assert_eq!(f.slice(d.secondary[0].span), "$");
    // A byte order mark before `#version` is reported, and the directive still counts.
    let (f, p) = run("\u{FEFF}#version 300 es\nx");
    assert_eq!(errors(&p), ["invalid-character"]);
    assert_eq!(p.version, Version::Es300);
    let (fixed, _) =
        essl::diagnostic::apply_fixes(f.text(), &p.diagnostics, Applicability::Certain);
    assert_eq!(fixed, "#version 300 es\nx");
    // In comments and skipped groups: fine.
    assert!(run(&v("// $ @ \u{2019}\n/* ` */\n#if 0\n$\n#endif\n"))
        .1
        .diagnostics
        .is_empty());
}

#[test]
fn stray_hash_and_token_pasting() {
    let (f, d) = the_error("a # b\n", "stray-hash");
    assert_eq!(at(&f, &d), "#");
    let (_, p) = run(&v("a # b"));
    assert_eq!(texts(&p), ["a", "b"]);
    let (_, p) = run(&v("#define CAT(a, b) a ## b\n"));
    assert_eq!((errors(&p), warnings(&p)), (vec![], vec!["token-pasting"]));
    let (_, p) = run(&v("#define CAT(a, b) a ## b\nCAT(x, y)"));
    assert_eq!(errors(&p), ["stray-hash"]);
    assert_eq!(texts(&p), ["x", "y"]);
}

#[test]
fn long_identifiers() {
    let ok = "a".repeat(1024);
    assert!(run(&v(&ok)).1.diagnostics.is_empty());
    let long = "a".repeat(1025);
    the_error(&long, "identifier-too-long");
}

// ---------------------------------------------------------------------------------------------
// Options

#[test]
fn defines_from_options() {
    let opts = PreprocessOptions {
        defines: vec![
            ("QUALITY".into(), "2".into()),
            ("F(a)".into(), "(a*a)".into()),
            ("E".into(), "".into()),
        ],
        ..Default::default()
    };
    let (_, p) = run_with(&v("QUALITY F(3) E\n#ifdef QUALITY\nyes\n#endif"), &opts);
    assert!(p.diagnostics.is_empty());
    assert_eq!(texts(&p), ["2", "(", "3", "*", "3", ")", "yes"]);
    // The shader may redefine them (warning) or undefine them.
    let (_, p) = run_with(&v("#define QUALITY 1\nQUALITY"), &opts);
    assert_eq!(
        (errors(&p), warnings(&p)),
        (vec![], vec!["option-macro-redefined"])
    );
    assert_eq!(texts(&p), ["1"]);
    let (_, p) = run_with(&v("#define QUALITY 2\n#undef QUALITY\nQUALITY"), &opts);
    assert!(p.diagnostics.is_empty());
    assert_eq!(texts(&p), ["QUALITY"]);
    // Bad ones are reported, with a note.
    let opts = PreprocessOptions {
        defines: vec![("GL_X".into(), "1".into())],
        ..Default::default()
    };
    let (_, p) = run_with(&v(""), &opts);
    assert_eq!(errors(&p), ["reserved-macro-name"]);
    assert!(p.diagnostics[0].notes.iter().any(|n| n.contains("options")));
}

// ---------------------------------------------------------------------------------------------
// Robustness and speed

#[test]
fn output_ends_with_one_eof_and_no_newlines() {
    let (_, p) = run(&v("a\n\n#define X\nb X\n"));
    assert!(p.tokens.iter().all(|t| t.kind != PpKind::Newline));
    assert_eq!(p.tokens.iter().filter(|t| t.kind == PpKind::Eof).count(), 1);
    assert_eq!(p.tokens.last().unwrap().kind, PpKind::Eof);
    let (_, p) = run("");
    assert_eq!(p.tokens.len(), 1);
}

#[test]
fn errors_do_not_stop_the_run() {
    let (_, p) = run(&v(
        "#defin A\n#define 1\n#if X\n#endif\n#undef __LINE__\n#error e\nok\n#if 1\n",
    ));
    assert_eq!(
        errors(&p),
        [
            "unknown-directive",
            "invalid-macro-name",
            "undefined-macro-in-if",
            "predefined-macro-undefined",
            "error-directive",
            "unterminated-conditional"
        ]
    );
    assert_eq!(texts(&p), ["ok"]);
}

#[test]
fn deep_nesting_of_conditionals() {
    let n = 10_000;
    let src = v(&format!(
        "{}x\n{}",
        "#if 1\n".repeat(n),
        "#endif\n".repeat(n)
    ));
    let (_, p) = run(&src);
    assert!(p.diagnostics.is_empty());
    assert_eq!(texts(&p), ["x"]);
    let src = v(&format!(
        "{}x\n{}",
        "#if 0\n".repeat(n),
        "#endif\n".repeat(n)
    ));
    assert!(texts(&run(&src).1).is_empty());
    // Unterminated: reported, but not 10,000 times.
    let (_, p) = run(&v(&"#if 1\n".repeat(n)));
    assert!(errors(&p).len() <= 16);
}

#[test]
fn long_macro_chains() {
    let mut src = String::new();
    for i in 0..10_000 {
        src.push_str(&format!("#define M{i} M{}\n", i + 1));
    }
    src.push_str("M0");
    let (_, p) = run(&v(&src));
    assert!(p.diagnostics.is_empty());
    assert_eq!(texts(&p), ["M10000"]);
}

#[test]
fn calls_nested_deep_in_arguments() {
    // Chromium compiles 1,000 nested calls and refuses 1,001 ("macro invocation chain too
    // deep"), with no other preprocessor error.
    let nested = |n: usize| {
        v(&format!(
            "#define F(x) x\n{}1{}",
            "F(".repeat(n),
            ")".repeat(n)
        ))
    };
    for n in [1001, 10_000] {
        let (_, p) = run(&nested(n));
        assert_eq!(errors(&p), ["macro-nesting-too-deep"], "{n} nested calls");
    }
    let (_, p) = run(&nested(1000));
    assert!(errors(&p).is_empty());
    assert_eq!(texts(&p), ["1"]);
}

#[test]
fn deep_if_expressions() {
    let n = 10_000;
    let src = v(&format!("#if {}1{}\n#endif", "(".repeat(n), ")".repeat(n)));
    assert_eq!(errors(&run(&src).1), ["expression-too-deep"]);
    let src = v(&format!("#if {}1\n#endif", "- ".repeat(n)));
    assert_eq!(errors(&run(&src).1), ["expression-too-deep"]);
    let src = v(&format!("#if {}1 == -1\nyes\n#endif", "- ".repeat(255)));
    assert_eq!(texts(&run(&src).1), ["yes"]);
}

#[test]
fn exponential_expansion_is_bounded() {
    let mut src = String::new();
    for i in 0..40 {
        src.push_str(&format!("#define E{i} E{} E{}\n", i + 1, i + 1));
    }
    src.push_str("E0\n");
    let (_, p) = run(&v(&src));
    assert_eq!(errors(&p), ["macro-expansion-too-large"]);
}

#[test]
fn large_input_is_linear() {
    let line = "float x = a * (b + 1.0); // comment\n#define M(a) (a + a)\nx = M(x);\n";
    let src = v(&line.repeat(10 * 1024 * 1024 / line.len()));
    let start = std::time::Instant::now();
    let (_, p) = run(&src);
    assert!(errors(&p).is_empty());
    assert!(
        start.elapsed().as_secs() < 120,
        "took {:?}",
        start.elapsed()
    );
}

mod never_panics {
    use super::*;
    use proptest::prelude::*;

    const PIECES: &[&str] = &[
        "#",
        "##",
        "#define ",
        "#undef ",
        "#if ",
        "#ifdef ",
        "#ifndef ",
        "#elif ",
        "#else",
        "#endif",
        "#line ",
        "#error",
        "#pragma ",
        "#extension ",
        "#version ",
        "defined",
        "(",
        ")",
        ",",
        "A",
        "B",
        "F",
        "F(",
        "1",
        "0",
        "0x",
        "1.5",
        "-",
        "+",
        "/",
        "%",
        "<<",
        ">>",
        "&&",
        "||",
        "!",
        "~",
        "\n",
        " ",
        "\\\n",
        "/*",
        "*/",
        "//",
        "$",
        "\u{a0}",
        "\u{2019}",
        "__LINE__",
        "GL_ES",
        ":",
        "all",
        "warn",
        "require",
        "300 es",
        "es",
        "x",
        ";",
    ];

    proptest! {
        #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]
        #[test]
        fn on_any_token_soup(pieces in proptest::collection::vec(0..PIECES.len(), 0..80)) {
            let mut src = String::from("#define F(a, b) a b F\n#define A B A\n#define B (A)\n");
            for i in pieces {
                src.push_str(PIECES[i]);
            }
            let (_, p) = run(&src);
            prop_assert_eq!(p.tokens.last().map(|t| t.kind), Some(PpKind::Eof));
        }
    }
}

/// A shader whose body repeats `;` through macros: only the expansion limit can reject it.
fn expansion_limit_shader(defines: &str, body: &str) -> String {
    format!("#version 300 es\nprecision mediump float;\nout vec4 o;\n{defines}\nvoid main() {{ {body} o = vec4(1.0); }}\n")
}

#[test]
fn macro_expansions_in_progress_are_bounded_as_in_angle() {
    // Chromium's answers: tests/oracle/PROBES.md, "Preprocessor limits".
    let ten = "#define T(x) x x x x x x x x x x";
    let cases = [
        (ten, "T(T(T(T(;))))".to_string(), true),
        (ten, "T(T(T(T(T(;)))))".to_string(), false),
        (ten, "T(T(T(T(T(T(;))))))".to_string(), false),
        (
            "#define I(x) x",
            format!("I({})", "; ".repeat(10_000)),
            true,
        ),
        (
            "#define I(x) x",
            format!("I({})", "; ".repeat(10_001)),
            false,
        ),
        (
            "#define R(x) x x x",
            format!("R({})", "; ".repeat(5_000)),
            true,
        ),
        (
            "#define R(x) x x x",
            format!("R({})", "; ".repeat(5_001)),
            false,
        ),
    ];
    for (defines, body, ok) in cases {
        let errs = shader_errors(&expansion_limit_shader(defines, &body), Stage::Fragment);
        let codes: Vec<&str> = errs.iter().map(|d| d.code).collect();
        if ok {
            assert!(codes.is_empty(), "{defines} / {}…: {codes:?}", &body[..12]);
        } else {
            assert_eq!(
                codes,
                ["macro-expansion-too-large"],
                "{defines} / {}…",
                &body[..12]
            );
            assert!(
                errs[0].message.contains("10000 tokens at once"),
                "{}",
                errs[0].message
            );
        }
    }
}

#[test]
fn a_diagnostic_in_a_replacement_list_labels_the_macro() {
    let src = "#version 300 es\nprecision highp float;\n\
               #define SHADE(c) vec4(c * undefinedGain, 1.0)\n\
               #define saturate(x) clamp(x, 0.0, 1.0)\nout vec4 o;\n\
               void main() {\n  o = SHADE(vec3(0.5));\n  float q = saturate(1.0 + missingName);\n}\n";
    let file = SourceFile::new("m.frag", src.to_string());
    let shader = essl::compile(file, Stage::Fragment, &essl::CompileOptions::default());
    let undeclared: Vec<&Diagnostic> = shader
        .diagnostics
        .iter()
        .filter(|d| d.code == "undeclared-identifier")
        .collect();
    assert_eq!(undeclared.len(), 2, "{undeclared:#?}");
    // In the replacement list: the whole call, and the `#define` labelled.
    let f = &shader.file;
    assert_eq!(f.slice(undeclared[0].span), "SHADE(vec3(0.5))");
    let labels: Vec<(&str, &str)> = undeclared[0]
        .secondary
        .iter()
        .map(|l| (f.slice(l.span), l.message.as_str()))
        .collect();
    assert_eq!(
        labels,
        [("SHADE", "in this expansion of `SHADE`, defined here")]
    );
    // In an argument: the argument itself, and no label.
    assert_eq!(f.slice(undeclared[1].span), "missingName");
    assert!(undeclared[1].secondary.is_empty());
}
