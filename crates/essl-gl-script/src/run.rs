//! Running a script: "Running a script" of `docs/gl-scripts.md` step by step — the context,
//! the extensions, each call with its error, status and record checks, the picture, and the
//! timed frames.

use std::collections::HashMap;
use std::time::Instant;

use essl_gl::{gl, Context, Parameter};
use essl_scene::RgbaImage;

use crate::calls;
use crate::results::{Failure, Phase, Results};
use crate::script::{Arg, Call, Script};
use crate::value::Value;
use crate::ScriptError;

/// How to run a script.
#[derive(Clone, Debug, Default)]
pub struct ReplayOptions {
    /// Run `frame` this many more times and report the median time of one (frame plus a
    /// one-pixel read to wait for the GPU). Not for a script that waits (`until`).
    pub times: usize,
}

/// What a replay produced.
#[derive(Debug)]
pub struct Replay {
    /// Records, failures and the frame time.
    pub results: Results,
    /// The default framebuffer after `frame`, top row first.
    pub picture: RgbaImage,
    /// essl-gl's messages for the errors it recorded, with the call that caused each,
    /// to explain a failure.
    pub error_messages: Vec<String>,
}

/// A call that threw: the script stops.
struct Stop;

struct Runner<'s> {
    ctx: Context,
    script: &'s Script,
    named: HashMap<String, Value>,
    results: Results,
    error_messages: Vec<String>,
}

/// Runs `script` through a new essl-gl context.
pub fn replay(script: &Script, options: &ReplayOptions) -> Result<Replay, ScriptError> {
    let ctx = Context::with_attributes(script.width, script.height, script.context)?;
    let mut r = Runner {
        results: Results {
            renderer: format!("essl-gl on {}", ctx.adapter_info().name),
            version: essl_gl::VERSION.to_string(),
            ..Results::default()
        },
        ctx,
        script,
        named: HashMap::new(),
        error_messages: Vec::new(),
    };
    for name in &script.extensions {
        if r.ctx.get_extension(name).is_none() {
            return Err(ScriptError::Extension(name.clone()));
        }
    }
    let left = r.ctx.get_error();
    if left != gl::NO_ERROR {
        r.fail(
            Phase::Runner,
            0,
            "getContext",
            format!("{} at the start", essl_gl::error_name(left)),
        );
    }
    let ran = r
        .phase(Phase::Setup, &script.setup, true)
        .and_then(|()| r.phase(Phase::Frame, &script.frame, true));
    let picture = r.picture()?;
    if ran.is_ok() && options.times > 0 && !script.waits() {
        r.time(options.times);
    }
    // essl-gl validates every call itself: an error wgpu reported is a bug of essl-gl's,
    // and the work it rejected is missing from the results.
    for e in r.ctx.backend_errors() {
        r.fail(Phase::Runner, 0, "wgpu", e);
    }
    Ok(Replay {
        results: r.results,
        picture,
        error_messages: r.error_messages,
    })
}

