//! Query objects: `create_query`, `begin_query`, `end_query`, `get_query`,
//! `get_query_parameter`, `delete_query`, `is_query`.
//!
//! `ANY_SAMPLES_PASSED` and `ANY_SAMPLES_PASSED_CONSERVATIVE` count samples with wgpu's
//! occlusion queries, which the batch runs
//! ([`Frame::begin_occlusion`](crate::frame::Frame::begin_occlusion)): each render pass
//! recorded while the query is active counts into a slot of its own, and the result is
//! whether any slot counted a sample. A query's state is [`object`]'s.
//! `TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN` counts the primitives transform feedback wrote.
//!
//! As WebGL requires, a result becomes available only after control returns to the caller's
//! event loop, which [`Context::present`] stands for: asking before it answers `false`
//! (`QUERY_RESULT_AVAILABLE`) and 0 (`QUERY_RESULT`).

mod object;

pub(crate) use object::{Measure, QueryObject};

use crate::context::Context;
use crate::gl;
use crate::objects::{Id, Query};
use crate::query::Parameter;

/// The binding slot of a query target: occlusion (both kinds share one) or primitives.
fn slot(target: u32) -> Option<usize> {
    match target {
        gl::ANY_SAMPLES_PASSED | gl::ANY_SAMPLES_PASSED_CONSERVATIVE => Some(0),
        gl::TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN => Some(1),
        _ => None,
    }
}

impl Context {
    /// Creates a query object (`createQuery`).
    pub fn create_query(&mut self) -> Query {
        Query {
            ctx: self.id,
            id: self.objects.queries.insert(QueryObject::default()),
        }
    }

    /// Whether `query` names a live query that was begun once (`isQuery`).
    pub fn is_query(&self, query: Query) -> bool {
        query.ctx == self.id
            && self
                .objects
                .queries
                .get(query.id)
                .is_some_and(|q| q.target.is_some())
    }

    /// Deletes a query (`deleteQuery`); an active one is ended first.
    pub fn delete_query(&mut self, query: Query) {
        if !self.owns(query.ctx, "deleteQuery") || !self.objects.queries.is_live(query.id) {
            return;
        }
        for target in [
            gl::ANY_SAMPLES_PASSED,
            gl::TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN,
        ] {
            if self.bindings.query(slot(target).expect("a query target")) == Some(query.id) {
                self.finish_query(target);
            }
        }
        self.objects.delete_query(query.id);
    }

    /// Starts measuring (`beginQuery`): `ANY_SAMPLES_PASSED`,
    /// `ANY_SAMPLES_PASSED_CONSERVATIVE` or `TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN`. A
    /// query of the same kind already active, a query already active, or one begun before
    /// with another target → `INVALID_OPERATION`.
    pub fn begin_query(&mut self, target: u32, query: Query) {
        const F: &str = "beginQuery";
        let Some(s) = slot(target) else {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        };
        if !self.owns(query.ctx, F) {
            return;
        }
        let Some(q) = self.objects.queries.get(query.id) else {
            return self.error(gl::INVALID_OPERATION, F, "deleted query");
        };
        if q.target.is_some_and(|t| slot(t) != Some(s) || t != target) {
            return self.error(
                gl::INVALID_OPERATION,
                F,
                "the query was begun with another target",
            );
        }
        if self.bindings.query(s).is_some() {
            return self.error(gl::INVALID_OPERATION, F, "a query of that kind is active");
        }
        if self.bindings.query(1 - s) == Some(query.id) {
            return self.error(gl::INVALID_OPERATION, F, "the query is active");
        }
        let q = self.objects.queries.get_mut(query.id).expect("checked");
        q.target = Some(target);
        q.ended = None;
        q.result = None;
        q.primitives = 0;
        self.bindings.begin_query(s, Some(query.id));
        if s == 0 {
            self.frame.begin_occlusion(&self.gpu);
        }
    }

    /// Stops measuring (`endQuery`); no active query of `target`'s kind →
    /// `INVALID_OPERATION`.
    pub fn end_query(&mut self, target: u32) {
        const F: &str = "endQuery";
        let Some(s) = slot(target) else {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        };
        match self.bindings.query(s) {
            Some(id) if self.objects.queries.get_any(id).and_then(|q| q.target) == Some(target) => {
                self.finish_query(target)
            }
            _ => self.error(gl::INVALID_OPERATION, F, "no active query of that target"),
        }
    }

    /// Ends the active query of `target`'s kind.
    fn finish_query(&mut self, target: u32) {
        let s = slot(target).expect("a query target");
        let Some(id) = self.bindings.query(s) else {
            return;
        };
        self.bindings.begin_query(s, None);
        let measure = if s == 0 {
            Measure::Samples(self.frame.end_occlusion(&self.gpu))
        } else {
            Measure::Primitives(self.objects.queries.get_any(id).map_or(0, |q| q.primitives))
        };
        let frames = self.presents;
        if let Some(q) = self.objects.queries.get_any_mut(id) {
            q.ended = Some((measure, frames));
        }
    }

    /// The active query of a target (`getQuery(target, CURRENT_QUERY)`).
    pub fn get_query(&self, target: u32, pname: u32) -> Option<Query> {
        const F: &str = "getQuery";
        let Some(s) = slot(target) else {
            self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
            return None;
        };
        if pname != gl::CURRENT_QUERY {
            self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
            return None;
        }
        let id = self.bindings.query(s)?;
        (self.objects.queries.get_any(id)?.target == Some(target))
            .then_some(Query { ctx: self.id, id })
    }

    /// A query's result (`getQueryParameter`): `QUERY_RESULT_AVAILABLE`
    /// ([`Parameter::Bool`]) and `QUERY_RESULT` ([`Parameter::Int`]; a boolean 0/1 for the
    /// sample queries). Both wait for a [`Context::present`] after `end_query`; an active
    /// query, or one never ended → `INVALID_OPERATION`.
    pub fn get_query_parameter(&mut self, query: Query, pname: u32) -> Option<Parameter> {
        const F: &str = "getQueryParameter";
        if !self.owns(query.ctx, F) {
            return None;
        }
        if !matches!(pname, gl::QUERY_RESULT | gl::QUERY_RESULT_AVAILABLE) {
            self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
            return None;
        }
        if self.bindings.query(0) == Some(query.id) || self.bindings.query(1) == Some(query.id) {
            self.error(gl::INVALID_OPERATION, F, "the query is active");
            return None;
        }
        let Some(q) = self.objects.queries.get(query.id) else {
            self.error(gl::INVALID_OPERATION, F, "deleted query");
            return None;
        };
        let Some((_, ended_at)) = &q.ended else {
            self.error(gl::INVALID_OPERATION, F, "the query was never ended");
            return None;
        };
        let available = self.presents > *ended_at;
        if pname == gl::QUERY_RESULT_AVAILABLE {
            return Some(Parameter::Bool(available));
        }
        if !available {
            return Some(Parameter::Int(0));
        }
        Some(Parameter::Int(self.query_result(query.id) as i64))
    }

    /// Reads (once) what an ended query measured.
    fn query_result(&mut self, id: Id) -> u64 {
        let Some(q) = self.objects.queries.get_any(id) else {
            return 0;
        };
        if let Some(r) = q.result {
            return r;
        }
        let result = match &q.ended {
            Some((Measure::Primitives(n), _)) => *n,
            Some((Measure::Samples(counts), _)) => self.frame.any_samples(&self.gpu, counts) as u64,
            None => 0,
        };
        if let Some(q) = self.objects.queries.get_any_mut(id) {
            q.result = Some(result);
        }
        result
    }
}
