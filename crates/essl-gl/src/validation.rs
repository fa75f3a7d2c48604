//! The validation mode: uniform values checked against the hazards of the program.
//!
//! `essl-lint` finds, for each shader, the expressions whose result is NaN, ±∞ or undefined
//! for some uniform values — `smoothstep(u_outerLimit, u_innerLimit, d)` with equal limits,
//! `x / (u_innerLimit - u_outerLimit)`, `normalize(u_lightDirection)` of the zero vector,
//! `pow(x, u_shininess)` with `u_shininess <= 0` — and exports them as
//! [`essl_lint::Precondition`]s: conditions on the uniforms, with the span of the expression
//! at risk. With validation on ([`Context::set_validation`]), each draw evaluates the
//! conditions of the current program with the uniform values it is about to draw with, once
//! per change of those values, and queues a [`ValidationWarning`] for each that fails
//! ([`Context::take_validation_warnings`]).
//!
//! Off (the default), none of it runs: a draw tests one flag; `uniform*` is unchanged. The
//! only bookkeeping that runs either way is at `link_program`, which keeps the two shader
//! texts it linked (so that validation turned on later checks programs linked before).

use std::fmt;

use essl::program::{ProgramLayout, UniformStorage};
use essl::source::{SourceFile, Span};
use essl::types::GlType;
use essl::Stage;
use essl_lint::precondition::{Condition, Outcome, Precision, Precondition, UniformRef, Value};

use crate::context::Context;
use crate::error::ContextError;
use crate::objects::{Id, Program, Shader};
use crate::program::{find_uniform, uniform_shape, LinkedProgram};

/// The most warnings the queue holds; later ones are counted
/// ([`Context::validation_warnings_dropped`]) until it is read.
pub const MAX_VALIDATION_WARNINGS: usize = 4096;

/// The largest finite 16-bit float: what `mediump` holds on GPUs that compute it in 16 bits.
const MEDIUMP_MAX: f32 = 65504.0;

/// A place in a shader's source: the span of an expression, with its file name, 1-based line
/// and column (in characters) and the text of that line. `Display` writes `file:line:col`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SourceLocation {
    /// The shader's name: [`Context::set_shader_name`]'s, or `vertex` / `fragment`.
    pub file: String,
    /// The expression's byte range in the shader's text.
    pub span: Span,
    /// 1-based line of the span's start.
    pub line: u32,
    /// 1-based column of the span's start, in characters.
    pub column: u32,
    /// The text of that line (without its line break).
    pub source_line: String,
}

impl SourceLocation {
    fn new(file: &SourceFile, span: Span) -> SourceLocation {
        let lc = file.line_col(span.start);
        SourceLocation {
            file: file.name().to_string(),
            span,
            line: lc.line,
            column: lc.column,
            source_line: file
                .line_text(file.line_index(span.start))
                .trim_end_matches(['\r', '\n'])
                .to_string(),
        }
    }
}

impl fmt::Display for SourceLocation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}", self.file, self.line, self.column)
    }
}

/// A uniform value that makes an expression of the program NaN, infinite or undefined, found
/// by a draw with validation on.
///
/// `Display` writes it as a compiler would:
///
/// ```text
/// warning[smoothstep-edges]: `u_outerLimit` = 0.9 is not below `u_innerLimit` = 0.9 (equal): `smoothstep(edge0, edge1, x)` is undefined unless edge0 < edge1 …
///   --> spot-smooth.frag:43:19
///    |   float inLight = smoothstep(u_outerLimit, u_innerLimit, dotFromDirection);
///    = uniforms: u_outerLimit, u_innerLimit (drawElements)
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct ValidationWarning {
    /// The program drawn with.
    pub program: Program,
    /// The draw call that found it (`drawArrays`, `drawElements`, …).
    pub function: &'static str,
    /// The rule: an `essl-lint` rule id (`smoothstep-edges`, `division-by-difference`,
    /// `normalize-zero`, `pow-zero-base`, `pow-negative-base`, `acos-domain`, `asin-domain`,
    /// `mediump-overflow`) or a runtime-only one (`division-by-zero`, `non-finite-uniform`).
    pub rule: &'static str,
    /// The uniforms involved, as WebGL names them (`u_innerLimit`, `light.cutOff`,
    /// `spotLights[0].coneCos`).
    pub uniforms: Vec<String>,
    /// What is wrong, with the values, and what it does to the result.
    pub message: String,
    /// The stage of the expression at risk (`None` for a program linked from a layout, whose
    /// source essl-gl does not have).
    pub stage: Option<Stage>,
    /// The expression at risk.
    pub location: Option<SourceLocation>,
    /// The calls through which the values reach it, outermost first (a helper function's
    /// parameters).
    pub call_sites: Vec<SourceLocation>,
}

