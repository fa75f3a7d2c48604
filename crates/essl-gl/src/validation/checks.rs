//! A linked program's runtime checks: built from the shaders it was linked from
//! ([`LinkedSources`]) and the layout of its uniforms, evaluated on its default uniform
//! block's image ([`ProgramChecks::run`]).

use essl::program::{ProgramLayout, UniformStorage};
use essl::source::{SourceFile, Span};
use essl::types::GlType;
use essl::Stage;
use essl_lint::precondition::{Condition, Outcome, Precision, Precondition, UniformRef, Value};

use super::warning::{SourceLocation, ValidationWarning};
use crate::objects::Program;
use crate::program::{find_uniform, uniform_shape};

/// The largest finite 16-bit float: what `mediump` holds on GPUs that compute it in 16 bits.
const MEDIUMP_MAX: f32 = 65504.0;

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
    /// The uniform preconditions of the shaders, vertex stage first.
    pub(crate) fn preconditions(&self) -> &[Precondition] {
        &self.preconditions
    }

    /// The checks of a program with `layout`, linked from `sources` (`None`: a layout linked
    /// directly, which has only the finiteness checks).
    pub(crate) fn build(layout: &ProgramLayout, sources: Option<&LinkedSources>) -> ProgramChecks {
        let mut preconditions = Vec::new();
        let mut files = Vec::new();
        if let Some(src) = sources {
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
    pub(crate) fn run(
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
