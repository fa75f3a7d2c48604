//! `essl::minify` over the conformance corpora: every shader essl accepts is minified, the
//! output compiles, and a pair's link result (status, active uniforms and attributes,
//! varyings, outputs) is the original's. Prints the bytes before and after. Skips with a
//! message when the corpora are absent, unless `ESSL_REQUIRE_CORPORA=1`.

use essl::link::{link, Program};
use essl::minify::{minify, MinifyOptions};
use essl::source::SourceFile;
use essl::{compile, CompileOptions, Stage, Target};

fn rows(name: &str) -> Option<Vec<serde_json::Value>> {
    let path = essl_testdata::corpus_file(name)?;
    let text = std::fs::read_to_string(&path).expect("the corpus file reads");
    Some(
        text.lines()
            .filter(|l| !l.trim().is_empty())
            .map(|l| serde_json::from_str(l).expect("valid JSON line"))
            .collect(),
    )
}

/// Bytes before and after, shaders minified, and the failures.
#[derive(Default)]
struct Tally {
    before: usize,
    after: usize,
    shaders: usize,
    pairs: usize,
    failures: Vec<String>,
}

impl Tally {
    /// Minifies one accepted shader; its minified text, or `None` after recording a failure.
    fn one(&mut self, what: &str, text: &str, stage: Stage, target: Target) -> Option<String> {
        let options = MinifyOptions {
            compile: CompileOptions::for_target(target),
            ..MinifyOptions::default()
        };
        match minify(text, stage, &options) {
            Ok(m) => {
                self.before += text.len();
                self.after += m.text.len();
                self.shaders += 1;
                Some(m.text)
            }
            Err(e) => {
                self.failures.push(format!("{what} ({stage:?}): {e}"));
                None
            }
        }
    }

    /// A vertex and fragment pair: each accepted shader minified, and where both are, the
    /// link results compared.
    fn pair(&mut self, what: &str, vs: &str, fs: &str, target: Target) {
        let opts = CompileOptions::for_target(target);
        let a = compile(SourceFile::new("vs", vs), Stage::Vertex, &opts);
        let b = compile(SourceFile::new("fs", fs), Stage::Fragment, &opts);
        let mv = a
            .ok()
            .then(|| self.one(what, vs, Stage::Vertex, target))
            .flatten();
        let mf = b
            .ok()
            .then(|| self.one(what, fs, Stage::Fragment, target))
            .flatten();
        let (Some(mv), Some(mf)) = (mv, mf) else {
            return;
        };
        let c = compile(SourceFile::new("vs", mv), Stage::Vertex, &opts);
        let d = compile(SourceFile::new("fs", mf), Stage::Fragment, &opts);
        let (before, after) = (link(&a, &b), link(&c, &d));
        self.pairs += 1;
        if summary(&before) != summary(&after) {
            self.failures.push(format!(
                "{what}: the link result changed\n{}\n{}",
                summary(&before),
                summary(&after)
            ));
        }
    }

    fn report(&self, corpus: &str) {
        let saved = 100.0 * (1.0 - self.after as f64 / self.before.max(1) as f64);
        println!(
            "{corpus}: {} shaders ({} linked pairs), {} → {} bytes ({saved:.1} % smaller), {} failures",
            self.shaders,
            self.pairs,
            self.before,
            self.after,
            self.failures.len()
        );
        for f in self.failures.iter().take(10) {
            println!("  {f}");
        }
    }
}

/// What WebGL reads of a linked program.
fn summary(p: &Program) -> String {
    format!(
        "{} {:?} {:?} {:?} {:?} {:?}",
        p.ok, p.uniforms, p.attributes, p.attribute_locations, p.varyings, p.fragment_outputs
    )
}

fn text<'a>(row: &'a serde_json::Value, key: &str) -> Option<&'a str> {
    row.get(key).and_then(|v| v.as_str())
}

fn run_pairs(corpus: &str, target: impl Fn(&serde_json::Value) -> Target) -> Option<Tally> {
    let rows = rows(corpus)?;
    let mut t = Tally::default();
    for (i, row) in rows.iter().enumerate() {
        let what = format!(
            "{corpus}:{} {}",
            i + 1,
            text(row, "name").or(text(row, "file")).unwrap_or("")
        );
        let (Some(vs), Some(fs)) = (text(row, "vertex_source"), text(row, "fragment_source"))
        else {
            continue;
        };
        t.pair(&what, vs, fs, target(row));
    }
    t.report(corpus);
    Some(t)
}

#[test]
fn minified_conformance_es300_shaders_compile_and_link_the_same() {
    let Some(t) = run_pairs("webgl_conformance_es300.jsonl", |_| Target::WebGl2) else {
        return;
    };
    assert!(t.failures.is_empty(), "{}", t.failures.join("\n"));
    assert!(t.shaders > 200 && t.after < t.before);
}

