//! Every program and shader essl accepts in the corpora translates to WGSL that naga's WGSL
//! front end parses and validates again, and whose uniform buffer has, at every offset the
//! binding map names, the member the map says (the map agrees with the layout WGSL itself
//! computes from the text). The other four targets are counted too. The figures are the ones
//! `docs/translate.md` reports. Skips, with a message, when the corpora are absent, unless
//! `ESSL_REQUIRE_CORPORA=1`.

use essl::source::SourceFile;
use essl::{CompileOptions, Shader, Stage};
use essl_translate::bindings::Place;
use essl_translate::roundtrip::read_wgsl;
use essl_translate::{Code, Options, Target};
use serde_json::Value;

fn compile(name: &str, text: &str, stage: Stage) -> Shader {
    essl::compile(
        SourceFile::new(name, text.to_owned()),
        stage,
        &CompileOptions::default(),
    )
}

fn lines(name: &str) -> Option<Vec<Value>> {
    let path = essl_testdata::corpus_file(name)?;
    let text = std::fs::read_to_string(path).expect("the corpus reads");
    Some(
        text.lines()
            .filter(|l| !l.trim().is_empty())
            .map(|l| serde_json::from_str(l).expect("a JSON line"))
            .collect(),
    )
}

/// The programs of the corpora that essl compiles and links: (name, vertex, fragment).
fn programs() -> Option<Vec<(String, String, String)>> {
    let mut out = Vec::new();
    // The seeds' programs (in the repository): stages that read different uniforms.
    let seeds = essl_testdata::repo_root().join("shaders-glsl");
    let mut names: Vec<_> = std::fs::read_dir(&seeds)
        .expect("shaders-glsl lists")
        .filter_map(|e| {
            let name = e.ok()?.file_name().to_string_lossy().into_owned();
            Some(name.strip_suffix(".vert")?.to_owned())
        })
        .collect();
    names.sort();
    for name in names {
        let read = |ext: &str| std::fs::read_to_string(seeds.join(format!("{name}.{ext}")));
        if let (Ok(v), Ok(f)) = (read("vert"), read("frag")) {
            out.push((format!("shaders-glsl/{name}"), v, f));
        }
    }
    for case in lines("webgl_conformance_es300.jsonl")? {
        if case["outcome"] == "must_pass" {
            let name = format!("{}#{}", case["file"].as_str().unwrap_or(""), case["index"]);
            out.push((
                name,
                case["vertex_source"].as_str().unwrap_or("").to_owned(),
                case["fragment_source"].as_str().unwrap_or("").to_owned(),
            ));
        }
    }
    for case in lines("deqp_gles3.jsonl")? {
        let pass = case["expect"] == "pass" || case["expect"] == "build_successful";
        if pass && case["version"] == "300 es" {
            out.push((
                case["name"].as_str().unwrap_or("").to_owned(),
                case["vertex_source"].as_str().unwrap_or("").to_owned(),
                case["fragment_source"].as_str().unwrap_or("").to_owned(),
            ));
        }
    }
    Some(out)
}

/// Checks the map against the WGSL's own layout: each buffer uniform's offset holds a member
/// (or an element of one) whose offset WGSL computes to be the same. Returns what differs.
fn check_offsets(map: &essl_translate::BindingMap, wgsl: &str) -> Result<(), String> {
    let (module, _) = read_wgsl(wgsl, Stage::Vertex).map_err(|e| e.to_string())?;
    let Some(block) = module.global_variables.iter().find_map(|(_, g)| {
        (g.binding
            == Some(naga::ResourceBinding {
                group: 0,
                binding: 0,
            }))
        .then_some(g.ty)
    }) else {
        return Ok(()); // This stage has no loose uniforms.
    };
    // Every offset where WGSL puts a scalar, vector or matrix.
    let mut leaves = std::collections::BTreeSet::new();
    fn walk(
        module: &naga::Module,
        ty: naga::Handle<naga::Type>,
        at: u32,
        out: &mut std::collections::BTreeSet<u32>,
    ) {
        match &module.types[ty].inner {
            naga::TypeInner::Struct { members, .. } => {
                for m in members {
                    walk(module, m.ty, at + m.offset, out);
                }
            }
            naga::TypeInner::Array {
                base,
                size: naga::ArraySize::Constant(n),
                stride,
            } => {
                for i in 0..n.get() {
                    walk(module, *base, at + i * stride, out);
                }
            }
            _ => {
                out.insert(at);
            }
        }
    }
    walk(&module, block, 0, &mut leaves);
    for u in &map.uniforms {
        if let Place::Buffer {
            offset,
            array_stride,
            ..
        } = u.place
        {
            for i in 0..u.size {
                let at = offset + i * array_stride;
                // A leaf of the other stage is not in this stage's struct: only check names the
                // text declares.
                let top = u.name.split(['.', '[']).next().unwrap_or("");
                if !wgsl.contains(&format!("    {top}: ")) {
                    continue;
                }
                if !leaves.contains(&at) {
                    return Err(format!("{}[{i}] at {at}: no member there in WGSL", u.name));
                }
            }
        }
    }
    Ok(())
}

