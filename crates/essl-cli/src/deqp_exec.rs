//! Executing the dEQP value cases through essl-gl, call for call as
//! `../shared/tools/deqp-exec-oracle.py` does in Chromium (the corpora README's "Executing"
//! section, after dEQP's `glsShaderLibraryCase.execute`), with the same output: one JSON line
//! per case, `{"name", "ok", "why"}`, then `{"total", "ok"}`. The two outputs can be compared
//! line by line.
//!
//! For each `300 es` case that must pass and has values: compile and link through the API
//! (a failure is `"compile"` or `"link"`); then for each value block and each of its sub-cases,
//! on a 128×128 viewport: `dEQP_Position` gets the quad's four corners, each `input` its
//! sub-case's scalars on all four vertices (a `FLOAT` attribute named `a_NAME` for a
//! fragment-only case or a value that is not float-based, else `NAME`; a matrix takes one
//! location per column), each `output` goes to uniform `ref_NAME` and each `uniform` to `NAME`;
//! then a clear to (0.125, 0.25, 0.5, 1), two triangles, and `readPixels`. A sub-case passes when
//! every pixel of the interior (1..=127 on both axes) is white.

use std::io::Write;
use std::path::Path;
use std::time::Instant;

use essl_gl::{gl, Context, Parameter, Program};
use serde::Deserialize;
use serde_json::json;

/// The viewport's side in pixels.
const SIZE: i32 = 128;

/// One case of `deqp_gles3.jsonl` (the fields the runner reads).
#[derive(Debug, Deserialize)]
pub struct Case {
    /// The case's full name.
    pub name: String,
    /// `pass`, `compile_fail`, …
    pub expect: String,
    /// `vertex_only`, `fragment_only` or `complete`.
    #[serde(default)]
    pub case_type: Option<String>,
    /// `300 es` or `100`.
    #[serde(default)]
    pub version: Option<String>,
    /// The vertex shader.
    #[serde(default)]
    pub vertex_source: Option<String>,
    /// The fragment shader.
    #[serde(default)]
    pub fragment_source: Option<String>,
    /// The value blocks.
    #[serde(default)]
    pub values: Option<Vec<Block>>,
}

/// A value block: `array_length` sub-cases.
#[derive(Debug, Deserialize)]
pub struct Block {
    /// The number of sub-cases (0 counts as 1).
    pub array_length: usize,
    /// Its values.
    pub values: Vec<Value>,
}

/// One input, output or uniform of a block.
#[derive(Debug, Deserialize)]
pub struct Value {
    /// `input`, `output` or `uniform`.
    pub storage: String,
    /// The GLSL name.
    pub name: String,
    /// The GLSL type (`float`, `ivec3`, `mat2x3`, `bool`…).
    #[serde(rename = "type")]
    pub ty: String,
    /// 1: the same scalars in every sub-case.
    pub array_length: usize,
    /// The scalars of every sub-case, one after another.
    pub elements: Vec<f64>,
}

impl Case {
    /// Whether the runner executes it: a `300 es` case that must pass and has values.
    pub fn executed(&self) -> bool {
        self.values.as_ref().is_some_and(|v| !v.is_empty())
            && self.version.as_deref() == Some("300 es")
            && self.expect == "pass"
    }
}

/// `(columns, rows)` of a matrix type.
fn matrix(ty: &str) -> Option<(usize, usize)> {
    let rest = ty.strip_prefix("mat")?;
    let digit = |s: &str| s.parse::<usize>().ok().filter(|n| (2..=4).contains(n));
    match rest.split_once('x') {
        Some((c, r)) => Some((digit(c)?, digit(r)?)),
        None => digit(rest).map(|n| (n, n)),
    }
}

/// The number of scalars of a type.
fn scalar_count(ty: &str) -> usize {
    if let Some((c, r)) = matrix(ty) {
        return c * r;
    }
    ty.rsplit_once("vec")
        .and_then(|(_, n)| n.parse().ok())
        .unwrap_or(1)
}

fn float_based(ty: &str) -> bool {
    ty.starts_with("float") || ty.starts_with("vec") || ty.starts_with("mat")
}

impl Value {
    /// The scalars of sub-case `sub`.
    fn scalars(&self, sub: usize) -> &[f64] {
        let n = scalar_count(&self.ty);
        let at = if self.array_length == 1 { 0 } else { sub * n };
        self.elements.get(at..at + n).unwrap_or(&[])
    }
}