impl Runner<'_> {
    fn fail(&mut self, phase: Phase, index: usize, f: &str, message: String) {
        self.results.failures.push(Failure {
            phase,
            index,
            f: f.to_string(),
            message,
        });
    }

    fn phase(&mut self, phase: Phase, calls: &[Call], checks: bool) -> Result<(), Stop> {
        for (i, call) in calls.iter().enumerate() {
            self.call(phase, i, call, checks)?;
        }
        Ok(())
    }

    /// The value an argument stands for.
    fn value(&self, arg: &Arg) -> Value {
        match arg {
            Arg::Number(n) => Value::Number(*n),
            Arg::Bool(b) => Value::Bool(*b),
            Arg::Null => Value::Null,
            Arg::Str(s) => Value::Str(s.clone()),
            Arg::Ref(name) => self.named.get(name).cloned().unwrap_or(Value::Undefined),
            Arg::Typed(a) | Arg::Out(a) => Value::Typed(a.clone()),
            Arg::List(items) => Value::List(items.iter().map(|a| self.value(a)).collect()),
        }
    }

    fn invoke(&mut self, call: &Call) -> Result<(Value, Vec<Value>), crate::CallError> {
        let mut args: Vec<Value> = call.args.iter().map(|a| self.value(a)).collect();
        let ret = calls::call(&mut self.ctx, &call.f, &mut args)?;
        Ok((ret, args))
    }

    fn call(&mut self, phase: Phase, index: usize, call: &Call, checks: bool) -> Result<(), Stop> {
        let f = call.f.as_str();
        let (mut ret, mut args) = match self.invoke(call) {
            Ok(r) => r,
            Err(e) => {
                self.fail(phase, index, f, format!("threw: {e}"));
                return Err(Stop);
            }
        };
        if let Some(until) = &call.until {
            // No event loop to return to: present (finish the GPU's work; results and fence
            // states become available) and ask once more.
            self.ctx.present();
            match self.invoke(call) {
                Ok(r) => (ret, args) = r,
                Err(e) => {
                    self.fail(phase, index, f, format!("threw: {e}"));
                    return Err(Stop);
                }
            }
            let want = self.value(until);
            if checks && ret.to_json() != want.to_json() {
                let message = format!("until {}: got {}", want.to_json(), ret.to_json());
                self.fail(phase, index, f, message);
            }
        }
        if let Some(name) = &call.keep_as {
            self.named.insert(name.clone(), ret.clone());
        }
        if !checks {
            return Ok(());
        }
        self.check_errors(phase, index, call);
        if matches!(f, "compileShader" | "linkProgram") {
            self.check_status(phase, index, call, &args);
        }
        if let Some(key) = &call.record {
            let out = call.args.iter().position(|a| matches!(a, Arg::Out(_)));
            let value = match out {
                Some(i) => args[i].to_json(),
                None => ret.to_json(),
            };
            self.results.records.push((key.clone(), value));
        }
        Ok(())
    }

    /// `getError` until `NO_ERROR` (at most 8 times): the first must be the call's `error`,
    /// and there must be no second.
    fn check_errors(&mut self, phase: Phase, index: usize, call: &Call) {
        let message = self.ctx.error_message();
        let mut errors = Vec::new();
        for _ in 0..8 {
            match self.ctx.get_error() {
                gl::NO_ERROR => break,
                e => errors.push(e),
            }
        }
        if let Some(m) = &message {
            self.error_messages
                .push(format!("{} {}: {m}", call.f, index));
        }
        let first = errors.first().copied().unwrap_or(gl::NO_ERROR);
        if first != call.error || errors.len() > 1 {
            let names: Vec<&str> = errors.iter().map(|&e| essl_gl::error_name(e)).collect();
            let got = if names.is_empty() {
                "NO_ERROR".to_string()
            } else {
                names.join(", ")
            };
            let why = message.map(|m| format!(" ({m})")).unwrap_or_default();
            let want = essl_gl::error_name(call.error);
            self.fail(
                phase,
                index,
                &call.f,
                format!("expected {want}, got {got}{why}"),
            );
        }
    }

    /// `COMPILE_STATUS` after `compileShader`, `LINK_STATUS` after `linkProgram`.
    fn check_status(&mut self, phase: Phase, index: usize, call: &Call, args: &[Value]) {
        use crate::value::Object;
        let (status, log) = match args.first() {
            Some(Value::Object(Object::Shader(s))) => (
                self.ctx.get_shader_parameter(*s, gl::COMPILE_STATUS),
                self.ctx.get_shader_info_log(*s),
            ),
            Some(Value::Object(Object::Program(p))) => (
                self.ctx.get_program_parameter(*p, gl::LINK_STATUS),
                self.ctx.get_program_info_log(*p),
            ),
            _ => return,
        };
        // A query of a deleted object leaves an error the script did not ask about.
        while self.ctx.get_error() != gl::NO_ERROR {}
        let status = status.and_then(|p| p.as_bool()).unwrap_or(false);
        if status != call.status {
            let log = log.unwrap_or_default();
            let message = format!("status {status}, expected {}: {log}", call.status);
            self.fail(phase, index, &call.f, message);
        }
    }

    /// Reads `width` × `height` of the default framebuffer as the runner does: read
    /// framebuffer and pack buffer unbound, pack parameters at their defaults, all restored.
    fn read_default(&mut self, width: u32, height: u32) -> Vec<u8> {
        const PACK: [u32; 4] = [
            gl::PACK_ALIGNMENT,
            gl::PACK_ROW_LENGTH,
            gl::PACK_SKIP_PIXELS,
            gl::PACK_SKIP_ROWS,
        ];
        let read_fb = match self.ctx.get_parameter(gl::READ_FRAMEBUFFER_BINDING) {
            Some(Parameter::Framebuffer(fb)) => fb,
            _ => None,
        };
        let pack_buffer = match self.ctx.get_parameter(gl::PIXEL_PACK_BUFFER_BINDING) {
            Some(Parameter::Buffer(b)) => b,
            _ => None,
        };
        let pack: Vec<i32> = PACK
            .iter()
            .map(|&p| {
                self.ctx
                    .get_parameter(p)
                    .and_then(|v| v.as_int())
                    .unwrap_or(0) as i32
            })
            .collect();
        self.ctx.bind_framebuffer(gl::READ_FRAMEBUFFER, None);
        self.ctx.bind_buffer(gl::PIXEL_PACK_BUFFER, None);
        for (p, v) in PACK.iter().zip([4, 0, 0, 0]) {
            self.ctx.pixel_storei(*p, v);
        }
        let mut data = vec![0u8; width as usize * height as usize * 4];
        let (w, h) = (width as i32, height as i32);
        self.ctx
            .read_pixels(0, 0, w, h, gl::RGBA, gl::UNSIGNED_BYTE, &mut data);
        self.ctx.bind_framebuffer(gl::READ_FRAMEBUFFER, read_fb);
        self.ctx.bind_buffer(gl::PIXEL_PACK_BUFFER, pack_buffer);
        for (p, v) in PACK.iter().zip(pack) {
            self.ctx.pixel_storei(*p, v);
        }
        data
    }

    fn picture(&mut self) -> Result<RgbaImage, ScriptError> {
        // Errors a stopped script left are not the read's.
        while self.ctx.get_error() != gl::NO_ERROR {}
        let (w, h) = (self.script.width, self.script.height);
        let data = self.read_default(w, h);
        let e = self.ctx.get_error();
        if e != gl::NO_ERROR {
            let message = format!("{} reading the picture", essl_gl::error_name(e));
            self.fail(Phase::Readback, 0, "readPixels", message);
        }
        RgbaImage::from_gl_rows(w, h, &data).map_err(|e| ScriptError::Malformed {
            at: "readback".into(),
            message: e.to_string(),
        })
    }

    /// Runs `frame` `times` more times, each followed by a one-pixel read; the median.
    fn time(&mut self, times: usize) {
        let script = self.script;
        let mut ms = Vec::with_capacity(times);
        for _ in 0..times {
            let start = Instant::now();
            if self.phase(Phase::Timed, &script.frame, false).is_err() {
                return;
            }
            self.read_default(1, 1);
            ms.push(start.elapsed().as_secs_f64() * 1e3);
        }
        ms.sort_by(f64::total_cmp);
        self.results.ms_per_frame = Some(ms[ms.len() / 2]);
        let expects_error = script.frame.iter().any(|c| c.error != gl::NO_ERROR);
        let e = self.ctx.get_error();
        while self.ctx.get_error() != gl::NO_ERROR {}
        if e != gl::NO_ERROR && !expects_error {
            let message = format!("{} after the timed frames", essl_gl::error_name(e));
            self.fail(Phase::Timed, 0, "frame", message);
        }
    }
}