/// The program as one WGSL module: written by essl's writer, read back by naga, with the
/// per-stage translation's binding map and every offset of it where WGSL puts a member.
fn single_module(
    vs: &Shader,
    fs: &Shader,
    bindings: &essl_translate::BindingMap,
) -> Result<(), String> {
    let one = essl_translate::translate_program_module(vs, fs, &Options::default())
        .map_err(|e| e.to_string())?;
    let text = one.code.as_text().expect("WGSL is text");
    if text.contains("Written by naga's WGSL writer") {
        return Err("naga's writer".into());
    }
    read_wgsl(text, Stage::Vertex).map_err(|e| e.to_string())?;
    if one.bindings != *bindings {
        return Err("a binding map of its own".into());
    }
    check_offsets(&one.bindings, text)
}

/// Programs that do not translate to WGSL yet (none: a `switch` case with statements that
/// falls through, which WGSL cannot say, is lowered with the statements it falls into).
const KNOWN: &[&str] = &[];

/// What translating a share of the programs found.
#[derive(Default)]
struct Tally {
    accepted: usize,
    wgsl_ok: usize,
    single_ok: usize,
    single_failures: Vec<String>,
    others: [usize; 4],
    failures: Vec<String>,
    unlowered: Vec<String>,
    other_failures: Vec<String>,
}

impl Tally {
    fn add(&mut self, o: Tally) {
        self.accepted += o.accepted;
        self.wgsl_ok += o.wgsl_ok;
        self.single_ok += o.single_ok;
        self.single_failures.extend(o.single_failures);
        for (a, b) in self.others.iter_mut().zip(o.others) {
            *a += b;
        }
        self.failures.extend(o.failures);
        self.unlowered.extend(o.unlowered);
        self.other_failures.extend(o.other_failures);
    }

    /// Translates one program to every target, if essl accepts it.
    fn program(&mut self, name: &str, v: &str, f: &str) {
        let vs = compile(&format!("{name}.vert"), v, Stage::Vertex);
        let fs = compile(&format!("{name}.frag"), f, Stage::Fragment);
        if !(vs.ok() && fs.ok() && essl::link::link(&vs, &fs).ok) {
            return;
        }
        self.accepted += 1;
        match essl_translate::translate_program(&vs, &fs, &Options::default()) {
            // A construct essl does not lower yet (docs/conformance.md's known gaps): essl-gl
            // cannot run it either.
            Err(essl_translate::TranslateError::Lower(e)) => {
                self.unlowered.push(format!("{name}: {e}"));
                return;
            }
            Ok(t) => {
                let mut ok = true;
                for (stage, code) in [(Stage::Vertex, &t.vertex), (Stage::Fragment, &t.fragment)] {
                    let text = code.as_text().expect("WGSL is text");
                    let wrong = if text.contains("Written by naga's WGSL writer") {
                        Err("naga's writer".to_string())
                    } else {
                        read_wgsl(text, stage)
                            .map(|_| ())
                            .map_err(|e| e.to_string())
                            .and_then(|()| check_offsets(&t.bindings, text))
                    };
                    if let Err(e) = wrong {
                        self.failures
                            .push(format!("{name} ({}): {e}", stage.as_str()));
                        ok = false;
                    }
                }
                self.wgsl_ok += ok as usize;
                self.single_ok += single_module(&vs, &fs, &t.bindings)
                    .map_err(|e| self.single_failures.push(format!("{name}: {e}")))
                    .is_ok() as usize;
            }
            Err(e) => self.failures.push(format!("{name}: {e}")),
        }
        for (k, target) in [Target::SpirV, Target::Msl, Target::Hlsl, Target::Glsl]
            .into_iter()
            .enumerate()
        {
            match essl_translate::translate_program(&vs, &fs, &Options::new(target)) {
                Ok(t) => {
                    let nonempty = |c: &Code| !c.to_bytes().is_empty();
                    self.others[k] += (nonempty(&t.vertex) && nonempty(&t.fragment)) as usize;
                }
                Err(e) => self
                    .other_failures
                    .push(format!("{name} ({}): {e}", target.name())),
            }
        }
    }
}