impl ValidationWarning {
    /// `file:line:col` of the expression at risk.
    pub fn position(&self) -> Option<String> {
        self.location.as_ref().map(|l| l.to_string())
    }
}

impl fmt::Display for ValidationWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "warning[{}]: {}", self.rule, self.message)?;
        if let Some(l) = &self.location {
            write!(f, "\n  --> {l}\n   | {}", l.source_line)?;
        }
        for c in &self.call_sites {
            write!(f, "\n   = via {c}: {}", c.source_line.trim())?;
        }
        write!(
            f,
            "\n   = uniforms: {} ({})",
            self.uniforms.join(", "),
            self.function
        )
    }
}

/// The context's validation settings and queue.
#[derive(Default)]
pub(crate) struct Validation {
    /// Whether draws check uniform values.
    pub(crate) enabled: bool,
    /// Whether warnings are also written to stderr.
    pub(crate) stderr: bool,
    warnings: Vec<ValidationWarning>,
    dropped: u64,
}

/// The shaders a program was linked from: (name, text) of each stage.
pub(crate) struct LinkedSources {
    pub(crate) vertex: (Option<String>, String),
    pub(crate) fragment: (Option<String>, String),
    /// The options they were compiled with.
    pub(crate) options: essl::CompileOptions,
}

/// How a uniform's value is stored in the default block image.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Slot {
    offset: u32,
    n: u8,
    kind: Kind,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    Float,
    Int,
    Uint,
}

impl Slot {
    fn of(layout: &ProgramLayout, name: &str) -> Option<Slot> {
        let (i, element) = find_uniform(layout, name)?;
        let u = &layout.uniforms[i];
        let UniformStorage::Buffer {
            offset,
            array_stride,
            ..
        } = u.storage
        else {
            return None;
        };
        let (n, matrix, boolean) = uniform_shape(u.ty);
        if matrix.is_some() {
            return None;
        }
        use GlType::*;
        let kind = match u.ty {
            _ if boolean => Kind::Uint,
            INT | INT_VEC2 | INT_VEC3 | INT_VEC4 => Kind::Int,
            UNSIGNED_INT | UNSIGNED_INT_VEC2 | UNSIGNED_INT_VEC3 | UNSIGNED_INT_VEC4 => Kind::Uint,
            FLOAT | FLOAT_VEC2 | FLOAT_VEC3 | FLOAT_VEC4 => Kind::Float,
            _ => return None,
        };
        Some(Slot {
            offset: offset + element * array_stride,
            n,
            kind,
        })
    }

    fn words<'a>(&self, data: &'a [u8]) -> &'a [u8] {
        let start = self.offset as usize;
        data.get(start..start + 4 * self.n as usize).unwrap_or(&[])
    }

    fn value(&self, data: &[u8]) -> Option<Value> {
        let bytes = self.words(data);
        if bytes.len() != 4 * self.n as usize {
            return None;
        }
        let c: Vec<f64> = bytes
            .chunks_exact(4)
            .map(|b| {
                let w = u32::from_ne_bytes([b[0], b[1], b[2], b[3]]);
                match self.kind {
                    Kind::Float => f32::from_bits(w) as f64,
                    Kind::Int => w as i32 as f64,
                    Kind::Uint => w as f64,
                }
            })
            .collect();
        Some(Value::new(&c))
    }
}

/// One precondition (one element of the arrays it indexes dynamically) with the storage of
/// its uniforms.
struct Check {
    pre: usize,
    uniforms: Vec<(UniformRef, String, Slot)>,
    location: Option<SourceLocation>,
    call_sites: Vec<SourceLocation>,
    /// The uniforms' bytes when last evaluated (empty: never).
    last: Vec<u8>,
}

/// `non-finite-uniform`: the float words of one active uniform (one array element).
struct FiniteCheck {
    name: String,
    offsets: Vec<u32>,
    stage: Option<Stage>,
    location: Option<SourceLocation>,
    /// The first read of it in `mediump`/`lowp` arithmetic, if any.
    mediump: Option<(Stage, Option<SourceLocation>)>,
    /// The words when last checked (empty: never), and whether one was not finite.
    last: Vec<u32>,
    bad: bool,
}

