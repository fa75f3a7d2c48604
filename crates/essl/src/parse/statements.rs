//! Statements: compound statements, selection (`if`, `switch`), iteration (`while`, `do`,
//! `for`), jumps, and the conditions that may declare a variable.

use super::{Failed, PResult, Parser};
use crate::ast::*;
use crate::diagnostic::Diagnostic;
use crate::diagnostic_code::Code;
use crate::lex::Punct;
use crate::token::{Kw, Tok};

impl Parser<'_> {
    /// `{ statements }` — the caller manages the scope.
    pub(super) fn block_stmts(&mut self) -> PResult<Block> {
        let open = self.expect(Punct::LeftBrace)?;
        let mut stmts = Vec::new();
        while !self.at(Punct::RightBrace) && !self.at_eof() {
            let before = self.pos;
            match self.statement() {
                Ok(s) => stmts.push(s),
                Err(Failed) => {
                    self.synchronize();
                    stmts.push(Stmt {
                        kind: StmtKind::Error,
                        span: self.span_from(self.toks[before].span),
                    });
                }
            }
            if self.pos == before {
                let t = self.bump();
                self.report(
                    Diagnostic::error(
                        Code::SyntaxError,
                        format!("unexpected {}", Self::describe(&t)),
                        t.span,
                    )
                    .with_label("not expected here")
                    .with_token(&*t.text),
                );
                self.synchronize();
            }
        }
        self.expect_close(Punct::RightBrace, open)?;
        Ok(Block {
            stmts,
            span: self.span_from(open),
        })
    }

    fn statement(&mut self) -> PResult<Stmt> {
        self.enter()?;
        let r = self.statement_inner();
        self.leave();
        r
    }

    fn statement_inner(&mut self) -> PResult<Stmt> {
        let start = self.peek().span;
        let kind = match *self.tok() {
            Tok::P(Punct::LeftBrace) => {
                self.push_scope();
                let b = self.block_stmts();
                self.pop_scope();
                StmtKind::Block(b?)
            }
            Tok::P(Punct::Semicolon) => {
                self.advance();
                StmtKind::Empty
            }
            Tok::Kw(Kw::If) => self.if_statement()?,
            Tok::Kw(Kw::Switch) => self.switch_statement()?,
            Tok::Kw(Kw::Case) => {
                self.advance();
                let e = self.expr()?;
                self.expect(Punct::Colon)?;
                StmtKind::Case(e)
            }
            Tok::Kw(Kw::Default) => {
                self.advance();
                self.expect(Punct::Colon)?;
                StmtKind::Default
            }
            Tok::Kw(Kw::While) => self.while_loop()?,
            Tok::Kw(Kw::Do) => self.do_while_loop()?,
            Tok::Kw(Kw::For) => self.for_loop()?,
            Tok::Kw(kw @ (Kw::Continue | Kw::Break | Kw::Discard | Kw::Return)) => self.jump(kw)?,
            _ if self.at_declaration() => StmtKind::Decl(self.local_declaration()?),
            _ => {
                let e = self.expr()?;
                self.expect_semicolon("the expression")?;
                StmtKind::Expr(e)
            }
        };
        Ok(Stmt {
            kind,
            span: self.span_from(start),
        })
    }

    /// `if (cond) then [else els]`.
    fn if_statement(&mut self) -> PResult<StmtKind> {
        self.advance();
        let open = self.expect(Punct::LeftParen)?;
        let cond = self.expr()?;
        self.expect_close(Punct::RightParen, open)?;
        let then = self.scoped_statement()?;
        let els = if self.eat_kw(Kw::Else) {
            Some(Box::new(self.scoped_statement()?))
        } else {
            None
        };
        Ok(StmtKind::If(cond, Box::new(then), els))
    }

    /// `switch (e) { … }`: the body is a scope of its own.
    fn switch_statement(&mut self) -> PResult<StmtKind> {
        self.advance();
        let open = self.expect(Punct::LeftParen)?;
        let e = self.expr()?;
        self.expect_close(Punct::RightParen, open)?;
        self.push_scope();
        let body = self.block_stmts();
        self.pop_scope();
        Ok(StmtKind::Switch(e, body?))
    }

    /// `while (cond) body`: the condition may declare a variable, in a scope the body shares.
    fn while_loop(&mut self) -> PResult<StmtKind> {
        self.advance();
        let open = self.expect(Punct::LeftParen)?;
        self.push_scope();
        let r = (|| {
            let cond = self.condition()?;
            self.expect_close(Punct::RightParen, open)?;
            let body = self.statement_no_new_scope()?;
            Ok(StmtKind::While(Box::new(cond), Box::new(body)))
        })();
        self.pop_scope();
        r
    }

    /// `do body while (cond);`.
    fn do_while_loop(&mut self) -> PResult<StmtKind> {
        self.advance();
        let body = self.scoped_statement()?;
        if !self.eat_kw(Kw::While) {
            return Err(self.expected("`while` after the body of `do`"));
        }
        let open = self.expect(Punct::LeftParen)?;
        let cond = self.expr()?;
        self.expect_close(Punct::RightParen, open)?;
        self.expect_semicolon("the `do`-`while` loop")?;
        Ok(StmtKind::DoWhile(Box::new(body), cond))
    }

    /// `for (init; cond; step) body`: the header opens a scope that the body shares.
    fn for_loop(&mut self) -> PResult<StmtKind> {
        self.advance();
        let open = self.expect(Punct::LeftParen)?;
        self.push_scope();
        let r = (|| {
            let init = self.for_init()?;
            let cond = if self.at(Punct::Semicolon) {
                None
            } else {
                Some(Box::new(self.condition()?))
            };
            self.expect(Punct::Semicolon)?;
            let step = if self.at(Punct::RightParen) {
                None
            } else {
                Some(Box::new(self.expr()?))
            };
            self.expect_close(Punct::RightParen, open)?;
            let body = self.statement_no_new_scope()?;
            Ok(StmtKind::For {
                init: Box::new(init),
                cond,
                step,
                body: Box::new(body),
            })
        })();
        self.pop_scope();
        r
    }

    /// The first clause of a `for` header, with its `;`: empty, a declaration or an expression.
    fn for_init(&mut self) -> PResult<Stmt> {
        let init_start = self.peek().span;
        Ok(if self.at(Punct::Semicolon) {
            self.advance();
            Stmt {
                kind: StmtKind::Empty,
                span: init_start,
            }
        } else if self.at_declaration() {
            let d = self.local_declaration()?;
            Stmt {
                kind: StmtKind::Decl(d),
                span: self.span_from(init_start),
            }
        } else {
            let e = self.expr()?;
            self.expect(Punct::Semicolon)?;
            Stmt {
                kind: StmtKind::Expr(e),
                span: self.span_from(init_start),
            }
        })
    }

    /// `continue;`, `break;`, `discard;` or `return [e];`, the keyword `kw` next.
    fn jump(&mut self, kw: Kw) -> PResult<StmtKind> {
        self.advance();
        Ok(match kw {
            Kw::Continue => {
                self.expect_semicolon("`continue`")?;
                StmtKind::Continue
            }
            Kw::Break => {
                self.expect_semicolon("`break`")?;
                StmtKind::Break
            }
            Kw::Discard => {
                self.expect_semicolon("`discard`")?;
                StmtKind::Discard
            }
            _ => {
                let e = if self.at(Punct::Semicolon) {
                    None
                } else {
                    Some(self.expr()?)
                };
                self.expect_semicolon("the `return` statement")?;
                StmtKind::Return(e)
            }
        })
    }

    /// A sub-statement of `if`/`else`/`do`: a scope of its own.
    fn scoped_statement(&mut self) -> PResult<Stmt> {
        self.push_scope();
        let s = self.statement();
        self.pop_scope();
        s
    }

    /// A loop body: shares the scope the loop's header opened (ES 3.00: the body of a `for` or
    /// `while` with a compound statement does not open a new scope for redeclaring the
    /// loop variable).
    fn statement_no_new_scope(&mut self) -> PResult<Stmt> {
        self.statement()
    }

    fn condition(&mut self) -> PResult<Condition> {
        if self.at_declaration() {
            let start = self.peek().span;
            let qualifiers = self.qualifiers()?;
            let spec = self.type_spec()?;
            let ty = FullType {
                span: start.to(spec.span),
                qualifiers,
                spec,
            };
            let name = self.ident("a variable name")?;
            self.expect(Punct::Equal)?;
            let init = self.assignment()?;
            self.declare_name(&name.name, false);
            Ok(Condition::Decl(ty, name, init))
        } else {
            Ok(Condition::Expr(self.expr()?))
        }
    }
}