/// The outcome of one case.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Outcome {
    /// The case's name.
    pub name: String,
    /// Whether it passed.
    pub ok: bool,
    /// Why not: `compile`, `link`, `no dEQP_Position` or `pixels (block B, sub-case S)`.
    pub why: Option<String>,
}

/// Runs the cases on one context.
pub struct Runner {
    gl: Context,
    pixels: Vec<u8>,
}

impl Runner {
    /// A 128×128 context.
    pub fn new() -> Result<Runner, essl_gl::ContextError> {
        Ok(Runner {
            gl: Context::new(SIZE as u32, SIZE as u32)?,
            pixels: vec![0; (SIZE * SIZE * 4) as usize],
        })
    }

    /// [`Runner::via_wgsl`] if `via_wgsl`, else [`Runner::new`].
    pub fn with(via_wgsl: bool) -> Result<Runner, essl_gl::ContextError> {
        if via_wgsl {
            Runner::via_wgsl()
        } else {
            Runner::new()
        }
    }

    /// A 128×128 context that runs every program from its WGSL translation, read back by
    /// naga's WGSL front end ([`essl_translate::roundtrip::through_wgsl`]).
    pub fn via_wgsl() -> Result<Runner, essl_gl::ContextError> {
        let mut runner = Runner::new()?;
        let options = essl_translate::Options::default();
        runner.gl.set_program_filter(Some(Box::new(move |layout| {
            essl_translate::roundtrip::through_wgsl(layout, &options).map_err(|e| e.to_string())
        })));
        Ok(runner)
    }

    fn compile(&mut self, ty: u32, source: &str) -> Option<essl_gl::Shader> {
        let gl = &mut self.gl;
        let shader = gl.create_shader(ty)?;
        gl.shader_source(shader, source);
        gl.compile_shader(shader);
        if gl.get_shader_parameter(shader, gl::COMPILE_STATUS) == Some(Parameter::Bool(true)) {
            Some(shader)
        } else {
            gl.delete_shader(shader);
            None
        }
    }

    /// Runs one case.
    pub fn run(&mut self, case: &Case) -> Outcome {
        let mut outcome = Outcome {
            name: case.name.clone(),
            ok: false,
            why: None,
        };
        let vs = self.compile(
            gl::VERTEX_SHADER,
            case.vertex_source.as_deref().unwrap_or(""),
        );
        let fs = self.compile(
            gl::FRAGMENT_SHADER,
            case.fragment_source.as_deref().unwrap_or(""),
        );
        let (Some(vs), Some(fs)) = (vs, fs) else {
            for s in [vs, fs].into_iter().flatten() {
                self.gl.delete_shader(s);
            }
            outcome.why = Some("compile".into());
            return outcome;
        };
        let gl = &mut self.gl;
        let program = gl.create_program();
        gl.attach_shader(program, vs);
        gl.attach_shader(program, fs);
        gl.link_program(program);
        if gl.get_program_parameter(program, gl::LINK_STATUS) != Some(Parameter::Bool(true)) {
            outcome.why = Some("link".into());
        } else {
            match self.draw_all(case, program) {
                Ok(()) => outcome.ok = true,
                Err(why) => outcome.why = Some(why),
            }
        }
        let gl = &mut self.gl;
        gl.delete_program(program);
        gl.delete_shader(vs);
        gl.delete_shader(fs);
        outcome
    }

    /// Draws every sub-case of every block; the first failure's reason.
    fn draw_all(&mut self, case: &Case, program: Program) -> Result<(), String> {
        self.gl.viewport(0, 0, SIZE, SIZE);
        self.gl.use_program(Some(program));
        let position = self.gl.get_attrib_location(program, "dEQP_Position");
        if position < 0 {
            return Err("no dEQP_Position".into());
        }
        let fragment_only = case.case_type.as_deref() == Some("fragment_only");
        for (b, block) in case.values.iter().flatten().enumerate() {
            for sub in 0..block.array_length.max(1) {
                if !self.draw_one(program, position as u32, block, sub, fragment_only) {
                    return Err(format!("pixels (block {b}, sub-case {sub})"));
                }
            }
        }
        Ok(())
    }