#[test]
fn minified_conformance_es100_shaders_compile_and_link_the_same() {
    let Some(t) = run_pairs("webgl_conformance_es100.jsonl", |_| Target::WebGl1) else {
        return;
    };
    assert!(t.failures.is_empty(), "{}", t.failures.join("\n"));
    assert!(t.shaders > 1000 && t.after < t.before);
}

#[test]
fn minified_deqp_shaders_compile_and_link_the_same() {
    let Some(t) = run_pairs("deqp_gles3.jsonl", |_| Target::WebGl2) else {
        return;
    };
    assert!(t.failures.is_empty(), "{}", t.failures.join("\n"));
    assert!(t.shaders > 4000 && t.after < t.before);
}

#[test]
fn minified_webgl2fundamentals_shaders_compile() {
    let Some(rows) = rows("webgl2fundamentals_shaders.jsonl") else {
        return;
    };
    let mut t = Tally::default();
    for row in &rows {
        let (Some(src), Some(stage)) = (text(row, "source"), text(row, "stage")) else {
            continue;
        };
        let stage = if stage == "vertex" {
            Stage::Vertex
        } else {
            Stage::Fragment
        };
        let opts = CompileOptions::default();
        if compile(SourceFile::new("s", src), stage, &opts).ok() {
            t.one(text(row, "file").unwrap_or(""), src, stage, Target::WebGl2);
        }
    }
    t.report("webgl2fundamentals_shaders.jsonl");
    assert!(t.failures.is_empty(), "{}", t.failures.join("\n"));
    assert!(t.shaders > 150 && t.after < t.before);
}

/// A shader with what the minifier must get right: macros (object- and function-like, tested
/// and skipped), comments, a line continuation, shadowing, overloads, structs, a block.
const RICH: &str = "#version 300 es // first\nprecision highp float;\n#define SCALE 2.0\n\
    #define MUL(a, b) ((a) * (b))\n#ifdef USE_MAP\nuniform sampler2D map;\n#endif\n\
    struct Light { vec3 color; float power; };\nuniform Light u_light;\n\
    uniform Block { mat4 u_view; } block;\nin vec2 v_uv;\nout vec4 outColor;\n\
    const float K = 0.50;\nfloat gain = 1.0;\n/* helpers */\n\
    float shade(float x) { return MUL(x, SCALE) * K; }\nfloat shade(vec2 x) { return x.x; }\n\
    void main() {\n  float x = shade(v_uv.x); // local\n  { float x = shade(v_uv); gain += x; }\n\
      vec3 c = u_light.color * u_light.power \\\n    * x;\n  outColor = block.u_view * vec4(c, gain);\n}\n";

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig { cases: 256, ..Default::default() })]

    /// Minify never panics on a mutated shader, and minifies every one that compiles.
    #[test]
    fn mutations_that_compile_minify(
        pos in 0usize..RICH.len(),
        insert in proptest::sample::select(vec![
            "", ";", "{", "}", "(", ")", ".x", " float ", "1", "-", "- -", "/", "*", "#",
            "//", "/*x*/", "\\\n", "\n#define x 1\n", "\n#if 0\nuniform float x;\n#endif\n",
            "\n#undef SCALE\n", " a", "1.0", ".5", "__LINE__",
        ]),
        delete in 0usize..6,
    ) {
        let mut s = RICH.to_string();
        let p = pos.min(s.len());
        let end = (p + delete).min(s.len());
        s.replace_range(p..end, insert);
        let opts = CompileOptions::default();
        let ok = compile(SourceFile::new("m", s.clone()), Stage::Fragment, &opts).ok();
        let r = minify(&s, Stage::Fragment, &MinifyOptions::default());
        if ok {
            let m = r.unwrap_or_else(|e| panic!("{e}\n{s}"));
            proptest::prop_assert!(m.text.len() < s.len());
        } else {
            proptest::prop_assert!(r.is_err());
        }
    }
}

#[test]
fn the_rich_shader_minifies_with_and_without_its_macros() {
    for defines in [vec![], vec![("USE_MAP".to_string(), "1".to_string())]] {
        let options = MinifyOptions {
            compile: CompileOptions {
                defines,
                ..CompileOptions::default()
            },
            ..MinifyOptions::default()
        };
        let m = minify(RICH, Stage::Fragment, &options).unwrap();
        assert!(m
            .text
            .contains("#ifdef USE_MAP\nuniform sampler2D map;\n#endif\n"));
        assert!(m.text.contains("uniform Light u_light;"));
    }
}