/// The runtime checks of a linked program.
pub(crate) struct ProgramChecks {
    preconditions: Vec<Precondition>,
    checks: Vec<Check>,
    finite: Vec<FiniteCheck>,
    /// The uniform image version last validated.
    version: Option<u64>,
}

impl ProgramChecks {
    fn build(linked: &LinkedProgram) -> ProgramChecks {
        let layout = &linked.layout;
        let mut preconditions = Vec::new();
        let mut files = Vec::new();
        if let Some(src) = &linked.sources {
            for (stage, (name, text)) in [
                (Stage::Vertex, &src.vertex),
                (Stage::Fragment, &src.fragment),
            ] {
                let name = name.clone().unwrap_or_else(|| stage.as_str().to_string());
                let shader =
                    essl::compile(SourceFile::new(name, text.as_str()), stage, &src.options);
                preconditions.extend(essl_lint::preconditions(&shader));
                files.push((stage, shader.file));
            }
        }
        let file = |stage: Stage| files.iter().find(|(s, _)| *s == stage).map(|(_, f)| f);
        let location =
            |p: &Precondition, span: Span| file(p.stage).map(|f| SourceLocation::new(f, span));
        let mut checks = Vec::new();
        for (i, p) in preconditions.iter().enumerate() {
            if matches!(p.condition, Condition::Finite(_)) {
                continue;
            }
            let refs: Vec<UniformRef> = p.uniforms().into_iter().cloned().collect();
            let instances: Vec<Option<u32>> = if p.has_any_index() {
                (0..256).map(Some).collect()
            } else {
                vec![None]
            };
            for k in instances {
                let resolved: Option<Vec<(UniformRef, String, Slot)>> = refs
                    .iter()
                    .map(|r| {
                        let name = r.name(k);
                        Slot::of(layout, &name).map(|s| (r.clone(), name, s))
                    })
                    .collect();
                let Some(uniforms) = resolved else {
                    if k.is_some_and(|k| k > 0) {
                        break;
                    }
                    continue;
                };
                checks.push(Check {
                    pre: i,
                    uniforms,
                    location: location(p, p.span),
                    call_sites: p
                        .call_sites
                        .iter()
                        .filter_map(|s| location(p, *s))
                        .collect(),
                    last: Vec::new(),
                });
            }
        }
        // Every float uniform the program uses: finite.
        let mut finite = Vec::new();
        for u in &layout.uniforms {
            let UniformStorage::Buffer {
                offset,
                array_stride,
                matrix_stride,
            } = u.storage
            else {
                continue;
            };
            let (n, matrix, _) = uniform_shape(u.ty);
            let float = matches!(
                u.ty,
                GlType::FLOAT | GlType::FLOAT_VEC2 | GlType::FLOAT_VEC3 | GlType::FLOAT_VEC4
            ) || matrix.is_some();
            if !float {
                continue;
            }
            for e in 0..u.size {
                let name = match u.name.strip_suffix("[0]") {
                    Some(base) if u.size > 1 || e > 0 => format!("{base}[{e}]"),
                    _ => u.name.clone(),
                };
                let base = offset + e * array_stride;
                let offsets: Vec<u32> = match matrix {
                    Some((cols, rows)) => (0..cols as u32)
                        .flat_map(|c| {
                            (0..rows as u32).map(move |r| base + c * matrix_stride + 4 * r)
                        })
                        .collect(),
                    None => (0..n as u32).map(|i| base + 4 * i).collect(),
                };
                // The first read of it, vertex stage first.
                let pre = [Stage::Vertex, Stage::Fragment]
                    .into_iter()
                    .find_map(|stage| {
                        preconditions.iter().find(|p| {
                            p.stage == stage
                                && matches!(&p.condition, Condition::Finite(r) if r.covers(&name))
                        })
                    });
                let mediump = preconditions
                    .iter()
                    .find(|p| {
                        p.precision == Precision::Low
                            && matches!(&p.condition, Condition::Finite(r) if r.covers(&name))
                    })
                    .map(|p| (p.stage, location(p, p.span)));
                finite.push(FiniteCheck {
                    name,
                    offsets,
                    stage: pre.map(|p| p.stage),
                    location: pre.and_then(|p| location(p, p.span)),
                    mediump,
                    last: Vec::new(),
                    bad: false,
                });
            }
        }
        ProgramChecks {
            preconditions,
            checks,
            finite,
            version: None,
        }
    }

