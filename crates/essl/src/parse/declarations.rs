//! Declarations: the translation unit and its external declarations, function definitions
//! and their parameters, `precision` and `invariant` statements, uniform blocks and
//! declarator lists, and the look-ahead that tells a declaration from an expression.

use super::types::{is_qualifier_kw, type_keyword};
use super::{Failed, PResult, Parser};
use crate::ast::*;
use crate::diagnostic::{Diagnostic, Fix};
use crate::diagnostic_code::Code;
use crate::lex::Punct;
use crate::source::Span;
use crate::token::{Kw, Tok};
use crate::types::Precision;

impl Parser<'_> {
    pub(super) fn translation_unit(&mut self) -> TranslationUnit {
        let mut unit = TranslationUnit::default();
        while !self.at_eof() {
            let start = self.pos;
            match self.external() {
                Ok(Some(item)) => unit.items.push(item),
                Ok(None) => {}
                Err(Failed) => self.synchronize(),
            }
            if self.pos == start && !self.at_eof() {
                // Never loop without progress.
                let t = self.peek().clone();
                self.report(
                    Diagnostic::error(
                        Code::SyntaxError,
                        format!("unexpected {}", Self::describe(&t)),
                        t.span,
                    )
                    .with_label("not expected here")
                    .with_token(&*t.text),
                );
                self.advance();
                self.synchronize();
            }
        }
        unit
    }

    fn external(&mut self) -> PResult<Option<ExternalDecl>> {
        if self.at(Punct::Semicolon) {
            let s = self.bump_span();
            self.report(
                Diagnostic::error(Code::SyntaxError, "unexpected `;` at global scope", s)
                    .with_label("an empty declaration")
                    .with_fix(Fix::certain("remove it", s, ""))
                    .with_token(";"),
            );
            self.suppress = false;
            return Ok(None);
        }
        if self.at(Punct::RightBrace) {
            let s = self.bump_span();
            self.report(
                Diagnostic::error(Code::SyntaxError, "unmatched `}`", s)
                    .with_label("no block to close here")
                    .with_token("}"),
            );
            self.suppress = false;
            return Ok(None);
        }
        let start = self.peek().span;
        if self.at_kw(Kw::Precision) {
            return Ok(Some(ExternalDecl::Declaration(self.precision_statement()?)));
        }
        if self.at_kw(Kw::Invariant) && matches!(self.peek_at(1).tok, Tok::Ident) {
            return Ok(Some(ExternalDecl::Declaration(self.invariant_statement()?)));
        }
        let qualifiers = self.qualifiers()?;
        // Interface block: `uniform Name {`.
        if !qualifiers.is_empty() {
            if *self.tok() == Tok::Ident
                && matches!(self.peek_at(1).tok, Tok::P(Punct::LeftBrace))
                && !self.is_type_name(&self.peek().text)
            {
                return Ok(Some(ExternalDecl::Declaration(
                    self.block(qualifiers, start)?,
                )));
            }
            if self.at(Punct::Semicolon) {
                self.advance();
                return Ok(Some(ExternalDecl::Declaration(Declaration::Qualifiers {
                    qualifiers,
                    span: self.span_from(start),
                })));
            }
        }
        let spec = self.type_spec()?;
        let ty = FullType {
            span: start.to(spec.span),
            qualifiers,
            spec,
        };
        if let Tok::Ident | Tok::Reserved = self.tok() {
            if matches!(self.peek_at(1).tok, Tok::P(Punct::LeftParen)) {
                let name = self.ident("a function name")?;
                return self.function(ty, name, start).map(Some);
            }
        }
        let decl = self.declarators(ty, start)?;
        Ok(Some(ExternalDecl::Declaration(decl)))
    }

    fn precision_statement(&mut self) -> PResult<Declaration> {
        let start = self.bump_span();
        let precision = match self.tok() {
            Tok::Kw(Kw::Lowp) => Precision::Low,
            Tok::Kw(Kw::Mediump) => Precision::Medium,
            Tok::Kw(Kw::Highp) => Precision::High,
            _ => return Err(self.expected("`lowp`, `mediump` or `highp`")),
        };
        self.advance();
        let ty = self.type_spec()?;
        self.expect_semicolon("the `precision` statement")?;
        Ok(Declaration::Precision {
            precision,
            ty,
            span: self.span_from(start),
        })
    }

    fn invariant_statement(&mut self) -> PResult<Declaration> {
        let start = self.bump_span();
        let mut names = vec![self.ident("a variable name")?];
        while self.eat(Punct::Comma) {
            names.push(self.ident("a variable name")?);
        }
        self.expect_semicolon("the `invariant` declaration")?;
        Ok(Declaration::Invariant {
            names,
            span: self.span_from(start),
        })
    }

    fn block(&mut self, qualifiers: Vec<(Qualifier, Span)>, start: Span) -> PResult<Declaration> {
        let name = self.ident("a block name")?;
        let open = self.expect(Punct::LeftBrace)?;
        let members = self.member_list(open)?;
        let instance = match self.tok() {
            Tok::Ident | Tok::Reserved => {
                let n = self.ident("an instance name")?;
                let a = if self.at(Punct::LeftBracket) {
                    Some(self.array_size()?)
                } else {
                    None
                };
                Some((n, a))
            }
            _ => None,
        };
        self.expect_semicolon("the uniform block")?;
        Ok(Declaration::Block {
            qualifiers,
            name,
            members,
            instance,
            span: self.span_from(start),
        })
    }

    /// `name [array] [= init], …;` after a type; an empty list declares only a struct. The
    /// grammar lets the list start with an empty declarator: `float, a;` declares `a`.
    fn declarators(&mut self, ty: FullType, start: Span) -> PResult<Declaration> {
        let mut declarators = Vec::new();
        if self.at(Punct::Comma) && matches!(self.peek_at(1).tok, Tok::Ident) {
            self.advance();
        }
        if !self.at(Punct::Semicolon) {
            loop {
                let name = self.ident("a variable name")?;
                let array = if self.at(Punct::LeftBracket) {
                    Some(self.array_size()?)
                } else {
                    None
                };
                let init = if self.eat(Punct::Equal) {
                    match self.assignment() {
                        Ok(e) => Some(e),
                        Err(Failed) => {
                            // Keep the variable, so later uses of it are not reported as
                            // undeclared (no cascade), and skip the rest of the statement.
                            let span = self.span_from(name.span);
                            declarators.push(Declarator {
                                span,
                                name,
                                array,
                                init: Some(Expr {
                                    kind: ExprKind::Error,
                                    span,
                                }),
                            });
                            self.synchronize();
                            return Ok(Declaration::Variables {
                                ty,
                                declarators,
                                span: self.span_from(start),
                            });
                        }
                    }
                } else {
                    None
                };
                // The variable's scope starts after its initializer (`S S = S(1.0);`).
                self.declare_name(&name.name, false);
                declarators.push(Declarator {
                    span: self.span_from(name.span),
                    name,
                    array,
                    init,
                });
                if !self.eat(Punct::Comma) {
                    break;
                }
            }
        }
        self.expect_semicolon("the declaration")?;
        Ok(Declaration::Variables {
            ty,
            declarators,
            span: self.span_from(start),
        })
    }

    fn function(&mut self, ret: FullType, name: Ident, start: Span) -> PResult<ExternalDecl> {
        // The parameters (and a struct one defines) are scoped to the function.
        self.push_scope();
        let result = self.function_rest(ret, name, start);
        self.pop_scope();
        result
    }

    fn function_rest(&mut self, ret: FullType, name: Ident, start: Span) -> PResult<ExternalDecl> {
        let open = self.expect(Punct::LeftParen)?;
        let mut params = Vec::new();
        if self.at_kw(Kw::Void) && matches!(self.peek_at(1).tok, Tok::P(Punct::RightParen)) {
            self.advance();
        } else if !self.at(Punct::RightParen) {
            loop {
                let p = self.param()?;
                if let Some(n) = &p.name {
                    self.declare_name(&n.name, false);
                }
                params.push(p);
                if !self.eat(Punct::Comma) {
                    break;
                }
            }
        }
        self.expect_close(Punct::RightParen, open)?;
        let proto = FunctionProto {
            ret,
            name,
            params,
            span: self.span_from(start),
        };
        if self.at(Punct::LeftBrace) {
            let body = self.block_stmts()?;
            Ok(ExternalDecl::Function(FunctionDef { proto, body }))
        } else {
            self.expect_semicolon("the function prototype")?;
            Ok(ExternalDecl::Prototype(proto))
        }
    }

    fn param(&mut self) -> PResult<Param> {
        let start = self.peek().span;
        let qualifiers = self.qualifiers()?;
        let spec = self.type_spec()?;
        let ty = FullType {
            span: start.to(spec.span),
            qualifiers,
            spec,
        };
        let name = match self.tok() {
            Tok::Ident | Tok::Reserved => Some(self.ident("a parameter name")?),
            _ => None,
        };
        let array = if name.is_some() && self.at(Punct::LeftBracket) {
            Some(self.array_size()?)
        } else {
            None
        };
        Ok(Param {
            ty,
            name,
            array,
            span: self.span_from(start),
        })
    }

    /// Whether the tokens ahead start a declaration (not an expression).
    pub(super) fn at_declaration(&self) -> bool {
        match self.tok() {
            Tok::Kw(k) if is_qualifier_kw(*k) || *k == Kw::Struct || *k == Kw::Precision => true,
            Tok::Reserved if matches!(&*self.peek().text, "attribute" | "varying") => true,
            Tok::Kw(k) if type_keyword(*k).is_some() => self.type_then_name(),
            Tok::Ident if self.is_type_name(&self.peek().text) => self.type_then_name(),
            // Two names in a row can only be a declaration with an unknown type (`uint x`
            // in GLSL ES 1.00, a misspelt struct): read it as one, to say so.
            Tok::Ident => matches!(self.peek_at(1).tok, Tok::Ident),
            _ => false,
        }
    }

    /// After a type name: an identifier (declaration) rather than `(` (constructor). Skips a
    /// bracketed array size.
    fn type_then_name(&self) -> bool {
        let mut i = 1;
        if matches!(self.peek_at(1).tok, Tok::P(Punct::LeftBracket)) {
            let mut depth = 0;
            loop {
                match &self.peek_at(i).tok {
                    Tok::P(Punct::LeftBracket) => depth += 1,
                    Tok::P(Punct::RightBracket) => {
                        depth -= 1;
                        if depth == 0 {
                            i += 1;
                            break;
                        }
                    }
                    Tok::Eof | Tok::P(Punct::Semicolon) => return true,
                    _ => {}
                }
                i += 1;
            }
        }
        !matches!(
            self.peek_at(i).tok,
            Tok::P(Punct::LeftParen) | Tok::P(Punct::Dot)
        )
    }

    pub(super) fn local_declaration(&mut self) -> PResult<Declaration> {
        let start = self.peek().span;
        if self.at_kw(Kw::Precision) {
            return self.precision_statement();
        }
        if self.at_kw(Kw::Invariant) && matches!(self.peek_at(1).tok, Tok::Ident) {
            return self.invariant_statement();
        }
        let qualifiers = self.qualifiers()?;
        if !qualifiers.is_empty()
            && *self.tok() == Tok::Ident
            && matches!(self.peek_at(1).tok, Tok::P(Punct::LeftBrace))
            && !self.is_type_name(&self.peek().text)
        {
            return self.block(qualifiers, start);
        }
        let spec = self.type_spec()?;
        let ty = FullType {
            span: start.to(spec.span),
            qualifiers,
            spec,
        };
        if let (Tok::Ident, Tok::P(Punct::LeftParen)) = (self.tok(), &self.peek_at(1).tok) {
            let name = self.ident("a function name")?;
            let d = Diagnostic::error(
                Code::NestedFunction,
                format!(
                    "function `{}` is declared inside another function",
                    name.name
                ),
                name.span,
            )
            .with_label("functions can only be declared at global scope")
            .with_token(&*name.name);
            self.report(d);
            return Err(Failed);
        }
        self.declarators(ty, start)
    }
}
