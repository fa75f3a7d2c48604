//! Active uniforms and attributes through the API: every program of `shaders-glsl/` and of the
//! webgl2fundamentals corpus is created, compiled and linked with `create_shader` …
//! `link_program`, then enumerated with `get_program_parameter(ACTIVE_UNIFORMS)`,
//! `get_active_uniform`, `get_active_attrib` and `get_attrib_location`, and compared with what
//! Chromium answered (`tests/oracle/*.json`): link status, and names, types, sizes, order and
//! attribute locations. (`crates/essl/tests/it/oracle.rs` checks the same below the API.)

use crate::common;

use std::path::{Path, PathBuf};

use essl_gl::{gl, Context, Parameter};
use serde_json::Value;

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn oracle(name: &str) -> Value {
    let path = repo().join("tests/oracle").join(name);
    serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap()
}

/// The oracle's type: a WebGL enum name, or (in older files) its number.
fn type_name(v: &Value) -> String {
    match v {
        Value::String(s) => s.clone(),
        Value::Number(n) => essl::types::GlType::from_u32(n.as_u64().unwrap_or(0) as u32)
            .map(|t| t.name().to_owned())
            .unwrap_or_default(),
        _ => String::new(),
    }
}

fn gl_type_name(ty: u32) -> String {
    essl::types::GlType::from_u32(ty).map_or_else(|| format!("0x{ty:04X}"), |t| t.name().into())
}

/// Links `vs` + `fs` through the API and lists what it reports, in the oracle's format:
/// the link status, `"name TYPE size"` per uniform and `"name TYPE size @location"` per
/// attribute.
fn through_the_api(ctx: &mut Context, vs: &str, fs: &str) -> (bool, Vec<String>, Vec<String>) {
    let program = ctx.create_program();
    for (ty, src) in [(gl::VERTEX_SHADER, vs), (gl::FRAGMENT_SHADER, fs)] {
        let s = ctx.create_shader(ty).unwrap();
        ctx.shader_source(s, src);
        ctx.compile_shader(s);
        ctx.attach_shader(program, s);
        ctx.delete_shader(s);
    }
    ctx.link_program(program);
    let ok = ctx.get_program_parameter(program, gl::LINK_STATUS) == Some(Parameter::Bool(true));
    let count = |ctx: &mut Context, pname| {
        ctx.get_program_parameter(program, pname)
            .and_then(|p| p.as_int())
            .unwrap() as u32
    };
    let uniforms = (0..count(ctx, gl::ACTIVE_UNIFORMS))
        .map(|i| {
            let essl_gl::ActiveInfo { name, ty, size } =
                ctx.get_active_uniform(program, i).unwrap();
            format!("{name} {} {size}", gl_type_name(ty))
        })
        .collect();
    let attributes = (0..count(ctx, gl::ACTIVE_ATTRIBUTES))
        .map(|i| {
            let essl_gl::ActiveInfo { name, ty, size } = ctx.get_active_attrib(program, i).unwrap();
            let location = ctx.get_attrib_location(program, &name);
            format!("{name} {} {size} @{location}", gl_type_name(ty))
        })
        .collect();
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    ctx.delete_program(program);
    (ok, uniforms, attributes)
}

/// Compares one program with the oracle's entry; returns the differences.
fn compare(what: &str, got: (bool, Vec<String>, Vec<String>), want: &Value) -> Vec<String> {
    let (ok, uniforms, attributes) = got;
    let want_ok = want["ok"].as_bool().unwrap();
    if ok != want_ok {
        return vec![format!("{what}: link status essl-gl {ok}, WebGL {want_ok}")];
    }
    if !ok {
        return Vec::new();
    }
    let want_u: Vec<String> = want["uniforms"]
        .as_array()
        .unwrap()
        .iter()
        .map(|u| {
            format!(
                "{} {} {}",
                u["name"].as_str().unwrap(),
                type_name(&u["type"]),
                u["size"]
            )
        })
        .collect();
    let want_a: Vec<String> = want["attributes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|a| {
            format!(
                "{} {} {} @{}",
                a["name"].as_str().unwrap(),
                type_name(&a["type"]),
                a["size"],
                a["location"]
            )
        })
        .collect();
    let mut diffs = Vec::new();
    if uniforms != want_u {
        diffs.push(format!(
            "{what}: uniforms\n  WebGL   {want_u:?}\n  essl-gl {uniforms:?}"
        ));
    }
    if attributes != want_a {
        diffs.push(format!(
            "{what}: attributes\n  WebGL   {want_a:?}\n  essl-gl {attributes:?}"
        ));
    }
    diffs
}

#[test]
fn shaders_glsl_through_the_api() {
    let Some(mut ctx) = common::context(4, 4) else {
        return;
    };
    let data = oracle("shaders-glsl.json");
    let links = data["link"].as_object().unwrap();
    assert!(links.len() >= 15, "{} programs", links.len());
    let (mut linked, mut failures) = (0, Vec::new());
    for (base, want) in links {
        let read = |ext: &str| std::fs::read_to_string(repo().join(format!("{base}.{ext}")));
        let (Ok(vs), Ok(fs)) = (read("vert"), read("frag")) else {
            panic!("{base}: sources missing");
        };
        let got = through_the_api(&mut ctx, &vs, &fs);
        linked += got.0 as usize;
        failures.extend(compare(base, got, want));
    }
    println!("shaders-glsl: {} programs, {linked} linked", links.len());
    assert!(
        failures.is_empty(),
        "{} disagreements:\n{}",
        failures.len(),
        failures.join("\n")
    );
    common::assert_clean(&ctx);
}

#[test]
fn webgl2fundamentals_through_the_api() {
    let Some(corpus) = essl_testdata::corpus_file("webgl2fundamentals_shaders.jsonl") else {
        return;
    };
    let Some(mut ctx) = common::context(4, 4) else {
        return;
    };
    let sources: Vec<Value> = std::fs::read_to_string(&corpus)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let data = oracle("webgl2fundamentals.json");
    let programs = data["programs"].as_array().unwrap();
    assert!(programs.len() >= 50, "{} programs", programs.len());
    let (mut linked, mut failures) = (0, Vec::new());
    for p in programs {
        let (v, f) = (
            p["vertex"].as_u64().unwrap() as usize,
            p["fragment"].as_u64().unwrap() as usize,
        );
        let src = |i: usize| sources[i]["source"].as_str().unwrap().to_owned();
        let got = through_the_api(&mut ctx, &src(v), &src(f));
        linked += got.0 as usize;
        let what = format!("program {v}+{f} ({})", p["file"].as_str().unwrap_or(""));
        failures.extend(compare(&what, got, p));
    }
    println!(
        "webgl2fundamentals: {} programs, {linked} linked",
        programs.len()
    );
    assert!(
        failures.is_empty(),
        "{} disagreements:\n{}",
        failures.len(),
        failures.join("\n")
    );
    common::assert_clean(&ctx);
}