    /// One sub-case: whether the interior is white.
    fn draw_one(
        &mut self,
        program: Program,
        position: u32,
        block: &Block,
        sub: usize,
        fragment_only: bool,
    ) -> bool {
        const CORNERS: [f32; 16] = [
            -1.0, -1.0, 0.0, 1.0, -1.0, 1.0, 0.0, 1.0, 1.0, -1.0, 0.0, 1.0, 1.0, 1.0, 0.0, 1.0,
        ];
        const INDICES: [u16; 6] = [0, 1, 2, 1, 3, 2];
        let gl = &mut self.gl;
        let vao = gl.create_vertex_array();
        gl.bind_vertex_array(Some(vao));
        let mut buffers = Vec::new();
        let mut attribute =
            |gl: &mut Context, location: u32, size: i32, data: &[f32], stride: i32, offset: i64| {
                let buffer = gl.create_buffer();
                buffers.push(buffer);
                gl.bind_buffer(gl::ARRAY_BUFFER, Some(buffer));
                gl.buffer_data(gl::ARRAY_BUFFER, data, gl::STATIC_DRAW);
                gl.enable_vertex_attrib_array(location);
                gl.vertex_attrib_pointer(location, size, gl::FLOAT, false, stride, offset);
            };
        attribute(gl, position, 4, &CORNERS, 0, 0);
        for v in block.values.iter().filter(|v| v.storage == "input") {
            let scalars = v.scalars(sub);
            let n = scalar_count(&v.ty);
            let data: Vec<f32> = (0..4)
                .flat_map(|_| (0..n).map(|j| scalars.get(j).copied().unwrap_or(0.0) as f32))
                .collect();
            let prefix = if fragment_only || !float_based(&v.ty) {
                "a_"
            } else {
                ""
            };
            let location = gl.get_attrib_location(program, &format!("{prefix}{}", v.name));
            if location < 0 {
                continue;
            }
            match matrix(&v.ty) {
                Some((cols, rows)) => {
                    for c in 0..cols {
                        let offset = (c * rows * 4) as i64;
                        let location = location as u32 + c as u32;
                        attribute(gl, location, rows as i32, &data, (n * 4) as i32, offset);
                    }
                }
                None => attribute(gl, location as u32, n as i32, &data, 0, 0),
            }
        }
        for v in &block.values {
            let name = match v.storage.as_str() {
                "output" => format!("ref_{}", v.name),
                "uniform" => v.name.clone(),
                _ => continue,
            };
            set_uniform(gl, program, &name, v, sub);
        }
        let index_buffer = gl.create_buffer();
        gl.bind_buffer(gl::ELEMENT_ARRAY_BUFFER, Some(index_buffer));
        gl.buffer_data(gl::ELEMENT_ARRAY_BUFFER, &INDICES, gl::STATIC_DRAW);
        gl.clear_color(0.125, 0.25, 0.5, 1.0);
        gl.clear(gl::COLOR_BUFFER_BIT);
        gl.draw_elements(gl::TRIANGLES, 6, gl::UNSIGNED_SHORT, 0);
        gl.read_pixels(
            0,
            0,
            SIZE,
            SIZE,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            &mut self.pixels,
        );
        let white = (1..SIZE as usize).all(|y| {
            (1..SIZE as usize).all(|x| {
                let i = (y * SIZE as usize + x) * 4;
                self.pixels[i..i + 3] == [255, 255, 255]
            })
        });
        let gl = &mut self.gl;
        gl.bind_vertex_array(None);
        gl.delete_vertex_array(vao);
        for b in buffers {
            gl.delete_buffer(b);
        }
        gl.delete_buffer(index_buffer);
        white
    }

    /// The context (to read its error state).
    pub fn context(&mut self) -> &mut Context {
        &mut self.gl
    }
}

/// Sets a uniform from a value's sub-case, with the call its type takes (none when the name has
/// no location).
fn set_uniform(gl: &mut Context, program: Program, name: &str, v: &Value, sub: usize) {
    let Some(location) = gl.get_uniform_location(program, name) else {
        return;
    };
    let location = Some(location);
    let e = v.scalars(sub);
    let t = v.ty.as_str();
    if let Some((c, r)) = matrix(t) {
        let f: Vec<f32> = e.iter().map(|&x| x as f32).collect();
        match (c, r) {
            (2, 2) => gl.uniform_matrix2fv(location, false, &f),
            (3, 3) => gl.uniform_matrix3fv(location, false, &f),
            (4, 4) => gl.uniform_matrix4fv(location, false, &f),
            (2, 3) => gl.uniform_matrix2x3fv(location, false, &f),
            (2, 4) => gl.uniform_matrix2x4fv(location, false, &f),
            (3, 2) => gl.uniform_matrix3x2fv(location, false, &f),
            (3, 4) => gl.uniform_matrix3x4fv(location, false, &f),
            (4, 2) => gl.uniform_matrix4x2fv(location, false, &f),
            _ => gl.uniform_matrix4x3fv(location, false, &f),
        }
        return;
    }
    let n = scalar_count(t);
    if t.starts_with("float") || t.starts_with("vec") {
        let f: Vec<f32> = e.iter().map(|&x| x as f32).collect();
        match n {
            1 => gl.uniform1fv(location, &f),
            2 => gl.uniform2fv(location, &f),
            3 => gl.uniform3fv(location, &f),
            _ => gl.uniform4fv(location, &f),
        }
    } else if t.starts_with("uint") || t.starts_with("uvec") {
        // JavaScript's Uint32Array conversion: modulo 2^32.
        let u: Vec<u32> = e.iter().map(|&x| x as i64 as u32).collect();
        match n {
            1 => gl.uniform1uiv(location, &u),
            2 => gl.uniform2uiv(location, &u),
            3 => gl.uniform3uiv(location, &u),
            _ => gl.uniform4uiv(location, &u),
        }
    } else {
        let i: Vec<i32> = e.iter().map(|&x| x as i64 as i32).collect();
        match n {
            1 => gl.uniform1iv(location, &i),
            2 => gl.uniform2iv(location, &i),
            3 => gl.uniform3iv(location, &i),
            _ => gl.uniform4iv(location, &i),
        }
    }
}

