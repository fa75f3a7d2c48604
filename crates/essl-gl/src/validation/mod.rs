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

mod checks;
mod warning;

pub(crate) use checks::{LinkedSources, ProgramChecks};
pub(crate) use warning::Validation;
pub use warning::{SourceLocation, ValidationWarning, MAX_VALIDATION_WARNINGS};

use essl_lint::precondition::Precondition;

use crate::context::Context;
use crate::error::ContextError;
use crate::objects::{Id, Program, Shader};
use crate::program::LinkedProgram;

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
        self.validation.take()
    }

    /// How many warnings did not fit in the queue ([`MAX_VALIDATION_WARNINGS`]) since it was
    /// last read.
    pub fn validation_warnings_dropped(&self) -> u64 {
        self.validation.dropped()
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
            let checks = ProgramChecks::build(&linked.layout, linked.sources.as_deref());
            linked.checks = Some(Box::new(checks));
        }
        linked
            .checks
            .as_ref()
            .map(|c| c.preconditions().to_vec())
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
            let checks = ProgramChecks::build(&linked.layout, linked.sources.as_deref());
            linked.checks = Some(Box::new(checks));
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
        for w in found {
            self.validation.push(w);
        }
    }
}