#[test]
fn every_accepted_program_translates_and_reads_back() {
    let Some(programs) = programs() else {
        return;
    };
    // The programs in as many shares as the machine has cores (this test is most of the
    // crate's test time): each share tallied on a thread of its own, in order.
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let share = programs.len().div_ceil(threads).max(1);
    let tally = std::thread::scope(|scope| {
        let running: Vec<_> = programs
            .chunks(share)
            .map(|chunk| {
                scope.spawn(move || {
                    let mut t = Tally::default();
                    for (name, v, f) in chunk {
                        t.program(name, v, f);
                    }
                    t
                })
            })
            .collect();
        let mut all = Tally::default();
        for r in running {
            all.add(r.join().expect("a share of the programs"));
        }
        all
    });
    let Tally {
        accepted,
        wgsl_ok,
        single_ok,
        single_failures,
        others,
        failures,
        unlowered,
        other_failures,
    } = tally;
    let lowered = accepted - unlowered.len();
    println!(
        "programs: {accepted} accepted, {lowered} lowered, {wgsl_ok} WGSL read back; spirv {}, \
         msl {}, hlsl {}, glsl {}\nnot lowered:\n{}",
        others[0],
        others[1],
        others[2],
        others[3],
        unlowered.join("\n")
    );
    assert!(accepted > 4000, "{accepted} programs accepted");
    let unknown: Vec<_> = failures
        .iter()
        .filter(|f| !KNOWN.iter().any(|k| f.starts_with(&format!("{k}:"))))
        .collect();
    assert!(unknown.is_empty(), "{unknown:#?}");
    for k in KNOWN {
        assert!(
            failures.iter().any(|f| f.starts_with(&format!("{k}:"))),
            "{k} translates now: take it off KNOWN (and docs/translate.md)"
        );
    }
    assert_eq!(wgsl_ok, lowered - KNOWN.len());
    println!("one module per program (--module single): {single_ok} read back");
    assert_eq!(single_ok, wgsl_ok, "{single_failures:#?}");
    println!("known: {failures:#?}\nother targets: {other_failures:#?}");
    // SPIR-V is what essl-gl runs through wgpu: every program.
    assert_eq!(others[0], lowered, "{other_failures:#?}");
}

#[test]
fn every_accepted_lone_shader_translates_and_reads_back() {
    let Some(cases) = lines("webgl2fundamentals_shaders.jsonl") else {
        return;
    };
    let (mut accepted, mut ok) = (0, 0);
    let mut failures = Vec::new();
    for case in &cases {
        let stage = match case["stage"].as_str() {
            Some("vertex") => Stage::Vertex,
            Some("fragment") => Stage::Fragment,
            _ => continue,
        };
        let name = case["file"].as_str().unwrap_or("");
        let shader = compile(name, case["source"].as_str().unwrap_or(""), stage);
        if !shader.ok() {
            continue;
        }
        accepted += 1;
        match essl_translate::translate_shader(&shader, &Options::default()) {
            Ok(t)
                if t.code
                    .as_text()
                    .is_some_and(|t| t.contains("Written by naga's WGSL writer")) =>
            {
                failures.push(format!("{name}: naga's writer"))
            }
            Ok(t) => match read_wgsl(t.code.as_text().expect("text"), stage) {
                Ok(_) => ok += 1,
                Err(e) => failures.push(format!("{name}: {e}")),
            },
            Err(e) => failures.push(format!("{name}: {e}")),
        }
    }
    println!("webgl2fundamentals shaders: {accepted} accepted, {ok} WGSL read back");
    assert!(accepted > 200, "{accepted}");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