    /// Evaluates the checks whose uniforms changed since their last evaluation.
    fn run(
        &mut self,
        data: &[u8],
        version: u64,
        program: Program,
        function: &'static str,
        out: &mut Vec<ValidationWarning>,
    ) {
        if self.version == Some(version) {
            return;
        }
        self.version = Some(version);
        let word = |o: u32| {
            data.get(o as usize..o as usize + 4)
                .map_or(0, |b| u32::from_ne_bytes([b[0], b[1], b[2], b[3]]))
        };
        let mut not_finite: Vec<&str> = Vec::new();
        for fc in &mut self.finite {
            // Unchanged since the last check: nothing new (no allocation on this path).
            let same = fc.last.len() == fc.offsets.len()
                && fc.offsets.iter().zip(&fc.last).all(|(o, w)| word(*o) == *w);
            if !same {
                fc.last.clear();
                fc.last.extend(fc.offsets.iter().map(|o| word(*o)));
                let first_bad = fc
                    .last
                    .iter()
                    .map(|w| f32::from_bits(*w))
                    .find(|x| !x.is_finite());
                fc.bad = first_bad.is_some();
                if let Some(x) = first_bad {
                    out.push(ValidationWarning {
                        program,
                        function,
                        rule: essl_lint::precondition::NON_FINITE_UNIFORM,
                        uniforms: vec![fc.name.clone()],
                        message: format!(
                            "`{}` holds {}: a NaN or infinite uniform value spreads through \
                             everything computed from it",
                            fc.name,
                            if x.is_nan() { "NaN" } else { "an infinity" }
                        ),
                        stage: fc.stage,
                        location: fc.location.clone(),
                        call_sites: Vec::new(),
                    });
                } else if let Some((stage, location)) = &fc.mediump {
                    let big = fc
                        .last
                        .iter()
                        .map(|w| f32::from_bits(*w))
                        .find(|x| x.abs() > MEDIUMP_MAX);
                    if let Some(x) = big {
                        out.push(ValidationWarning {
                            program,
                            function,
                            rule: "mediump-overflow",
                            uniforms: vec![fc.name.clone()],
                            message: format!(
                                "`{}` holds {x}, beyond the range of mediump (±65504): a GPU \
                                 that computes mediump in 16 bits reads it as infinity",
                                fc.name
                            ),
                            stage: Some(*stage),
                            location: location.clone(),
                            call_sites: Vec::new(),
                        });
                    }
                }
            }
            if fc.bad {
                not_finite.push(&fc.name);
            }
        }
        for c in &mut self.checks {
            let mut at = 0;
            let mut same = true;
            for (_, _, s) in &c.uniforms {
                let w = s.words(data);
                same &= c.last.get(at..at + w.len()) == Some(w);
                at += w.len();
            }
            if same && at == c.last.len() {
                continue;
            }
            c.last.clear();
            for (_, _, s) in &c.uniforms {
                c.last.extend_from_slice(s.words(data));
            }
            // A NaN is reported as such, not as every comparison it breaks.
            if c.uniforms
                .iter()
                .any(|(_, n, _)| not_finite.contains(&n.as_str()))
            {
                continue;
            }
            let p = &self.preconditions[c.pre];
            let outcome = p.check(&mut |r: &UniformRef| {
                c.uniforms
                    .iter()
                    .find(|(u, _, _)| u == r)
                    .and_then(|(_, _, s)| s.value(data))
            });
            let Outcome::Violated(why) = outcome else {
                continue;
            };
            let mut why = why;
            for (u, name, _) in &c.uniforms {
                let generic = u.name(None);
                if generic != *name {
                    why = why.replace(&generic, name);
                }
            }
            let unset = c
                .uniforms
                .iter()
                .all(|(_, _, s)| s.words(data).iter().all(|b| *b == 0));
            let hint = if unset {
                " (every value involved is 0: was it set?)"
            } else {
                ""
            };
            out.push(ValidationWarning {
                program,
                function,
                rule: p.rule,
                uniforms: c.uniforms.iter().map(|(_, n, _)| n.clone()).collect(),
                message: format!("{why}{hint}: {}", p.message),
                stage: Some(p.stage),
                location: c.location.clone(),
                call_sites: c.call_sites.clone(),
            });
        }
    }
}