/// Reads the corpus' executed cases, those whose name contains `only` if given.
pub fn read_cases(corpus: &Path, only: Option<&str>) -> Result<Vec<Case>, String> {
    let text = std::fs::read_to_string(corpus)
        .map_err(|e| format!("{}: {}", corpus.display(), essl_check::io_message(&e)))?;
    let mut cases = Vec::new();
    for (i, line) in text.lines().enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let case: Case = serde_json::from_str(line)
            .map_err(|e| format!("{}: line {}: {e}", corpus.display(), i + 1))?;
        if case.executed() && only.is_none_or(|o| case.name.contains(o)) {
            cases.push(case);
        }
    }
    Ok(cases)
}

/// `essl deqp-exec`: runs the cases (from their WGSL translation if `via_wgsl`), writes the
/// JSON lines to `out` (or standard output),
/// prints the totals and the time to standard error. Exit status 0 when all pass, 1 when some
/// fail, 2 when the corpus cannot be read or no context can be made.
pub fn run(corpus: &Path, only: Option<&str>, out: Option<&Path>, via_wgsl: bool) -> i32 {
    let cases = match read_cases(corpus, only) {
        Ok(c) => c,
        Err(e) => {
            eprintln!("error: {e}");
            return 2;
        }
    };
    let mut runner = match Runner::with(via_wgsl) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("error: no WebGL2 context: {e}");
            return 2;
        }
    };
    let start = Instant::now();
    let mut text = String::new();
    let mut passed = 0;
    for case in &cases {
        let o = runner.run(case);
        passed += o.ok as usize;
        text.push_str(&json!({"name": o.name, "ok": o.ok, "why": o.why}).to_string());
        text.push('\n');
    }
    text.push_str(&json!({"total": cases.len(), "ok": passed}).to_string());
    text.push('\n');
    let seconds = start.elapsed().as_secs_f64();
    let written = match out {
        Some(path) => std::fs::write(path, &text),
        None => std::io::stdout().write_all(text.as_bytes()),
    };
    if let Err(e) = written {
        eprintln!(
            "error: cannot write the results: {}",
            essl_check::io_message(&e)
        );
        return 2;
    }
    eprintln!(
        "essl deqp-exec: {passed}/{} cases pass ({seconds:.1} s on {})",
        cases.len(),
        runner.gl.adapter_info().name
    );
    i32::from(passed != cases.len())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn type_shapes() {
        assert_eq!(matrix("mat3"), Some((3, 3)));
        assert_eq!(matrix("mat2x4"), Some((2, 4)));
        assert_eq!(matrix("vec3"), None);
        assert_eq!(scalar_count("mat4x3"), 12);
        assert_eq!(scalar_count("bvec2"), 2);
        assert_eq!(scalar_count("uint"), 1);
        assert!(float_based("mat2") && !float_based("ivec2") && !float_based("bool"));
    }

    #[test]
    fn sub_cases_share_a_value_of_length_one() {
        let v = Value {
            storage: "uniform".into(),
            name: "u".into(),
            ty: "vec2".into(),
            array_length: 1,
            elements: vec![1.0, 2.0],
        };
        assert_eq!(v.scalars(3), &[1.0, 2.0]);
        let w = Value {
            array_length: 2,
            elements: vec![1.0, 2.0, 3.0, 4.0],
            ..v
        };
        assert_eq!(w.scalars(1), &[3.0, 4.0]);
    }
}
