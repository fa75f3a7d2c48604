//! `minify(source, options)`: the shader checked as `check` checks it, then, when it has no
//! errors, minified by [`essl_check::minify`] (comments and white space gone, local names
//! shortened, the output compiled again and compared with the original). JSON of the check's
//! result with `text` (the minified text, or `null` for a shader with errors) and `renamed`.

use napi::bindgen_prelude::AsyncTask;
use napi::{Env, Error, Status, Task};
use napi_derive::napi;
use serde_json::{json, Map, Value};

use crate::{guarded, options, report, type_error, Answer, Answered};

/// `minify(source, options)`: JSON of `{shaders, programs, errors, warnings, text, renamed}`,
/// with the diagnostics' texts as `check` answers them.
#[napi(js_name = "minifyJson")]
pub fn minify_json(source: String, options: String, rename: bool) -> napi::Result<Answered> {
    minify_text_json(source, options, rename).map(Answer::new)
}

/// [`minify_json`] on a thread of Node's pool: a promise of the same JSON.
#[napi(js_name = "minifyJsonAsync")]
pub fn minify_json_async(source: String, options: String, rename: bool) -> AsyncTask<MinifyTask> {
    AsyncTask::new(MinifyTask {
        source,
        options,
        rename,
    })
}

/// The work of [`minify_json_async`].
pub struct MinifyTask {
    source: String,
    options: String,
    rename: bool,
}

impl Task for MinifyTask {
    type Output = (String, report::Rendering);
    type JsValue = Answered;

    fn compute(&mut self) -> napi::Result<Self::Output> {
        minify_text_json(
            std::mem::take(&mut self.source),
            std::mem::take(&mut self.options),
            self.rename,
        )
    }

    fn resolve(&mut self, _env: Env, output: Self::Output) -> napi::Result<Answered> {
        Ok(Answer::new(output))
    }
}

fn minify_text_json(
    source: String,
    options: String,
    rename: bool,
) -> napi::Result<(String, report::Rendering)> {
    guarded("minify", || {
        let opts = options::read(&options, "shader.glsl").map_err(|e| type_error(e.0))?;
        let given = source.clone();
        let unit = crate::check_one(source, &opts)?;
        let [shader] = unit.shaders.as_slice() else {
            return Err(type_error(format!(
                "minify takes one shader's text; {} holds {} shaders",
                opts.filename.display(),
                unit.shaders.len()
            )));
        };
        if shader.embedded_at.is_some() {
            return Err(type_error(
                "minify takes a shader's text, not a JS/TS or HTML module's",
            ));
        }
        let mut rendering = report::Rendering::default();
        let mut out = serde_json::to_value(report::unit(&unit, Some(&given), &mut rendering))
            .map_err(|e| Error::new(Status::GenericFailure, e.to_string()))?;
        let errors = out["errors"].as_u64().unwrap_or(0)
            + if opts.overrides.deny_warnings {
                out["warnings"].as_u64().unwrap_or(0)
            } else {
                0
            };
        out["errors"] = json!(errors);
        if errors > 0 {
            out["text"] = Value::Null;
            out["renamed"] = json!({});
            return Ok((out.to_string(), rendering));
        }
        let m = essl_check::minify(shader, rename).map_err(|e| match e {
            essl_check::MinifyError::Preset(_) => type_error(format!("essl: {e}")),
            _ => Error::new(Status::GenericFailure, format!("essl: {e}")),
        })?;
        let renamed: Map<String, Value> =
            m.renamed.into_iter().map(|(a, b)| (a, json!(b))).collect();
        out["text"] = json!(m.text);
        out["renamed"] = Value::Object(renamed);
        Ok((out.to_string(), rendering))
    })
}