impl Context {
    /// Creates a context ([`Context::new`]) with validation on: see
    /// [`Context::set_validation`].
    pub fn with_validation(width: u32, height: u32) -> Result<Context, ContextError> {
        let mut ctx = Context::new(width, height)?;
        ctx.set_validation(true);
        Ok(ctx)
    }

    /// Turns the validation of uniform values on or off (off by default; no WebGL
    /// implementation has it).
    ///
    /// On, every draw checks the uniform values of the current program against the hazards
    /// `essl-lint` finds in its shaders ([`essl_lint::preconditions`]): equal or swapped
    /// `smoothstep` edges, a zero divisor, the zero vector (or parallel vectors under a cross
    /// product) given to `normalize`, a `pow` exponent ≤ 0 where the base can be 0, an `acos`
    /// argument outside [-1, 1], a NaN or infinite value in any uniform, a value beyond ±65504
    /// in a uniform read in `mediump` arithmetic. Each check runs when
    /// the values it reads have changed since it last ran, so a bad value is reported once,
    /// at the first draw that uses it, not at every frame. Read the warnings with
    /// [`Context::take_validation_warnings`].
    ///
    /// The first draw of a program with validation on compiles its shaders again for the
    /// analysis (a few milliseconds). Off, draws test one flag and nothing else runs.
    pub fn set_validation(&mut self, enabled: bool) {
        self.validation.enabled = enabled;
    }

    /// Whether validation is on.
    pub fn validation_enabled(&self) -> bool {
        self.validation.enabled
    }

    /// Also writes each validation warning to stderr as it is found (off by default).
    pub fn set_validation_stderr(&mut self, enabled: bool) {
        self.validation.stderr = enabled;
    }

    /// The validation warnings found since the last call, oldest first.
    pub fn take_validation_warnings(&mut self) -> Vec<ValidationWarning> {
        self.validation.dropped = 0;
        std::mem::take(&mut self.validation.warnings)
    }

    /// How many warnings did not fit in the queue ([`MAX_VALIDATION_WARNINGS`]) since it was
    /// last read.
    pub fn validation_warnings_dropped(&self) -> u64 {
        self.validation.dropped
    }

    /// Names a shader for validation warnings (`spot.frag` in `spot.frag:43:19`); without
    /// one, a shader is `vertex` or `fragment`. An essl-gl extension, like a wgpu label: it
    /// changes nothing else. Takes effect at the next `link_program`.
    pub fn set_shader_name(&mut self, shader: Shader, name: &str) {
        if let Some(id) = self.shader_id(shader, "setShaderName") {
            if let Some(s) = self.objects.shaders.get_any_mut(id) {
                s.name = Some(name.to_owned());
            }
        }
    }

    /// The uniform preconditions of a linked program's shaders, vertex stage first (empty for
    /// a program linked from a layout): what validation checks, besides every float uniform
    /// being finite.
    pub fn program_preconditions(&mut self, program: Program) -> Vec<Precondition> {
        let Some(p) = self.program_id(program, "programPreconditions") else {
            return Vec::new();
        };
        let Some(linked) = self.objects.linked_mut(p) else {
            return Vec::new();
        };
        if linked.checks.is_none() {
            linked.checks = Some(Box::new(ProgramChecks::build(linked)));
        }
        linked
            .checks
            .as_ref()
            .map(|c| c.preconditions.clone())
            .unwrap_or_default()
    }

    /// Checks the current program's uniform values before a draw (validation on).
    pub(crate) fn validate_uniforms(&mut self, pid: Id, function: &'static str) {
        let program = Program {
            ctx: self.id,
            id: pid,
        };
        let Some(linked) = self.objects.linked_mut(pid) else {
            return;
        };
        if linked.checks.is_none() {
            linked.checks = Some(Box::new(ProgramChecks::build(linked)));
        }
        let mut found = Vec::new();
        let LinkedProgram {
            checks,
            uniform_data,
            uniform_version,
            ..
        } = linked;
        if let Some(c) = checks.as_mut() {
            c.run(
                uniform_data,
                *uniform_version,
                program,
                function,
                &mut found,
            );
        }
        let v = &mut self.validation;
        for w in found {
            if v.stderr {
                eprintln!("{w}");
            }
            if v.warnings.len() < MAX_VALIDATION_WARNINGS {
                v.warnings.push(w);
            } else {
                v.dropped += 1;
            }
        }
    }
}
